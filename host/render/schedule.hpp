// The progressive schedule: how many samples the next pass adds and how many rows one
// kernel launch covers, chosen from the speed measured so far, the target, the time
// limit and the launch-time bound. Pure functions, no device (as Cycles keeps its
// integrator/render_scheduler.cpp), so every rule is unit-tested on its own
// (tests/progressive_test.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace facet {

struct ScheduleRules {
    double pass_fraction = 0.1;  // a pass takes about this share of the render time so far
    double min_pass_s = 0.05;    // ... clamped to these (log-spaced error points, few passes)
    double max_pass_s = 2.0;
    double max_growth = 2.0;  // a pass has at most this many times the last pass's samples
    // The host's work between passes (reading the films back, the error estimate, the
    // report) at most about this share of the wall time: a pass lasts at least
    // host_s (1 - share) / share, within max_pass_s. It bites where passes are short
    // against it: large images on fast devices (a GPU at 1024²).
    double max_host_share = 0.05;
    double max_launch_s = 0.25;      // per kernel launch (GPU display watchdogs kill at ~2 s)
    double max_launch_growth = 2.0;  // rows of a launch into unmeasured rows, over the last launch's
    double probe_pixels = 4096;      // the first launch of a render: pixels of one sample each
};

// Where a render stands, as the schedule sees it.
struct ScheduleState {
    std::uint64_t target_spp = 0;
    std::optional<double> time_limit_s;  // seconds of rendering allowed
    std::uint64_t done_spp = 0;          // samples per pixel finished
    double render_s = 0.0;               // seconds spent rendering them
    std::uint32_t last_pass = 0;         // samples of the last pass (0: none yet)
    double host_s = 0.0;                 // the host's time between the last two passes, as measured
};

// Whether the render is over: the target reached, or the time limit spent.
bool schedule_done(const ScheduleState& s);

// Samples of the next pass: 1 first; then about pass_fraction of the render time so
// far at the measured rate, and at least the host's time between passes times
// (1 - max_host_share) / max_host_share, clamped to [min_pass_s, max_pass_s], at most max_growth
// times the last pass and at least 1; never past the target, and cut to the time left
// (at least 1). 0 when schedule_done().
std::uint32_t next_pass_samples(const ScheduleState& s, const ScheduleRules& rules = {});

// Rows of the next launch, from `row_begin`, adding `samples` samples per pixel: as
// many as fit in max_launch_s by the measured cost of each row (`row_cost`, one entry a
// row: seconds for one sample over the whole row, 0 where not measured yet). Rows not
// measured count as the dearest measured one, and a launch reaching into them covers
// at most max_launch_growth times `last_rows` (the previous launch's), since the rows
// measured so far may be the cheap ones. Nothing measured: the probe band, about
// probe_pixels pixels. At least 1 row, at most the rows left.
std::uint32_t rows_per_launch(const std::vector<double>& row_cost, std::uint32_t row_begin, std::uint32_t width,
                              std::uint32_t samples, std::uint32_t last_rows, const ScheduleRules& rules = {});

// Seconds left to the target at the measured rate, or to the time limit if sooner.
double schedule_remaining_s(const ScheduleState& s);

}  // namespace facet
