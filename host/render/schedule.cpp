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
    const double rate = double(s.done_spp) / s.render_s;   // samples per pixel per second
    // About a tenth of the time so far, at most twice the last pass.
    const double want_s = std::clamp(rules.pass_fraction * s.render_s, rules.min_pass_s, rules.max_pass_s);
    const double growth = rules.max_growth * double(std::max<std::uint32_t>(s.last_pass, 1));
    double n = std::clamp(want_s * rate, 1.0, std::max(1.0, growth));
    n = std::min(n, double(left));
    // Cut to the time left.
    if (s.time_limit_s) n = std::clamp(std::floor((*s.time_limit_s - s.render_s) * rate), 1.0, n);
    n = std::min(n, double(std::numeric_limits<std::uint32_t>::max()));
    return std::uint32_t(n);
}

std::uint32_t rows_per_launch(double seconds_per_sample, std::uint32_t width, std::uint32_t height,
                              std::uint32_t samples, const ScheduleRules& rules) {
    if (height == 0) return 0;
    const double row_pixels = double(std::max<std::uint32_t>(width, 1));
    double rows;
    if (seconds_per_sample > 0.0 && std::isfinite(seconds_per_sample))
        rows = rules.max_launch_s / (seconds_per_sample * row_pixels * double(std::max<std::uint32_t>(samples, 1)));
    else
        rows = rules.probe_pixels / row_pixels;
    return std::uint32_t(std::clamp(std::floor(rows), 1.0, double(height)));
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
