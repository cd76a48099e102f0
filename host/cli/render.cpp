// `facet render SCENE`: load, render through the progressive driver
// (render/progressive.hpp: passes that grow geometrically, every launch bounded), write.
// After every pass: progress, the error against a reference and/or the half-buffer
// estimate, and the CSV report; snapshots on request (best effort). On SIGINT, SIGTERM
// or SIGHUP the current pass ends (the first is dropped) and everything is written
// (exit 130); SIGPIPE is ignored (cli/stop_signals.hpp, cli/console.hpp).
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/bvh/bvh.hpp"
#include "host/bvh/bvh_width.hpp"
#include "host/cli/adaptive_tiles.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/console.hpp"
#include "host/cli/outputs.hpp"
#include "host/cli/progress.hpp"
#include "host/cli/stop_signals.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/film/film_state.hpp"
#include "host/film/image_io.hpp"
#include "host/film/sample_ranges.hpp"
#include "host/render/aov.hpp"
#include "host/render/features.hpp"
#include "host/render/film_identity.hpp"
#include "host/render/progressive.hpp"
#include "host/render/device_group.hpp"
#include "host/render/device_group_watch.hpp"
#include "host/report/report.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/util/strings.hpp"
#include "host/readers/load_scene.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// Camera samples per pixel of the AOV pass (at most the render's): enough for
// antialiased edges; the AOVs hold no lighting noise.
constexpr int kAovSpp = 64;

// --noise-threshold: the estimate is too noisy below 16 spp to stop on; --adaptive tiles
// renders this many uniformly first.
constexpr std::uint64_t kMinAdaptiveSpp = 16;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void apply_overrides(const RenderOptions& opt, Scene& scene) {
    RenderSettings& s = scene.settings;
    if (opt.spp) s.spp = *opt.spp;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.max_depth) s.max_depth = *opt.max_depth;
    if (opt.seed) s.seed = *opt.seed;
    if (opt.strategy) s.strategy = *opt.strategy;
    if (opt.sampler) s.sampler = *opt.sampler;
    if (opt.env_plain)
        scene.environment.sampling =
            *opt.env_plain != 0 ? EnvironmentSampling::plain : EnvironmentSampling::compensated;
    if (opt.filter) s.filter = *opt.filter;
    if (opt.filter_radius) s.filter_radius = *opt.filter_radius;
    if (opt.clamp) s.clamp = *opt.clamp;
    CameraDesc& c = scene.camera;
    auto vec = [](const std::vector<float>& v) { return glm::vec3(v[0], v[1], v[2]); };
    if (opt.eye.size() == 3) c.eye = vec(opt.eye);
    if (opt.target.size() == 3) c.target = vec(opt.target);
    if (opt.up.size() == 3) c.up = vec(opt.up);
    if (opt.fov) c.fov_y_degrees = *opt.fov;
    if (opt.aperture) c.aperture = *opt.aperture;
    if (opt.focus_distance) c.focus_distance = *opt.focus_distance;
    const glm::vec3 forward = c.target - c.eye;
    if (!(glm::length(forward) > 0.0f) || !std::isfinite(glm::length(forward)))
        throw Error("--eye and --target: the camera needs two distinct points at a finite distance");
    if (!(glm::length(glm::cross(glm::normalize(forward), c.up)) > 1e-6f))
        throw Error("--up: must be non-zero and not parallel to the view direction (--target minus --eye)");
}

// The --aov layers of the EXR, in the order asked.
std::vector<ImageLayer> aov_layers(const RenderOptions& opt, const AovImages& aovs) {
    std::vector<ImageLayer> layers;
    for (const std::string& name : opt.aov) {
        if (name == "albedo") layers.push_back({"albedo", {"R", "G", "B"}, aovs.albedo});
        else if (name == "normal") layers.push_back({"normal", {"X", "Y", "Z"}, aovs.normal});
        else if (name == "depth") layers.push_back({"depth", {"Z"}, aovs.depth});
    }
    return layers;
}

