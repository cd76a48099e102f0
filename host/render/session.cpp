#include "host/render/session.hpp"

#include <algorithm>
#include <csignal>

#include <fmt/format.h>

#include "host/bvh/bvh_width.hpp"
#include "host/error.hpp"
#include "host/util/clock.hpp"
#include "host/film/error_metrics.hpp"
#include "host/render/features.hpp"
#include "host/render/film_identity.hpp"
#include "host/render/packet_paths.hpp"
#include "host/render/progressive.hpp"

namespace facet {
namespace {

// Camera samples per pixel of the AOV pass (at most the render's): enough for
// antialiased edges; the AOVs hold no lighting noise.
constexpr std::uint64_t kAovSpp = 64;

// Each rank opens its own devices: an error says which rank failed.
std::vector<ClContext> open_devices(const std::string& selector) {
    try {
        return ClContext::create_many(selector);
    } catch (const Error& e) {
        const std::string rank = Ranks::where();
        if (!rank.empty()) throw Error(fmt::format("{}: {}", rank, e.what()));
        throw;
    }
}

}  // namespace

RenderSession::RenderSession(const Scene& scene, SessionOptions options) : scene_(scene), options_(std::move(options)) {
    StopRequest request = options_.stop;
    request.scene_spp = std::uint64_t(scene.settings.spp);
    rules_ = resolve_stop_rules(request);
    if (rules_.adaptive == AdaptiveMode::tiles && (options_.samples_from != 0 || Ranks::world().size() > 1))
        throw Error(
            "--adaptive tiles: each band's samples are indices 0 to its count, so it renders in one process "
            "from sample 0: no --samples-from or MPI ranks");

    std::vector<ClContext> contexts = open_devices(options_.device);
    BvhOptions bvh_options;  // the node width of the first device (every program reads the tree's own)
    bvh_options.width = bvh_width_for(contexts.front().desc().type == CL_DEVICE_TYPE_GPU,
                                      contexts.front().device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>());
    bvh_options.layout_triangles = scene.stored_triangle_count();  // instanced meshes take its layout
    {
        // a small tree whose packets keep every ray to the leaves: the SAH of packet tests
        const ClContext& first = contexts.front();
        const bool packets =
            packet_paths_for(first.desc(), first.device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>(),
                             options_.generic ? all_features() : scene_features(scene), lights_in_packets(scene),
                             std::uint32_t(scene.settings.sampler), options_.generic);
        packet_tree_options(bvh_options, scene.vertices.size() / 3, packets);
    }
    bvh_ = build_bvh(scene.vertices, bvh_options);
    // The device scene, compiled once for the AOVs and every device; the film's identity is
    // computed from it here alone, for the resumed film's check and the film saved, before
    // any sample is rendered.
    device_scene_ = std::make_unique<DeviceScene>(compile(scene, bvh_));
    film_identity_ = film_identity(*device_scene_);
    if (options_.resume) check_film_matches(*options_.resume, options_.resume_path, scene, film_identity_);
    // The AOVs first (rank 0's first device), their buffers released before the path
    // tracer uploads the scene.
    if ((options_.aovs || options_.denoise) && Ranks::world().leads())
        aovs_ = render_aovs(contexts.front(), scene, bvh_, *device_scene_, aov_spp());
    if (options_.denoise && Ranks::world().leads())
        denoiser_ = std::async(std::launch::async, [ctx = contexts.front()] {
                        return std::shared_ptr<const Denoiser>(std::make_shared<Denoiser>(ctx));
                    }).share();
    group_ = std::make_unique<DeviceGroup>(std::move(contexts), scene, bvh_, *device_scene_, options_.generic,
                                           options_.samples_from, options_.warn);
    if (options_.resume)
        group_->restore(options_.resume->sums, options_.resume->samples, options_.resume->render_seconds,
                        options_.resume->second_moments);
}

RenderSession::~RenderSession() = default;

std::uint32_t RenderSession::aov_spp() const { return std::uint32_t(std::min(rules_.spp, kAovSpp)); }

bool RenderSession::follow() {
    if (group_->ranks().leads()) return false;
    // Ctrl-C on mpirun reaches every rank: rank 0 ends the pass, writes, and stops the others.
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_IGN);
    group_->follow();
    return true;
}

std::vector<float> RenderSession::image(double* rejected_samples) const {
    if (!bands_) return group_->image(rejected_samples);
    if (rejected_samples) group_->image(rejected_samples);
    return bands_->rgb;
}

