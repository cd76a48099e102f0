// Colour helpers shared by the host: luminance of linear RGB.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

// The Y row of the Rec. 709 / sRGB RGB -> XYZ matrix (linear RGB, D65).
inline constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};

inline double luminance(double r, double g, double b) {
    return kLuminanceWeights[0] * r + kLuminanceWeights[1] * g + kLuminanceWeights[2] * b;
}
inline double luminance(const float rgb[3]) { return luminance(double(rgb[0]), double(rgb[1]), double(rgb[2])); }
inline double luminance(glm::vec3 c) { return luminance(double(c.x), double(c.y), double(c.z)); }

}  // namespace facet