void write_image(const std::string& out, const std::vector<float>& rgb, const DeviceGroup& r, const Scene& scene,
                 const RenderOptions& opt, double wall_s, bool with_png = true,
                 const std::vector<ImageLayer>& layers = {}, const ImageMetadata& extra = {}) {
    ImageMetadata meta;
    meta.ints.push_back({"facet:spp", int(r.stats().samples_per_pixel)});
    meta.ints.push_back({"facet:seed", int(scene.settings.seed)});
    meta.ints.push_back({"facet:max_depth", scene.settings.max_depth});
    meta.strings.push_back({"facet:sampler", scene.settings.sampler == FC_SAMPLER_SOBOL ? "sobol" : "independent"});
    const RenderSettings& s = scene.settings;
    meta.strings.push_back({"facet:filter", pixel_filter_info(s.filter).name});
    meta.floats.push_back({"facet:filter_radius", pixel_filter_radius(s.filter, s.filter_radius)});
    // The clamp biases the image: recorded when on (0 would read as "clamped to 0").
    if (s.clamp > 0.0f) meta.floats.push_back({"facet:clamp", s.clamp});
    meta.floats.push_back({"facet:render_seconds", float(r.stats().render_seconds)});
    meta.floats.push_back({"facet:wall_seconds", float(wall_s)});
    meta.strings.push_back({"facet:device", r.description()});
    meta.strings.push_back({"facet:scene", scene.source_path});
    meta.strings.insert(meta.strings.end(), extra.strings.begin(), extra.strings.end());
    meta.floats.insert(meta.floats.end(), extra.floats.begin(), extra.floats.end());
    meta.ints.insert(meta.ints.end(), extra.ints.begin(), extra.ints.end());
    write_exr(out, r.width(), r.height(), rgb, meta, layers);
    if (with_png) write_png(replace_extension(out, ".png"), r.width(), r.height(), rgb, opt.exposure, opt.tonemap);
}

// Saves the film (film/film_state.hpp) to `path`; false, with the message printed, on failure.
bool save_film(const std::string& path, const DeviceGroup& r, const Scene& scene, std::uint64_t scene_hash) {
    try {
        write_film(path, make_film(scene, scene_hash, r.samples(), r.stats().render_seconds, r.accumulation()));
        return true;
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        return false;
    }
}

bool save_film_or_rescue(const OutputPlan& plan, const DeviceGroup& r, const Scene& scene, std::uint64_t scene_hash);

// The final image, its PNG, and the film when asked (--film), interrupted or when the
// image fails. An image or film that cannot be written where asked goes to a rescue path
// (outputs.hpp), said on stderr, and false is returned: no finished sample is lost.
// Per-tile adaptive renders have no film (their bands hold different sample counts):
// `film_possible` false.
bool write_final(const OutputPlan& plan, const std::vector<float>& rgb, const DeviceGroup& r, const Scene& scene,
                 std::uint64_t scene_hash, const RenderOptions& opt, double wall_s, bool interrupted,
                 const std::vector<ImageLayer>& layers, const ImageMetadata& extra, bool film_possible) {
    bool image_ok = true, png_ok = true;
    try {
        write_image(plan.image, rgb, r, scene, opt, wall_s, false, layers, extra);
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        image_ok = false;
    }
    if (image_ok) {
        try {
            write_png(plan.png, r.width(), r.height(), rgb, opt.exposure, opt.tonemap);
        } catch (const Error& e) {
            say(stderr, "facet: error: {} (the linear image {} was written)\n", e.what(), plan.image);
            png_ok = false;
        }
    } else {
        const std::string rescue = rescue_path(plan.image);
        try {
            write_image(rescue, rgb, r, scene, opt, wall_s, true, layers, extra);
            say(stderr, "facet: the image was saved to {} (and {}) instead\n", rescue,
                replace_extension(rescue, ".png"));
        } catch (const Error& e) {
            say(stderr, "facet: error: the image could not be saved to {} either: {}\n", rescue, e.what());
        }
    }
    const bool want_film = film_possible && (interrupted || plan.film_requested || !image_ok);
    const bool film_ok = !want_film || save_film_or_rescue(plan, r, scene, scene_hash);
    return image_ok && png_ok && film_ok;
}

