#include "host/render/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet {

bool schedule_done(const ScheduleState& s) {
    if (s.done_spp >= s.target_spp) return true;
    return s.time_limit_s && s.done_spp > 0 && s.render_s >= *s.time_limit_s;
}

std::uint32_t next_pass_samples(const ScheduleState& s, const ScheduleRules& rules) {
    if (schedule_done(s)) return 0;
    const std::uint64_t left = s.target_spp - s.done_spp;
    if (s.done_spp == 0 || s.render_s <= 0.0) return 1;
    const double rate = double(s.done_spp) / s.render_s;  // samples per pixel per second
    // About a tenth of the time so far, long enough that the host's work between passes is
    // a small share, at most twice the last pass.
    const double share = std::clamp(rules.max_host_share, 1e-3, 1.0);
    const double host_floor_s = std::max(s.host_s, 0.0) * (1.0 - share) / share;
    const double want_s =
        std::clamp(std::max(rules.pass_fraction * s.render_s, host_floor_s), rules.min_pass_s, rules.max_pass_s);
    const double growth = rules.max_growth * double(std::max<std::uint32_t>(s.last_pass, 1));
    double n = std::clamp(want_s * rate, 1.0, std::max(1.0, growth));
    n = std::min(n, double(left));
    // Cut to the time left.
    if (s.time_limit_s) n = std::clamp(std::floor((*s.time_limit_s - s.render_s) * rate), 1.0, n);
    n = std::min(n, double(std::numeric_limits<std::uint32_t>::max()));
    return std::uint32_t(n);
}

std::uint32_t rows_per_launch(const std::vector<double>& row_cost, std::uint32_t row_begin, std::uint32_t width,
                              std::uint32_t samples, std::uint32_t last_rows, const ScheduleRules& rules) {
    const std::size_t height = row_cost.size();
    if (row_begin >= height) return 0;
    const std::uint32_t left = std::uint32_t(height - row_begin);
    const double dearest = *std::max_element(row_cost.begin(), row_cost.end());
    if (!(dearest > 0.0)) {
        const double probe = std::floor(rules.probe_pixels / double(std::max<std::uint32_t>(width, 1)));
        return std::uint32_t(std::clamp(probe, 1.0, double(left)));
    }
    const double budget = rules.max_launch_s / double(std::max<std::uint32_t>(samples, 1));
    std::uint32_t rows = 0;
    bool unmeasured = false;
    double cost = 0.0;
    for (std::size_t r = row_begin; r < height; ++r) {
        const bool known = row_cost[r] > 0.0;
        const double c = known ? row_cost[r] : dearest;
        if (rows > 0 && cost + c > budget) break;
        cost += c;
        unmeasured |= !known;
        ++rows;
    }
    if (unmeasured && last_rows > 0)
        rows = std::min(rows, std::uint32_t(std::max(1.0, std::floor(rules.max_launch_growth * double(last_rows)))));
    return std::max<std::uint32_t>(rows, 1);
}

double schedule_remaining_s(const ScheduleState& s) {
    if (s.done_spp >= s.target_spp) return 0.0;
    double remaining = s.done_spp && s.render_s > 0.0
                           ? double(s.target_spp - s.done_spp) / (double(s.done_spp) / s.render_s)
                           : std::numeric_limits<double>::infinity();
    if (s.time_limit_s) remaining = std::min(remaining, std::max(0.0, *s.time_limit_s - s.render_s));
    return remaining;
}

}  // namespace facet
