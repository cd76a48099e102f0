// The stop rules of a render session (render/session.hpp), resolved once from what the
// user asked: the samples per pixel, the time and the noise threshold, whichever ends
// first. Pure functions, no device (tests/render_session_test.cpp).
//
// The samples per pixel: `--spp` when given; else, when `--time` is given, none (time is
// the stop: the render goes on up to kUnboundedSpp, the largest --spp, over the scene
// file's spp too); else the scene's spp (a scene file's, 64 by default).
#pragma once

#include <cstdint>
#include <optional>

namespace facet {

// The noise threshold is judged from this many samples per pixel on (the half-buffer
// estimate is too noisy below); the tile mode renders this many uniformly first.
constexpr std::uint64_t kMinAdaptiveSpp = 16;

// The samples per pixel of a render that only time stops: the largest --spp
// (scene/settings_limits.hpp: limits::kSpp), which keeps every sample index below 2^32.
constexpr std::uint64_t kUnboundedSpp = std::uint64_t{1} << 24;

enum class AdaptiveMode { global, tiles };

// What the user asked, before the rules are resolved.
struct StopRequest {
    std::optional<std::uint64_t> spp;  // --spp
    std::uint64_t scene_spp = 64;      // the scene's (render.spp)
    std::optional<double> time_limit_s;
    std::optional<double> noise_threshold;  // relMSE of the half-buffer estimate
    AdaptiveMode adaptive = AdaptiveMode::global;
};

struct StopRules {
    std::uint64_t spp = 64;   // the target samples per pixel (kUnboundedSpp when unbounded)
    bool spp_bounded = true;  // false: only time (and the noise threshold) end the render
    std::optional<double> time_limit_s;
    std::optional<double> noise_threshold;
    AdaptiveMode adaptive = AdaptiveMode::global;

    // The uniform passes' target: all of it, or in the tile mode the first kMinAdaptiveSpp.
    std::uint64_t uniform_spp() const;
    // The noise threshold is reached at `spp` samples with this relMSE estimate: the
    // global mode stops there, and the outcome is "converged".
    bool converged(std::uint64_t spp, double relmse) const;
    // The target as a progress display shows it: 0 when unbounded.
    std::uint64_t shown_spp() const { return spp_bounded ? spp : 0; }
};

StopRules resolve_stop_rules(const StopRequest& request);

}  // namespace facet