// Saves the film where planned, else at its rescue path, saying where; false when it
// could not be saved where planned.
bool save_film_or_rescue(const OutputPlan& plan, const DeviceGroup& r, const Scene& scene, std::uint64_t scene_hash) {
    std::string film = plan.film;
    const bool ok = save_film(film, r, scene, scene_hash);
    if (!ok) {
        film = rescue_path(plan.film);
        if (!save_film(film, r, scene, scene_hash)) film.clear();
    }
    if (!film.empty())
        say(stderr, "facet: the film ({} spp) is saved in {}{}; continue with --resume {}\n",
            r.stats().samples_per_pixel, film, ok ? "" : " instead", film);
    return ok;
}

// Saves the film when an error ends the render before its final write (a failed pass,
// report or snapshot): the samples finished so far are not lost.
class FilmOnError {
public:
    FilmOnError(const OutputPlan& plan, const DeviceGroup& r, const Scene& scene, std::uint64_t scene_hash)
        : plan_(plan), r_(r), scene_(scene), hash_(scene_hash), exceptions_(std::uncaught_exceptions()) {}
    // The final write has saved what there is to save.
    void disarm() { armed_ = false; }
    ~FilmOnError() {
        if (!armed_ || std::uncaught_exceptions() <= exceptions_ || r_.stats().samples_per_pixel == 0) return;
        try {
            save_film_or_rescue(plan_, r_, scene_, hash_);
        } catch (...) {  // best effort while another error is on its way
        }
    }
    FilmOnError(const FilmOnError&) = delete;
    FilmOnError& operator=(const FilmOnError&) = delete;

private:
    const OutputPlan& plan_;
    const DeviceGroup& r_;
    const Scene& scene_;
    std::uint64_t hash_;
    int exceptions_;
    bool armed_ = true;
};

// Each device's share and speed, when there are several.
void print_device_shares(const DeviceGroup& group) {
    const std::vector<std::uint64_t>& ranks = group.rank_pixel_samples();
    if (ranks.size() > 1) {
        double all = 0.0;
        for (std::uint64_t n : ranks) all += double(n);
        for (std::size_t r = 0; r < ranks.size(); ++r)
            say(stdout, "rank     {}: {:.1f}% of the samples\n", r, all > 0.0 ? 100.0 * double(ranks[r]) / all : 0.0);
        say(stdout, "reduce   {:.3f} s summing the ranks' films to rank 0\n", group.reduce_seconds());
    }
    if (group.devices().size() < 2) return;
    double total = 0.0;
    for (const DeviceShare& d : group.devices()) total += double(d.pixel_samples);
    for (const DeviceShare& d : group.devices())
        say(stdout, "share    [{}] {}: {:.1f}% of the samples, {:.3f} Msamples/s{}\n", d.desc.index, d.desc.name,
            total > 0.0 ? 100.0 * double(d.pixel_samples) / total : 0.0, d.samples_per_s() * 1e-6,
            d.dropped ? " (dropped: failed)" : "");
}

