// `facet render`: the image, its PNG and the film, each saved where asked or, failing
// that, at its rescue path (cli/outputs.hpp), said on stderr: no finished sample is lost.
#include <exception>

#include "host/util/console.hpp"
#include "host/cli/render_parts.hpp"
#include "host/error.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/util/strings.hpp"
#include "host/scene/render_names.hpp"

namespace facet {
namespace {

// Saves the session's film to `path`; false, with the message printed, on failure.
bool save_film(const RenderJob& job, const std::string& path) {
    try {
        write_film(path, job.session.film());
        return true;
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        return false;
    }
}

// Saves the film where planned, else at its rescue path, saying where; false when it
// could not be saved where planned.
bool save_film_or_rescue(const RenderJob& job) {
    std::string film = job.plan.film;
    const bool ok = save_film(job, film);
    if (!ok) {
        film = rescue_path(job.plan.film);
        if (!save_film(job, film)) film.clear();
    }
    if (!film.empty())
        say(stderr, "facet: the film ({} spp) is saved in {}{}; continue with --resume {}\n", job.session.spp(), film,
            ok ? "" : " instead", film);
    return ok;
}

// For a job that lost a rank: the samples the film holds, those missing, and how to add them.
std::string describe_missing_samples(const RenderJob& job) {
    const SampleRanges& held = job.session.group().samples();
    const std::uint64_t have = sample_count(held), from = next_sample(held);
    std::string s = fmt::format("facet: the film {} holds samples {} ({} spp), finished by every rank\n", job.plan.film,
                                describe(held), have);
    const StopRules& rules = job.session.rules();
    if (!rules.spp_bounded || have >= rules.spp) return s;
    const std::uint64_t spp = rules.spp;
    return s + fmt::format(
                   "facet: missing: {} spp, samples {}-{}: render them with the same options but `--samples-from {} "
                   "--spp {} --out rest.exr --film rest.film`, then `facet merge {} rest.film --out {}` (or "
                   "continue with `--resume {}`)\n",
                   spp - have, from, from + (spp - have) - 1, from, spp - have, job.plan.film,
                   job.opt.out.empty() ? job.plan.image : job.opt.out, job.plan.film);
}

}  // namespace

void write_image(const RenderJob& job, const std::string& out, const std::vector<float>& rgb, bool with_png,
                 const ImageMetadata& extra) {
    const DeviceGroup& r = job.session.group();
    const RenderSettings& s = job.scene.settings;
    ImageMetadata meta;
    meta.ints.push_back({"facet:spp", int(r.stats().samples_per_pixel)});
    meta.ints.push_back({"facet:seed", int(s.seed)});
    meta.ints.push_back({"facet:max_depth", s.max_depth});
    meta.ints.push_back({"facet:rr_depth", s.rr_depth});
    meta.floats.push_back({"facet:roulette_gain", s.roulette_gain});
    meta.strings.push_back({"facet:sampler", setting_name(kSamplerNames, s.sampler)});
    meta.strings.push_back({"facet:filter", pixel_filter_info(s.filter).name});
    meta.floats.push_back({"facet:filter_radius", pixel_filter_radius(s.filter, s.filter_radius)});
    // The clamp biases the image: recorded when on (0 would read as "clamped to 0").
    if (s.clamp > 0.0f) meta.floats.push_back({"facet:clamp", s.clamp});
    meta.floats.push_back({"facet:render_seconds", float(r.stats().render_seconds)});
    meta.floats.push_back({"facet:wall_seconds", float(job.since_start())});
    meta.strings.push_back({"facet:device", r.description()});
    meta.strings.push_back({"facet:scene", job.scene.source_path});
    meta.strings.insert(meta.strings.end(), extra.strings.begin(), extra.strings.end());
    meta.floats.insert(meta.floats.end(), extra.floats.begin(), extra.floats.end());
    meta.ints.insert(meta.ints.end(), extra.ints.begin(), extra.ints.end());
    write_exr(out, r.width(), r.height(), rgb, meta, job.layers);
    if (with_png)
        write_png(replace_extension(out, ".png"), r.width(), r.height(), rgb, job.opt.exposure, job.opt.tonemap);
}

bool write_final(const RenderJob& job, const std::vector<float>& rgb, bool interrupted, const ImageMetadata& extra) {
    const OutputPlan& plan = job.plan;
    const DeviceGroup& r = job.session.group();
    bool image_ok = true, png_ok = true;
    try {
        write_image(job, plan.image, rgb, false, extra);
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        image_ok = false;
    }
    if (image_ok) {
        try {
            write_png(plan.png, r.width(), r.height(), rgb, job.opt.exposure, job.opt.tonemap);
        } catch (const Error& e) {
            say(stderr, "facet: error: {} (the linear image {} was written)\n", e.what(), plan.image);
            png_ok = false;
        }
    } else {
        const std::string rescue = rescue_path(plan.image);
        try {
            write_image(job, rescue, rgb, true, extra);
            say(stderr, "facet: the image was saved to {} (and {}) instead\n", rescue,
                replace_extension(rescue, ".png"));
        } catch (const Error& e) {
            say(stderr, "facet: error: the image could not be saved to {} either: {}\n", rescue, e.what());
        }
    }
    const bool want_film = job.session.has_film() && (interrupted || plan.film_requested || !image_ok);
    const bool film_ok = !want_film || save_film_or_rescue(job);
    return image_ok && png_ok && film_ok;
}

int write_on_rank_lost(const RenderJob& job, const DeviceGroupWatch::Lost& lost) {
    say(stderr, "facet: error: {}\n", lost.why);
    const int status = lost.waiting ? kExitRankLost : kExitInterrupted;
    if (job.session.spp() == 0) {
        say(stderr, "facet: no pass had finished; nothing written\n");
        return status;
    }
    write_final(job, job.session.image(), true);
    say(stderr, "{}", describe_missing_samples(job));
    return status;
}

FilmOnError::FilmOnError(const RenderJob& job) : job_(job), exceptions_(std::uncaught_exceptions()) {}

FilmOnError::~FilmOnError() {
    if (!armed_ || std::uncaught_exceptions() <= exceptions_ || job_.session.spp() == 0 || !job_.session.has_film())
        return;
    try {
        save_film_or_rescue(job_);
    } catch (...) {  // best effort while another error is on its way
    }
}

}  // namespace facet
