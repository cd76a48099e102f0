// The progressive schedule: how many samples the next pass adds and how many rows one
// kernel launch covers, chosen from the speed measured so far, the target, the time
// limit and the launch-time bound. Pure functions, no device (as Cycles keeps its
// integrator/render_scheduler.cpp), so every rule is unit-tested on its own
// (tests/progressive_test.cpp).
#pragma once

#include <cstdint>
#include <optional>

namespace facet {

struct ScheduleRules {
    double pass_fraction = 0.1;   // a pass takes about this share of the render time so far
    double min_pass_s = 0.05;     // ... clamped to these (log-spaced error points, few passes)
    double max_pass_s = 2.0;
    double max_growth = 2.0;      // a pass has at most this many times the last pass's samples
    double max_launch_s = 0.25;   // per kernel launch (GPU display watchdogs kill at ~2 s)
    double probe_pixels = 4096;   // the first launch of a render: pixels of one sample each
};

// Where a render stands, as the schedule sees it.
struct ScheduleState {
    std::uint64_t target_spp = 0;
    std::optional<double> time_limit_s;   // seconds of rendering allowed
    std::uint64_t done_spp = 0;           // samples per pixel finished
    double render_s = 0.0;                // seconds spent rendering them
    std::uint32_t last_pass = 0;          // samples of the last pass (0: none yet)
};

// Whether the render is over: the target reached, or the time limit spent.
bool schedule_done(const ScheduleState& s);

// Samples of the next pass: 1 first; then about pass_fraction of the render time so
// far at the measured rate, clamped to [min_pass_s, max_pass_s], at most max_growth
// times the last pass and at least 1; never past the target, and cut to the time left
// (at least 1). 0 when schedule_done().
std::uint32_t next_pass_samples(const ScheduleState& s, const ScheduleRules& rules = {});

// Rows of one launch adding `samples` samples per pixel, at the measured
// `seconds_per_sample` (one sample at one pixel), so that a launch runs at most
// max_launch_s: at least 1, at most `height`. Without a measurement (<= 0), the
// probe's rows: about probe_pixels pixels.
std::uint32_t rows_per_launch(double seconds_per_sample, std::uint32_t width, std::uint32_t height,
                              std::uint32_t samples, const ScheduleRules& rules = {});

// Seconds left to the target at the measured rate, or to the time limit if sooner.
double schedule_remaining_s(const ScheduleState& s);

}  // namespace facet
