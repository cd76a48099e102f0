// The tile mode of a render session (`--noise-threshold RELMSE --adaptive tiles`): after
// the uniform passes (kMinAdaptiveSpp), rounds that double the samples of every band of
// rows whose own reference-free relMSE is still above the threshold
// (render/adaptive_bands.hpp), until no band is, or a band reaches the target spp, or the
// time limit or a stop request ends it. Launches are bounded by the schedule's
// max_launch_s (render/schedule.hpp), as the uniform passes are.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "host/render/adaptive_bands.hpp"
#include "host/render/device_group.hpp"
#include "host/render/schedule.hpp"

namespace facet {

struct TileOptions {
    double threshold = 0.0;              // relMSE of a band's estimate
    std::uint64_t max_spp = 0;           // no band goes past it
    std::optional<double> time_limit_s;  // seconds of rendering (the group's, so far)
    ScheduleRules rules;
    std::function<bool()> stop;  // polled between launches; ends the round early
    // After each round: the bands as resolved (image and estimate) and the round's number.
    std::function<void(const ResolvedBands& bands, int round, bool last)> on_round;
};

struct TileRun {
    BandLayout layout;
    ResolvedBands image;  // the final image and estimate
    int rounds = 0;
    bool converged = false;  // every band reached the threshold
};

// Continues `group` (every pixel at group.stats().samples_per_pixel) band by band.
TileRun render_tiles(DeviceGroup& group, const TileOptions& opt);

}  // namespace facet
