#include "host/render/session_tiles.hpp"

#include <algorithm>
#include <chrono>

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBandRows = 8;

}  // namespace

TileRun render_tiles(DeviceGroup& group, const TileOptions& opt) {
    TileRun run;
    BandLayout& layout = run.layout;
    layout.width = group.width();
    layout.height = group.height();
    layout.band_rows = kBandRows;
    layout.spp.assign(std::size_t(layout.bands()), group.stats().samples_per_pixel);
    auto stop_requested = [&] { return opt.stop && opt.stop(); };
    // Seconds per sample per row, as the uniform passes measured it.
    const double row_sample_s =
        group.stats().render_seconds / std::max(1.0, double(group.stats().samples_per_pixel) * double(layout.height));
    for (;;) {
        run.image = resolve_bands(group.accumulation(), layout);
        const std::vector<int> active = bands_above(run.image, layout, opt.threshold, opt.max_spp);
        const bool time_up = opt.time_limit_s && group.stats().render_seconds >= *opt.time_limit_s;
        const bool last = active.empty() || time_up || stop_requested();
        if (run.rounds > 0 && opt.on_round) opt.on_round(run.image, run.rounds, last);
        if (last) {
            run.converged = active.empty() && std::all_of(run.image.band_relmse.begin(), run.image.band_relmse.end(),
                                                          [&](double e) { return e <= opt.threshold; });
            return run;
        }
        // Double each active band's samples (up to max_spp), in launches of bounded length.
        const auto round_start = Clock::now();
        for (int band : active) {
            std::uint64_t& spp = layout.spp[std::size_t(band)];
            const std::uint32_t row = std::uint32_t(band * kBandRows);
            const std::uint32_t rows = std::uint32_t(std::min(kBandRows, layout.height - band * kBandRows));
            std::uint64_t todo = std::min(spp, opt.max_spp - spp);
            const std::uint64_t per_launch = std::max<std::uint64_t>(
                1, std::uint64_t(opt.rules.max_launch_s / std::max(row_sample_s * double(rows), 1e-12)));
            while (todo > 0 && !stop_requested()) {
                const std::uint32_t n = std::uint32_t(std::min({todo, per_launch, std::uint64_t(1) << 20}));
                group.launch_band(spp, n, row, rows);
                spp += n;
                todo -= n;
            }
        }
        group.end_pass(0, std::chrono::duration<double>(Clock::now() - round_start).count());
        run.rounds += 1;
    }
}

}  // namespace facet
