#include "host/render/progressive.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "host/util/clock.hpp"

namespace facet {

ProgressiveResult render_progressive(PassTarget& target, const ProgressiveOptions& opt) {
    const std::uint32_t width = target.target_width(), height = target.target_height();
    const std::uint64_t start_spp = target.finished_spp();
    auto stop_requested = [&] { return opt.stop && opt.stop(); };
    // The schedule counts this run's samples and time.
    ScheduleState s;
    s.target_spp = opt.target_spp > start_spp ? opt.target_spp - start_spp : 0;
    s.time_limit_s = opt.time_limit_s;
    ProgressiveResult result;
    std::vector<double> row_cost(height, 0.0);  // seconds for one sample over each row, as measured
    std::uint32_t last_rows = 0;
    bool first_pass_estimated = false;
    std::optional<Clock::time_point> last_pass_end;  // when the last pass's launches ended
    while (!schedule_done(s) && !stop_requested() && width > 0 && height > 0) {
        // The host's work since then: the films read back, the estimate, the report.
        if (last_pass_end) s.host_s = seconds_since(*last_pass_end);
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
            // The first launch is a probe band; later ones are sized by the measured rows.
            const std::uint32_t rows = rows_per_launch(row_cost, row, width, n, last_rows, opt.rules);
            const auto launch_start = Clock::now();
            target.launch(n, row, rows);
            const double launch_s = seconds_since(launch_start);
            for (std::uint32_t r = row; r < row + rows; ++r)
                row_cost[r] = std::max(launch_s, 1e-9) / (double(rows) * double(n));
            last_rows = rows;
            result.launches += 1;
            result.longest_launch_s = std::max(result.longest_launch_s, launch_s);
            row += rows;
            // The first pass's length: measured rows as measured, the rest at their mean.
            if (s.done_spp == 0 && row < height && opt.time_limit_s && opt.on_first_pass_estimate &&
                !first_pass_estimated) {
                const double done_s = seconds_since(pass_start);
                if (done_s > *opt.time_limit_s) {
                    const double estimate = done_s + done_s / double(row) * double(height - row);
                    opt.on_first_pass_estimate(estimate);
                    first_pass_estimated = true;
                }
            }
        }
        const double pass_s = seconds_since(pass_start);
        last_pass_end = Clock::now();
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
