// Numeric constants shared by the host.
#pragma once

#include <numbers>

namespace facet {

inline constexpr double kPi = std::numbers::pi;
inline constexpr float kPiF = std::numbers::pi_v<float>;

}  // namespace facet
