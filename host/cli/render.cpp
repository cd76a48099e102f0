// `facet render SCENE`: progressive rendering. Passes start at one sample per pixel
// and grow geometrically; each launch is kept short (row bands) so a GPU display
// watchdog never fires. After every pass: progress, the error against a reference
// and/or the half-buffer estimate, and the CSV report; snapshots on request; on
// SIGINT/SIGTERM the current pass ends and everything is written (exit 130).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "host/bvh/bvh.hpp"
#include "host/cli/commands.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/film/image_io.hpp"
#include "host/render/features.hpp"
#include "host/render/renderer.hpp"
#include "host/report/report.hpp"
#include "host/readers/load_scene.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

std::atomic<int> g_stop_signal{0};

extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig); }

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kMaxLaunchSeconds = 0.25;   // per kernel launch (GPU watchdogs kill ~2 s)

void apply_overrides(const RenderOptions& opt, Scene& scene) {
    RenderSettings& s = scene.settings;
    if (opt.spp) s.spp = *opt.spp;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.max_depth) s.max_depth = *opt.max_depth;
    if (opt.seed) s.seed = *opt.seed;
    if (opt.strategy) s.strategy = *opt.strategy;
}

std::string default_output(const std::string& scene_path) {
    return (std::filesystem::path("out") / std::filesystem::path(scene_path).stem()).string() + ".exr";
}

void write_image(const std::string& out, const std::vector<float>& rgb, const Renderer& r, const Scene& scene,
                 float exposure, double wall_s) {
    ImageMetadata meta;
    meta.ints.push_back({"facet:spp", int(r.stats().samples_per_pixel)});
    meta.ints.push_back({"facet:seed", int(scene.settings.seed)});
    meta.ints.push_back({"facet:max_depth", scene.settings.max_depth});
    meta.floats.push_back({"facet:render_seconds", float(r.stats().render_seconds)});
    meta.floats.push_back({"facet:wall_seconds", float(wall_s)});
    meta.strings.push_back({"facet:device", r.context().desc().platform + " / " + r.context().desc().name});
    meta.strings.push_back({"facet:scene", scene.source_path});
    write_exr(out, r.width(), r.height(), rgb, meta);
    write_png(replace_extension(out, ".png"), r.width(), r.height(), rgb, exposure);
}

// Fails early, before any rendering, when `path` cannot be written.
void check_writable(const std::string& path, const char* what) {
    namespace fs = std::filesystem;
    fs::path p(path);
    std::error_code ec;
    if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
    fs::path probe = p.parent_path() / (".tmp-probe-" + p.filename().string());
    bool ok = static_cast<bool>(std::ofstream(probe));
    fs::remove(probe, ec);
    if (!ok) throw Error(fmt::format("{} {}: cannot write there", what, path));
}

std::string fmt_seconds(double s) {
    if (!std::isfinite(s)) return "?";
    if (s < 60) return fmt::format("{:.1f}s", s);
    if (s < 3600) return fmt::format("{}m{:02d}s", int(s) / 60, int(s) % 60);
    return fmt::format("{}h{:02d}m", int(s) / 3600, (int(s) % 3600) / 60);
}

// The progress display: a live line on a terminal, plain lines (at most one every
// two seconds, and the last) otherwise.
class Progress {
public:
    explicit Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDOUT_FILENO)) {}

    void update(const PassRecord& p, std::uint64_t target, double remaining, double msamples, bool last) {
        if (quiet_) return;
        std::string err;
        if (p.reference) err = fmt::format("  rmse {:.3e}", p.reference->rmse);
        else if (std::isfinite(p.estimate.rmse)) err = fmt::format("  rmse~{:.3e} (est.)", p.estimate.rmse);
        std::string line = fmt::format("pass {:3d}  {:>7}/{} spp  {:>7} elapsed  {:>7} left  {:7.3f} Msamples/s{}", p.pass,
                                       p.spp, target, fmt_seconds(p.wall_s), fmt_seconds(remaining), msamples, err);
        if (tty_) {
            fmt::print("\r{:<120}", line);
            if (last) fmt::print("\n");
        } else if (last || p.wall_s - last_print_ >= 2.0 || p.pass == 1) {
            fmt::print("{}\n", line);
            last_print_ = p.wall_s;
        }
        std::fflush(stdout);
    }

private:
    bool quiet_, tty_;
    double last_print_ = -1e9;
};

}  // namespace

