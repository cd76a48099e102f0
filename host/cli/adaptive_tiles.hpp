// `facet render --noise-threshold RELMSE --adaptive tiles`: after the uniform passes
// (16 spp), rounds that double the samples of every band of rows whose own
// reference-free relMSE is still above the threshold (render/adaptive_bands.hpp), until
// no band is, or a band reaches --spp, or --time or a stop signal ends it. Each round is
// a report row (its spp column the mean samples per pixel).
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/stop_signals.hpp"
#include "host/image/image_io.hpp"
#include "host/render/adaptive_bands.hpp"
#include "host/render/device_group.hpp"
#include "host/report/report.hpp"

namespace facet {

struct TileRun {
    BandLayout layout;
    ResolvedBands image;  // the final image and estimate
    int rounds = 0;
    bool converged = false;  // every band reached the threshold
};

// Continues `renderer` (every pixel at renderer.stats().samples_per_pixel) band by band;
// appends a PassRecord per round to `passes` and rewrites `report` after each.
TileRun render_adaptive_tiles(const RenderOptions& opt, const Scene& scene, DeviceGroup& renderer,
                              const std::optional<ImageRGB>& reference, const std::string& report,
                              std::chrono::steady_clock::time_point start, const StopSignals& signals,
                              std::vector<PassRecord>& passes);

}  // namespace facet
