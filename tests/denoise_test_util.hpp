// Feature buffers for the denoiser's tests (denoiser_test.cpp, oidn_test.cpp).
#pragma once

#include <cstddef>

#include "host/render/aov.hpp"

namespace facet::test {

// Flat features over `pixels` pixels: albedo 0.5, normal +z, depth 1.
inline AovImages flat_features(std::size_t pixels) {
    AovImages f;
    f.albedo.assign(3 * pixels, 0.5f);
    f.normal.assign(3 * pixels, 0.0f);
    for (std::size_t i = 0; i < pixels; ++i) f.normal[3 * i + 2] = 1.0f;
    f.depth.assign(pixels, 1.0f);
    return f;
}

}  // namespace facet::test