int run_render(const RenderOptions& opt) {
    auto start = Clock::now();
    Scene scene = load_scene(opt.scene);
    apply_overrides(opt, scene);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "facet: warning: {}\n", w);
    const std::string out = opt.out.empty() ? default_output(opt.scene) : opt.out;
    const std::string report = opt.report.empty() ? replace_extension(out, ".csv") : opt.report;
    check_writable(out, "--out");
    check_writable(report, "--report");
    std::optional<ImageRGB> reference;
    if (!opt.reference.empty()) reference = read_reference(opt.reference, scene.settings.width, scene.settings.height);

    ClContext ctx = ClContext::create(opt.device);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer renderer(ctx, scene, bvh, opt.generic);
    const double compile_s = renderer.stats().compile_seconds;
    if (!opt.quiet) {
        fmt::print("device   {} / {}\n", ctx.desc().platform, ctx.desc().name);
        fmt::print("scene    {}: {} triangles, {} lights; BVH {} nodes in {:.3f} s\n", scene.source_path,
                   scene.triangle_count(), scene.lights.size(), bvh.stats.nodes, bvh.stats.build_seconds);
        fmt::print("kernels  {} program ({}), built in {:.2f} s\n", opt.generic ? "generic" : "specialised",
                   describe_features(renderer.stats().features), compile_s);
    }

    g_stop_signal.store(0);
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    Progress progress(opt.quiet);
    std::vector<PassRecord> passes;
    const std::uint64_t target = std::uint64_t(scene.settings.spp);
    const double pixels = double(renderer.pixel_count());
    std::uint32_t pass_samples = 1;
    double last_snapshot = 0.0;
    while (renderer.stats().samples_per_pixel < target && g_stop_signal.load() == 0) {
        const RenderStats& st = renderer.stats();
        if (opt.time_limit && st.render_seconds >= *opt.time_limit) break;
        // Samples this pass: the schedule's, no more than the target or the time left allows.
        std::uint64_t n = std::min<std::uint64_t>(pass_samples, target - st.samples_per_pixel);
        double per_sample = st.samples_per_pixel ? st.render_seconds / double(st.samples_per_pixel) : 0.0;
        if (opt.time_limit && per_sample > 0)
            n = std::clamp<std::uint64_t>(std::uint64_t((*opt.time_limit - st.render_seconds) / per_sample), 1, n);
        // Rows per launch so that no launch runs longer than kMaxLaunchSeconds.
        double pass_estimate = per_sample * double(n);
        std::uint32_t rows = pass_estimate > kMaxLaunchSeconds
            ? std::max<std::uint32_t>(1, std::uint32_t(scene.settings.height * kMaxLaunchSeconds / pass_estimate))
            : 0;
        renderer.render(std::uint32_t(n), rows);

        PassRecord p;
        p.pass = int(passes.size()) + 1;
        p.spp = st.samples_per_pixel;
        p.wall_s = since(start);
        p.render_s = st.render_seconds;
        p.compile_s = compile_s;
        Renderer::Halves h = renderer.halves();
        p.estimate = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
        if (reference) p.reference = compare_images(renderer.image(), reference->rgb, opt.reference);
        passes.push_back(p);
        write_report_csv(report, passes);

        double rate_spp = double(p.spp) / std::max(p.render_s, 1e-9);
        double remaining = double(target - p.spp) / rate_spp;
        if (opt.time_limit) remaining = std::min(remaining, std::max(0.0, *opt.time_limit - p.render_s));
        bool last = p.spp >= target || (opt.time_limit && p.render_s >= *opt.time_limit) || g_stop_signal.load();
        progress.update(p, target, remaining, rate_spp * pixels * 1e-6, last);

        if (opt.snapshot && p.wall_s - last_snapshot >= *opt.snapshot && !last) {
            write_image(out, renderer.image(), renderer, scene, opt.exposure, p.wall_s);
            last_snapshot = p.wall_s;
        }
        // Next pass: about a tenth of the time so far (log-spaced error points), at
        // most twice the samples, at least 50 ms and at most 2 s of work.
        double want_s = std::clamp(0.1 * p.render_s, 0.05, 2.0);
        pass_samples = std::uint32_t(std::clamp(want_s * rate_spp, 1.0, 2.0 * double(n)));
    }
    const bool interrupted = g_stop_signal.load() != 0;
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    double rejected = 0.0;
    std::vector<float> rgb = renderer.image(&rejected);
    write_image(out, rgb, renderer, scene, opt.exposure, since(start));
    const RenderStats& st = renderer.stats();
    ReportSummary summary;
    summary.scene = scene.source_path;
    summary.device = ctx.desc().platform + " / " + ctx.desc().name;
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
    fit_convergence(passes, summary);
    write_report_csv(report, passes);
    write_report_json(replace_extension(report, ".json"), summary, passes);
    write_error_plot_svg(replace_extension(report, ".svg"), passes, scene.source_path);

    if (interrupted)
        fmt::print(stderr, "facet: interrupted; wrote the {} spp finished so far\n", st.samples_per_pixel);
    if (rejected > 0)
        fmt::print(stderr, "facet: warning: {} samples were NaN, infinite or negative and were dropped\n", rejected);
    if (!summary.slope_warning.empty())
        fmt::print(stderr, "facet: warning: {}\n", summary.slope_warning);
    fmt::print("wrote    {} and {} ({} spp, {:.2f} s rendering, {:.2f} s in all)\n", out,
               replace_extension(out, ".png"), st.samples_per_pixel, st.render_seconds, since(start));
    if (!opt.quiet) {
        fmt::print("report   {} (+ .json, .svg); RMSE ~ time^{:.2f} ({}{})\n", report, summary.slope,
                   summary.slope_source, summary.slope_judged ? "" : ", too short a run to judge");
    }
    return interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace facet