// The passes, through the progressive driver: after each, the report row, the
// progress line and (on request) a snapshot, which is best effort: a failed snapshot
// is a warning and the render goes on.
std::vector<PassRecord> render_loop(const RenderOptions& opt, const Scene& scene, DeviceGroup& renderer,
                                    const std::optional<ImageRGB>& reference, const std::string& out,
                                    const std::string& report, Clock::time_point start, const StopSignals& signals,
                                    const std::vector<ImageLayer>& layers, std::uint64_t target) {
    std::vector<PassRecord> passes;
    Progress progress(opt.quiet);
    const double pixels = double(renderer.pixel_count());
    const double compile_s = renderer.stats().compile_seconds;
    double last_snapshot = 0.0;
    ProgressiveOptions po;
    po.target_spp = target;
    po.time_limit_s = opt.time_limit;
    bool converged = false;
    po.stop = [&] { return converged || signals.first() != 0; };
    po.on_first_pass_estimate = [&](double first_pass_s) {
        if (opt.time_limit && first_pass_s > *opt.time_limit)
            say(stderr, "facet: warning: one sample per pixel takes about {}, more than --time {}; rendering one\n",
                fmt_seconds(first_pass_s), *opt.time_limit);
    };
    po.on_pass = [&](const PassDone& d) {
        PassRecord p;
        p.pass = d.pass;
        p.spp = d.spp;
        p.wall_s = since(start);
        p.render_s = renderer.stats().render_seconds;
        p.compile_s = compile_s;
        FilmHalves h = renderer.halves();
        p.estimate = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
        if (reference) p.reference = compare_images(renderer.image(), reference->rgb, opt.reference);
        passes.push_back(p);
        write_report_csv(report, passes);
        converged = opt.noise_threshold && p.spp >= kMinAdaptiveSpp && p.estimate.relmse <= *opt.noise_threshold;
        const bool last = d.last || converged;

        const double rate_spp = double(p.spp) / std::max(p.render_s, 1e-9);
        progress.update(p, target, d.remaining_s, rate_spp * pixels * 1e-6, last);
        if (opt.snapshot && p.wall_s - last_snapshot >= *opt.snapshot && !last) {
            last_snapshot = p.wall_s;
            try {
                write_image(out, renderer.image(), renderer, scene, opt, p.wall_s, true, layers);
            } catch (const Error& e) {
                say(stderr, "facet: warning: snapshot not written ({}); rendering goes on\n", e.what());
            }
        }
    };
    render_progressive(renderer, po);
    return passes;
}

// The camera line: where it is and what it sees, and, for a bare OBJ, that the camera
// was framed and the default light added (load_scene.cpp), with how to choose.
std::string describe_camera(const RenderOptions& opt, const Scene& scene) {
    const CameraDesc& c = scene.camera;
    std::string line = fmt::format("camera   eye ({:g}, {:g}, {:g}), target ({:g}, {:g}, {:g}), ", c.eye.x, c.eye.y,
                                   c.eye.z, c.target.x, c.target.y, c.target.z);
    line += c.projection == FC_PROJECTION_ORTHOGRAPHIC ? fmt::format("orthographic, height {:g}", c.ortho_height)
                                                       : fmt::format("fov {:g} degrees", c.fov_y_degrees);
    if (c.projection == FC_PROJECTION_PERSPECTIVE && c.aperture > 0.0f)
        line += fmt::format(", lens radius {:g} focused at {:g}", c.aperture,
                            c.focus_distance > 0.0f ? c.focus_distance : glm::length(c.target - c.eye));
    const bool obj = lower(std::filesystem::path(opt.scene).extension().string()) == ".obj";
    if (obj && opt.eye.empty() && opt.target.empty()) line += " (framed to fit the model: --eye, --target to choose)";
    line += "\n";
    if (obj && std::find(scene.material_names.begin(), scene.material_names.end(), "default_light") !=
                   scene.material_names.end())
        line += "light    the OBJ has no emitters: a default area light was added above and in front of it\n";
    return line;
}

