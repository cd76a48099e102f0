#include "host/render/progressive.hpp"

#include <algorithm>
#include <chrono>

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

ProgressiveResult render_progressive(PassTarget& target, const ProgressiveOptions& opt) {
    const std::uint32_t width = target.target_width(), height = target.target_height();
    const std::uint64_t start_spp = target.finished_spp();
    auto stop_requested = [&] { return opt.stop && opt.stop(); };
    // The schedule counts this run's samples and time.
    ScheduleState s;
    s.target_spp = opt.target_spp > start_spp ? opt.target_spp - start_spp : 0;
    s.time_limit_s = opt.time_limit_s;
    ProgressiveResult result;
    double seconds_per_sample = 0.0;   // one sample at one pixel, from the latest launch
    while (!schedule_done(s) && !stop_requested() && width > 0 && height > 0) {
        const std::uint32_t n = opt.fixed_pass
            ? std::uint32_t(std::min<std::uint64_t>(opt.fixed_pass, s.target_spp - s.done_spp))
            : next_pass_samples(s, opt.rules);
        const auto pass_start = Clock::now();
        for (std::uint32_t row = 0; row < height;) {
            // Nothing finished yet: a stop drops the first pass rather than wait for it.
            if (row > 0 && s.done_spp == 0 && start_spp == 0 && stop_requested()) {
                target.reset();
                result.stopped = true;
                return result;
            }
            // The first launch is a probe band; later ones are sized from its speed.
            const std::uint32_t rows =
                std::min(rows_per_launch(seconds_per_sample, width, height, n, opt.rules), height - row);
            const auto launch_start = Clock::now();
            target.launch(n, row, rows);
            const double launch_s = since(launch_start);
            seconds_per_sample = launch_s / (double(rows) * double(width) * double(n));
            result.launches += 1;
            result.longest_launch_s = std::max(result.longest_launch_s, launch_s);
            if (result.launches == 1 && opt.on_first_pass_estimate)
                opt.on_first_pass_estimate(seconds_per_sample * double(width) * double(height) * double(n));
            row += rows;
        }
        const double pass_s = since(pass_start);
        target.end_pass(n, pass_s);
        s.done_spp += n;
        s.render_s += pass_s;
        s.last_pass = n;
        result.passes += 1;
        PassDone done;
        done.pass = result.passes;
        done.samples = n;
        done.spp = target.finished_spp();
        done.render_s = s.render_s;
        done.remaining_s = schedule_remaining_s(s);
        done.last = schedule_done(s) || stop_requested();
        if (opt.on_pass) opt.on_pass(done);
    }
    result.stopped = stop_requested();
    result.spp = target.finished_spp();
    result.render_s = s.render_s;
    return result;
}

ProgressiveResult render_fixed(PassTarget& target, std::uint64_t spp, std::uint32_t pass) {
    ProgressiveOptions opt;
    opt.target_spp = target.finished_spp() + spp;
    opt.fixed_pass = pass ? pass : std::uint32_t(std::min<std::uint64_t>(spp, 0xffffffffu));
    return render_progressive(target, opt);
}

}  // namespace facet
