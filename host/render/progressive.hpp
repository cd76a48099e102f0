// The progressive driver: passes of samples on a PassTarget until the target spp, the
// time limit or a stop request, each pass cut into launches of bounded length, with a
// callback after every pass (the CLI's report row, snapshot and progress line). Pass
// sizes and rows per launch come from render/schedule.hpp. The render session
// (render/session.hpp), the bench and the tests render through it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "host/render/pass_target.hpp"
#include "host/render/schedule.hpp"

namespace facet {

// After each finished pass.
struct PassDone {
    int pass = 0;               // 1, 2, ...
    std::uint32_t samples = 0;  // samples per pixel this pass added
    std::uint64_t spp = 0;      // samples per pixel finished
    double render_s = 0.0;      // seconds in passes so far (this run)
    double remaining_s = 0.0;   // to the target or the time limit, at the measured rate
    bool last = false;          // no pass follows (target, time limit or stop request)
};

struct ProgressiveOptions {
    std::uint64_t target_spp = 1;
    std::optional<double> time_limit_s;  // seconds of rendering
    // > 0: passes of exactly this many samples (the last one cut to the target), for
    // tests and benchmarks that need fixed pass sizes. 0: the schedule's.
    std::uint32_t fixed_pass = 0;
    ScheduleRules rules;
    // Polled between launches. A stop ends the render after the current pass; during
    // the first pass it drops that pass at once (there is nothing finished to keep).
    std::function<bool()> stop;
    std::function<void(const PassDone&)> on_pass;
    // At most once, during the first pass, once the seconds it has taken so far exceed the
    // time limit with rows still to render (measured, so one sample per pixel does take
    // longer than the limit): the pass's estimated seconds, the rows rendered so far as
    // measured and the rest at their mean.
    std::function<void(double first_pass_s)> on_first_pass_estimate;
};

struct ProgressiveResult {
    std::uint64_t spp = 0;  // samples per pixel finished
    int passes = 0;
    bool stopped = false;   // ended by a stop request
    double render_s = 0.0;  // seconds in passes, this run
    int launches = 0;
    double longest_launch_s = 0.0;
};

ProgressiveResult render_progressive(PassTarget& target, const ProgressiveOptions& opt);

// Adds exactly `spp` samples per pixel in passes of `pass` samples (0: one pass): the
// tests' and the bench's fixed schedules.
ProgressiveResult render_fixed(PassTarget& target, std::uint64_t spp, std::uint32_t pass = 0);

}  // namespace facet