FilmState RenderSession::film() const {
    if (!has_film()) throw Error("the tile mode's bands hold different sample counts, which a film cannot hold");
    FilmState f =
        make_film(scene_, film_identity_, group_->samples(), group_->stats().render_seconds, group_->accumulation());
    f.second_moments = group_->second_moments();
    return f;
}

DenoisedImage RenderSession::denoised(const DenoiseSettings& settings) const {
    if (!denoiser_.valid() || !aovs_) throw Error("denoise: the render session was not opened for denoising");
    const FilmState f = film();
    const FilmHalves halves = film_halves(f);
    return denoiser_.get()->run(std::uint32_t(f.width), std::uint32_t(f.height), halves, *aovs_, settings);
}

// PoCL and other drivers compile a kernel for its launch geometry at its first launch:
// one launch of a row, its samples then dropped, keeps that compile out of the first
// pass's measured time (and out of the time limit). One sample for every device of
// every rank, so that each of them launches.
void RenderSession::warm_up() {
    const auto t = Clock::now();
    const std::uint32_t devices =
        std::uint32_t(std::max<std::size_t>(group_->devices().size() * std::size_t(group_->ranks().size()), 1));
    group_->launch(devices, 0, 1);
    group_->reset();
    warmup_s_ = seconds_since(t);
}

PassRecord RenderSession::record(int pass, std::uint64_t spp, const ErrorMetrics& estimate) const {
    PassRecord p;
    p.pass = pass;
    p.spp = spp;
    p.wall_s = seconds_since(options_.start);
    p.render_s = group_->stats().render_seconds;
    p.compile_s = compile_seconds();
    p.estimate = estimate;
    return p;
}

SessionOutcome RenderSession::run(const SessionHooks& hooks) {
    DeviceGroup& group = *group_;
    auto stop_signal = [&] { return hooks.stop_signal ? hooks.stop_signal() : 0; };
    // MPI: when a rank dies mpirun ends the job; the watch hands over what every rank finished.
    std::optional<DeviceGroupWatch> watch;
    if (group.ranks().size() > 1 && hooks.on_rank_lost) watch.emplace(group, stop_signal, hooks.on_rank_lost);
    warm_up();

    SessionOutcome out;
    const double pixels = double(group.pixel_count());
    auto report = [&](const PassRecord& p, std::uint64_t target, double remaining_s, bool last) {
        SessionPass done{p, rules_.spp_bounded ? target : 0, remaining_s, 0.0, last};
        done.msamples_per_s = double(p.spp) / std::max(p.render_s, 1e-9) * pixels * 1e-6;
        if (hooks.on_pass) hooks.on_pass(done);
    };
    // The uniform passes: to the target (the tile mode's first kMinAdaptiveSpp), the time
    // limit, the noise threshold or a stop signal.
    ProgressiveOptions po;
    po.target_spp = rules_.uniform_spp();
    po.time_limit_s = rules_.time_limit_s;
    po.stop = [&] { return out.converged || stop_signal() != 0; };
    po.on_first_pass_estimate = hooks.on_slow_first_pass;
    po.on_pass = [&](const PassDone& d) {
        const PassRecord p = record(d.pass, d.spp, group.estimate());
        out.converged = rules_.converged(p.spp, p.estimate.relmse);
        report(p, po.target_spp, d.remaining_s, d.last || out.converged);
    };
    out.passes = render_progressive(group, po).passes;

    // The tile mode: rounds of bands, from the uniform passes on.
    if (rules_.adaptive == AdaptiveMode::tiles && rules_.noise_threshold && stop_signal() == 0 && spp() > 0) {
        tiles_started_ = true;
        TileOptions to;
        to.threshold = *rules_.noise_threshold;
        to.max_spp = rules_.spp;
        to.time_limit_s = rules_.time_limit_s;
        to.rules = po.rules;
        to.stop = [&] { return stop_signal() != 0; };
        to.on_round = [&](const ResolvedBands& bands, int round, bool last) {
            bands_ = bands;
            report(record(out.passes + round, std::uint64_t(bands.mean_spp + 0.5), bands.estimate), rules_.spp, 0.0,
                   last);
        };
        out.tiles = render_tiles(group, to);
        bands_ = out.tiles->image;
        out.passes += out.tiles->rounds;
        out.converged = out.tiles->converged;
    }
    if (watch) watch->stand_down();
    out.interrupted = stop_signal() != 0;
    out.spp = spp();
    out.mean_spp = out.tiles ? out.tiles->image.mean_spp : double(out.spp);
    return out;
}

}  // namespace facet
