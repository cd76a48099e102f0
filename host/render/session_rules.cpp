#include "host/render/session_rules.hpp"

#include <algorithm>

namespace facet {

StopRules resolve_stop_rules(const StopRequest& request) {
    StopRules rules;
    rules.time_limit_s = request.time_limit_s;
    rules.noise_threshold = request.noise_threshold;
    rules.adaptive = request.adaptive;
    if (request.spp) {
        rules.spp = *request.spp;
    } else if (request.time_limit_s) {
        rules.spp = kUnboundedSpp;
        rules.spp_bounded = false;
    } else {
        rules.spp = request.scene_spp;
    }
    return rules;
}

std::uint64_t StopRules::uniform_spp() const {
    return adaptive == AdaptiveMode::tiles ? std::min(kMinAdaptiveSpp, spp) : spp;
}

bool StopRules::converged(std::uint64_t at_spp, double relmse) const {
    return noise_threshold && at_spp >= kMinAdaptiveSpp && relmse <= *noise_threshold;
}

}  // namespace facet
