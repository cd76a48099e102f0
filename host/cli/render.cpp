// `facet render SCENE`: progressive rendering with progress, interruption that keeps
// the finished samples, and EXR + PNG output.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>

#include <fmt/format.h>

#include "bvh/bvh.hpp"
#include "cli/commands.hpp"
#include "film/image_io.hpp"
#include "render/renderer.hpp"
#include "scene/load.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

std::atomic<int> g_stop_signal{0};

extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig); }

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void apply_overrides(const RenderOptions& opt, Scene& scene) {
    RenderSettings& s = scene.settings;
    if (opt.spp) s.spp = *opt.spp;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.max_depth) s.max_depth = *opt.max_depth;
    if (opt.seed) s.seed = *opt.seed;
}

std::string default_output(const std::string& scene_path) {
    return (std::filesystem::path("out") / std::filesystem::path(scene_path).stem()).string() + ".exr";
}

// Samples for the next pass: aim at `target_seconds` a pass from the rate measured so
// far, growing at most 4x a pass so the first images come quickly.
std::uint32_t next_pass_samples(std::uint32_t last, double last_seconds, double target_seconds) {
    double rate = last / std::max(last_seconds, 1e-6);
    double want = std::clamp(rate * target_seconds, 1.0, 4.0 * last);
    return std::uint32_t(want);
}

void write_outputs(const std::string& out, const Renderer& r, const Scene& scene, float exposure,
                   double wall_seconds, double* rejected) {
    std::vector<float> rgb = r.image(rejected);
    ImageMetadata meta;
    meta.ints.push_back({"facet:spp", int(r.stats().samples_per_pixel)});
    meta.ints.push_back({"facet:seed", int(scene.settings.seed)});
    meta.ints.push_back({"facet:max_depth", scene.settings.max_depth});
    meta.floats.push_back({"facet:render_seconds", float(r.stats().render_seconds)});
    meta.floats.push_back({"facet:wall_seconds", float(wall_seconds)});
    meta.strings.push_back({"facet:device", r.context().desc().platform + " / " + r.context().desc().name});
    meta.strings.push_back({"facet:scene", scene.source_path});
    write_exr(out, r.width(), r.height(), rgb, meta);
    write_png(replace_extension(out, ".png"), r.width(), r.height(), rgb, exposure);
}

}  // namespace

int run_render(const RenderOptions& opt) {
    auto start = Clock::now();
    Scene scene = load_scene(opt.scene);
    apply_overrides(opt, scene);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "facet: warning: {}\n", w);
    std::string out = opt.out.empty() ? default_output(opt.scene) : opt.out;

    ClContext ctx = ClContext::create(opt.device);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer renderer(ctx, scene, bvh);
    if (!opt.quiet) {
        fmt::print("device   {} / {}\n", ctx.desc().platform, ctx.desc().name);
        fmt::print("scene    {}: {} triangles, {} lights; BVH {} nodes in {:.3f} s; kernels built in {:.2f} s\n",
                   scene.source_path, scene.triangle_count(), scene.lights.size(), bvh.stats.nodes,
                   bvh.stats.build_seconds, renderer.stats().compile_seconds);
    }

    g_stop_signal.store(0);
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    const bool tty = isatty(STDOUT_FILENO);
    const std::uint32_t target = std::uint32_t(scene.settings.spp);
    std::uint32_t pass_samples = 1;
    int pass = 0;
    while (renderer.stats().samples_per_pixel < target && g_stop_signal.load() == 0) {
        if (opt.time_limit && renderer.stats().render_seconds >= *opt.time_limit) break;
        std::uint32_t n = std::min<std::uint32_t>(pass_samples, target - std::uint32_t(renderer.stats().samples_per_pixel));
        auto pass_start = Clock::now();
        renderer.render(n);
        double pass_seconds = since(pass_start);
        ++pass;
        const RenderStats& st = renderer.stats();
        double rate = double(st.samples_per_pixel) * scene.settings.width * scene.settings.height / st.render_seconds;
        double remaining = double(target - st.samples_per_pixel) / std::max(double(st.samples_per_pixel), 1.0) * st.render_seconds;
        if (opt.time_limit) remaining = std::min(remaining, std::max(0.0, *opt.time_limit - st.render_seconds));
        if (!opt.quiet) {
            std::string line = fmt::format("pass {:3d}  {:6d}/{} spp  {:7.2f} s elapsed  {:7.2f} s left  {:8.3f} Msamples/s",
                                           pass, st.samples_per_pixel, target, since(start), remaining, rate * 1e-6);
            if (tty) fmt::print("\r{}", line);
            else fmt::print("{}\n", line);
            std::fflush(stdout);
        }
        pass_samples = next_pass_samples(n, pass_seconds, pass < 4 ? 0.25 : 1.0);
    }
    if (tty && !opt.quiet) fmt::print("\n");
    int status = g_stop_signal.load() ? kExitInterrupted : kExitOk;
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    double rejected = 0.0;
    write_outputs(out, renderer, scene, opt.exposure, since(start), &rejected);
    const RenderStats& st = renderer.stats();
    if (status == kExitInterrupted) fmt::print(stderr, "facet: interrupted; wrote the {} spp finished so far\n", st.samples_per_pixel);
    if (rejected > 0) fmt::print(stderr, "facet: warning: {} samples were NaN, infinite or negative and were dropped\n", rejected);
    fmt::print("wrote    {} and {} ({} spp, {:.2f} s rendering, {:.2f} s in all)\n", out, replace_extension(out, ".png"),
               st.samples_per_pixel, st.render_seconds, since(start));
    return status;
}

}  // namespace facet