// For a job that lost a rank: the samples the film holds, those missing, and how to add them.
std::string describe_missing_samples(const SampleRanges& held, std::uint64_t spp, const RenderOptions& opt,
                                     const OutputPlan& plan) {
    const std::uint64_t have = sample_count(held), from = next_sample(held);
    std::string s = fmt::format("facet: the film {} holds samples {} ({} spp), finished by every rank\n", plan.film,
                                describe(held), have);
    if (have >= spp) return s;
    return s + fmt::format(
                   "facet: missing: {} spp, samples {}-{}: render them with the same options but `--samples-from {} "
                   "--spp {} --out rest.exr --film rest.film`, then `facet merge {} rest.film --out {}` (or "
                   "continue with `--resume {}`)\n",
                   spp - have, from, from + (spp - have) - 1, from, spp - have, plan.film,
                   opt.out.empty() ? plan.image : opt.out, plan.film);
}

}  // namespace

int run_render(const RenderOptions& opt) {
    auto start = Clock::now();
    const SigpipeIgnored sigpipe_ignored;  // `facet render ... | head -1` renders on
    Scene scene = load_scene(opt.scene, opt.camera);
    apply_overrides(opt, scene);
    for (const std::string& w : scene.warnings) say(stderr, "facet: warning: {}\n", w);
    if (opt.adaptive_tiles() && (!opt.film.empty() || !opt.resume.empty()))
        throw Error(
            "--adaptive tiles: its bands of rows hold different sample counts, which a film cannot hold: "
            "no --film or --resume");
    if (opt.adaptive_tiles() && (opt.samples_from != 0 || Ranks::world().size() > 1))
        throw Error(
            "--adaptive tiles: each band's samples are indices 0 to its count, so it renders in one process "
            "from sample 0: no --samples-from or MPI ranks");
    const OutputPlan plan = plan_outputs(opt);
    const std::string& out = plan.image;
    const std::string& report = plan.report;
    check_outputs(plan, opt);
    std::optional<FilmState> resumed;
    if (!opt.resume.empty()) resumed = read_film(opt.resume);
    std::optional<ImageRGB> reference;
    if (!opt.reference.empty()) reference = read_reference(opt.reference, scene.settings.width, scene.settings.height);

    if (!opt.aov.empty() && lower(std::filesystem::path(out).extension().string()) != ".exr")
        throw Error(fmt::format("--aov: the layers go into the EXR, but --out {} is not one", out));

    std::vector<ClContext> contexts;
    try {
        contexts = ClContext::create_many(opt.device);
    } catch (const Error& e) {  // each rank opens its own devices: say which failed
        const std::string rank = Ranks::where();
        if (!rank.empty()) throw Error(fmt::format("{}: {}", rank, e.what()));
        throw;
    }
    BvhOptions bvh_options;  // the node width of the first device (every program reads the tree's own)
    bvh_options.width = bvh_width_for(contexts.front().desc().type == CL_DEVICE_TYPE_GPU,
                                      contexts.front().device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>());
    Bvh bvh = build_bvh(scene.vertices, bvh_options);
    // The device scene, compiled once for the AOVs and every device; the film's identity from it.
    const DeviceScene device_scene = compile(scene, bvh);
    const std::uint64_t scene_hash = film_identity(device_scene);
    if (resumed) check_film_matches(*resumed, opt.resume, scene, scene_hash);
    // The AOVs first (rank 0's first device), their buffers released before the path
    // tracer uploads the scene.
    std::vector<ImageLayer> layers;
    if (!opt.aov.empty() && Ranks::world().leads()) {
        const std::uint32_t aov_spp = std::uint32_t(std::min(scene.settings.spp, kAovSpp));
        const AovImages aovs = render_aovs(contexts.front(), scene, bvh, device_scene, aov_spp);
        layers = aov_layers(opt, aovs);
        if (!opt.quiet) say(stdout, "aovs     {} ({} spp) in {:.2f} s\n", name_list(opt.aov), aov_spp, aovs.seconds);
    }
    DeviceGroup renderer(std::move(contexts), scene, bvh, device_scene, opt.generic, opt.samples_from,
                         [](const std::string& w) { say(stderr, "facet: warning: {}\n", w); });
    const double compile_s = renderer.stats().compile_seconds;
    if (resumed) renderer.restore(resumed->sums, resumed->samples, resumed->render_seconds);
    if (!renderer.ranks().leads()) {  // an MPI rank other than 0: renders what rank 0 deals out
        // Ctrl-C on mpirun reaches every rank: rank 0 ends the pass, writes, and stops the others.
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_IGN);
        renderer.follow();
        return kExitOk;
    }
    FilmOnError film_on_error(plan, renderer, scene, scene_hash);
    if (!opt.quiet) {
        for (const DeviceShare& d : renderer.devices())
            if (!d.dropped) say(stdout, "device   [{}] {} / {}\n", d.desc.index, d.desc.platform, d.desc.name);
        say(stdout, "scene    {}: {} triangles, {}{} lights; BVH {} nodes in {:.3f} s\n", scene.source_path,
            scene.triangle_count(), scene.spheres.empty() ? "" : fmt::format("{} spheres, ", scene.spheres.size()),
            scene.lights.size(), bvh.stats.nodes, bvh.stats.build_seconds);
        say(stdout, "kernels  {} program ({}), built in {:.2f} s\n", opt.generic ? "generic" : "specialised",
            describe_features(renderer.stats().features), compile_s);
        if (resumed) say(stdout, "resumed  {} spp from {}\n", resumed->spp, opt.resume);
        say(stdout, "{}", describe_camera(opt, scene));
    }

    // Held until every file is written: a second Ctrl-C during the writes is counted, not fatal.
    StopSignals signals;
    // MPI: when a rank dies mpirun ends the job; the watch writes what every rank finished.
    std::optional<DeviceGroupWatch> watch;
    if (renderer.ranks().size() > 1)
        watch.emplace(
            renderer, [&] { return signals.first(); },
            [&](const DeviceGroupWatch::Lost& lost) {
                say(stderr, "facet: error: {}\n", lost.why);
                const int status = lost.waiting ? kExitRankLost : kExitInterrupted;
                if (renderer.stats().samples_per_pixel == 0) {
                    say(stderr, "facet: no pass had finished; nothing written\n");
                    return status;
                }
                write_final(plan, renderer.image(), renderer, scene, scene_hash, opt, since(start), true, layers, {},
                            true);
                say(stderr, "{}",
                    describe_missing_samples(renderer.samples(), std::uint64_t(scene.settings.spp), opt, plan));
                return status;
            });
    const std::uint64_t uniform_target =
        opt.adaptive_tiles() ? std::min<std::uint64_t>(kMinAdaptiveSpp, std::uint64_t(scene.settings.spp))
                             : std::uint64_t(scene.settings.spp);
    std::vector<PassRecord> passes =
        render_loop(opt, scene, renderer, reference, out, report, start, signals, layers, uniform_target);
    std::optional<TileRun> tiles;
    if (opt.adaptive_tiles() && signals.first() == 0 && renderer.stats().samples_per_pixel > 0) {
        film_on_error.disarm();  // from here on the bands differ: no film
        tiles = render_adaptive_tiles(opt, scene, renderer, reference, report, start, signals, passes);
    }
    if (watch) watch->stand_down();
    const bool interrupted = signals.first() != 0;
    const RenderStats& st = renderer.stats();
    if (st.samples_per_pixel == 0) {
        say(stderr, "facet: interrupted before the first pass finished; nothing written\n");
        return kExitInterrupted;
    }
    if (interrupted)
        say(stderr,
            "facet: interrupted; writing the {} spp finished so far (further Ctrl-C is ignored until written)\n",
            st.samples_per_pixel);

    double rejected = 0.0;
    std::vector<float> rgb = renderer.image(&rejected);
    ImageMetadata extra;
    std::uint64_t final_spp = st.samples_per_pixel;
    if (tiles) {
        rgb = tiles->image.rgb;
        final_spp = std::uint64_t(tiles->image.mean_spp + 0.5);
        // facet:spp stays the fewest samples of any pixel (the uniform passes).
        extra.strings.push_back({"facet:adaptive", "tiles"});
        extra.floats.push_back({"facet:mean_spp", float(tiles->image.mean_spp)});
        extra.ints.push_back(
            {"facet:max_spp", int(*std::max_element(tiles->layout.spp.begin(), tiles->layout.spp.end()))});
    }
    const bool written =
        write_final(plan, rgb, renderer, scene, scene_hash, opt, since(start), interrupted, layers, extra, !tiles);
    film_on_error.disarm();
    ReportSummary summary;
    summary.scene = scene.source_path;
    summary.device = renderer.description();
    summary.image = out;
    summary.reference = opt.reference;
    summary.spp = st.samples_per_pixel;
    summary.width = renderer.width();
    summary.height = renderer.height();
    summary.wall_s = since(start);
    summary.render_s = st.render_seconds;
    summary.compile_s = compile_s;
    summary.interrupted = interrupted;
    summary.rejected_samples = rejected;
    summary.stratified = scene.settings.sampler == FC_SAMPLER_SOBOL;
    summary.sampler = summary.stratified ? "sobol" : "independent";
    summary.filter = pixel_filter_info(scene.settings.filter).name;
    summary.filter_radius = pixel_filter_radius(scene.settings.filter, scene.settings.filter_radius);
    summary.clamp = scene.settings.clamp;
    if (reference) summary.reference_spp = reference->spp;
    summary.noise_threshold = opt.noise_threshold.value_or(0.0);
    summary.converged = tiles ? tiles->converged
                              : opt.noise_threshold && !passes.empty() &&
                                    passes.back().spp < std::uint64_t(scene.settings.spp) &&
                                    passes.back().estimate.relmse <= *opt.noise_threshold;
    summary.adaptive = !opt.noise_threshold ? "" : tiles ? "tiles" : "global";
    if (tiles) summary.spp = final_spp;
    fit_convergence(passes, summary);
    write_report_csv(report, passes);
    write_report_json(plan.report_json, summary, passes);
    write_error_plot_svg(plan.report_svg, passes, scene.source_path);
    if (!written) return kExitError;

    if (interrupted) say(stderr, "facet: interrupted; wrote the {} spp finished so far\n", st.samples_per_pixel);
    if (summary.converged && !opt.quiet)
        say(stdout, "adaptive the error estimate (relMSE {:.3g}) reached --noise-threshold {} at {} spp{}\n",
            passes.back().estimate.relmse, *opt.noise_threshold, final_spp,
            tiles ? fmt::format(" (mean; every band of {} rows below it)", tiles->layout.band_rows) : "");
    if (std::none_of(rgb.begin(), rgb.end(), [](float v) { return v != 0.0f; }))
        say(stderr,
            "facet: warning: the image is black: no light reaches the camera (no emitters in view or lighting "
            "the visible surfaces; for an OBJ, --eye and --target choose another view)\n");
    if (rejected > 0)
        say(stderr, "facet: warning: {} samples were NaN, infinite or negative and were dropped\n", rejected);
    if (!summary.slope_warning.empty()) say(stderr, "facet: warning: {}\n", summary.slope_warning);
    say(stdout, "wrote    {} and {} ({} spp{}, {:.2f} s rendering, {:.2f} s in all)\n", out,
        replace_extension(out, ".png"), final_spp, tiles ? " mean" : "", st.render_seconds, since(start));
    if (!opt.quiet) print_device_shares(renderer);
    if (!opt.quiet) {
        if (std::isfinite(summary.slope))
            say(stdout, "report   {} (+ .json, .svg); RMSE ~ time^{:.2f} ({}{})\n", report, summary.slope,
                summary.slope_source, summary.slope_judged ? "" : ", too short a run to judge");
        else say(stdout, "report   {} (+ .json, .svg); the run was too short to fit a convergence rate\n", report);
    }
    return interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace facet
