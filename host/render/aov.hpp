// Auxiliary images (AOVs) for denoisers and compositors: albedo, shading normal and depth
// at the first non-specular hit (kernels/aov/aov.cl), rendered by their own short pass
// before the image: the compiled scene is uploaded for it, its samples are taken, and its
// buffers are released before the path tracer's upload (so the device holds the scene
// once at a time).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/cl/runtime.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// The AOVs a render can add to its EXR, by name: "albedo", "normal", "depth".
inline constexpr const char* kAovNames[] = {"albedo", "normal", "depth"};

struct AovImages {
    std::vector<float> albedo;  // 3 floats a pixel, top row first; 0 where nothing was hit
    std::vector<float> normal;  // 3 floats a pixel (world space, filtered: not unit length at edges)
    std::vector<float> depth;   // 1 float a pixel: path length to the hit; 0 where nothing was hit
    double seconds = 0.0;       // building the program and rendering
};

// The seed of the AOV pass for a render of seed `seed`: never the render's own. The AOVs
// guide a denoiser that filters each half-image on its own so that the other half can
// check it (docs/denoising.md); camera samples shared with the halves (the same seed and
// sample indices give the same pixel positions) would carry where the other half's rays
// landed into the guides, and the check would read low: at 4 spp on the Cornell box, 12
// renders pooled, -27 % of the true denoised error with the shared samples, -16 % without.
constexpr std::uint32_t aov_seed(std::uint32_t seed) { return seed ^ 0x0a0f5eedu; }

// Renders the AOVs of `scene` with `spp` camera samples per pixel, drawn as the path
// tracer draws them (its pixel filter and lens) but from samples of their own (aov_seed).
// Throws facet::Error on OpenCL failures.
AovImages render_aovs(ClContext& ctx, const Scene& scene, const Bvh& bvh, std::uint32_t spp);
// The same with the scene already compiled (`dev`, of `scene` and `bvh`), as the render's
// devices share it.
AovImages render_aovs(ClContext& ctx, const Scene& scene, const Bvh& bvh, const DeviceScene& dev, std::uint32_t spp);

}  // namespace facet
