// The host's one clock for timing spans (compile, passes, launches): steady, never adjusted.
#pragma once

#include <chrono>

namespace facet {

using Clock = std::chrono::steady_clock;

// Seconds from `t` to now.
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace facet
