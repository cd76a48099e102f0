#include "host/cli/adaptive_tiles.hpp"

#include <algorithm>

#include "host/cli/console.hpp"
#include "host/cli/progress.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr int kBandRows = 8;
constexpr double kMaxLaunchSeconds = 0.25;  // as render/schedule.hpp bounds the uniform passes

}  // namespace

TileRun render_adaptive_tiles(const RenderOptions& opt, const Scene& scene, DeviceGroup& renderer,
                              const std::optional<ImageRGB>& reference, const std::string& report,
                              Clock::time_point start, const StopSignals& signals, std::vector<PassRecord>& passes) {
    TileRun run;
    BandLayout& layout = run.layout;
    layout.width = renderer.width();
    layout.height = renderer.height();
    layout.band_rows = kBandRows;
    layout.spp.assign(std::size_t(layout.bands()), renderer.stats().samples_per_pixel);
    const std::uint64_t max_spp = std::uint64_t(scene.settings.spp);
    const double threshold = *opt.noise_threshold;
    // Seconds per sample per row, as the uniform passes measured it.
    const double row_sample_s = renderer.stats().render_seconds /
                                std::max(1.0, double(renderer.stats().samples_per_pixel) * double(layout.height));
    Progress progress(opt.quiet);
    int pass = passes.empty() ? 0 : passes.back().pass;
    for (;;) {
        run.image = resolve_bands(renderer.accumulation(), layout);
        const std::vector<int> active = bands_above(run.image, layout, threshold, max_spp);
        const bool time_up = opt.time_limit && renderer.stats().render_seconds >= *opt.time_limit;
        const bool last = active.empty() || time_up || signals.first() != 0;
        if (run.rounds > 0) {
            PassRecord p;
            p.pass = ++pass;
            p.spp = std::uint64_t(run.image.mean_spp + 0.5);
            p.wall_s = since(start);
            p.render_s = renderer.stats().render_seconds;
            p.compile_s = renderer.stats().compile_seconds;
            p.estimate = run.image.estimate;
            if (reference) p.reference = compare_images(run.image.rgb, reference->rgb, opt.reference);
            passes.push_back(p);
            write_report_csv(report, passes);
            const double rate = double(p.spp) / std::max(p.render_s, 1e-9);
            progress.update(p, max_spp, 0.0, rate * double(renderer.pixel_count()) * 1e-6, last);
        }
        if (last) {
            run.converged = active.empty() && std::all_of(run.image.band_relmse.begin(), run.image.band_relmse.end(),
                                                          [&](double e) { return e <= threshold; });
            return run;
        }
        // Double each active band's samples (up to --spp), in launches of bounded length.
        const auto round_start = Clock::now();
        for (int band : active) {
            std::uint64_t& spp = layout.spp[std::size_t(band)];
            const std::uint32_t row = std::uint32_t(band * kBandRows);
            const std::uint32_t rows = std::uint32_t(std::min(kBandRows, layout.height - band * kBandRows));
            std::uint64_t todo = std::min(spp, max_spp - spp);
            const std::uint64_t per_launch = std::max<std::uint64_t>(
                1, std::uint64_t(kMaxLaunchSeconds / std::max(row_sample_s * double(rows), 1e-12)));
            while (todo > 0 && signals.first() == 0) {
                const std::uint32_t n = std::uint32_t(std::min({todo, per_launch, std::uint64_t(1) << 20}));
                renderer.launch_band(spp, n, row, rows);
                spp += n;
                todo -= n;
            }
        }
        renderer.end_pass(0, since(round_start));
        run.rounds += 1;
    }
}

}  // namespace facet
