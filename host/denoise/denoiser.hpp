// facet's own denoiser (kernels/denoise/denoise.cl), run on the render's OpenCL device:
// each half-image of the film is denoised on its own, guided by its colour, its own
// variance (denoise_variance.hpp) and the AOV features, and the denoised image is the mean of the
// two denoised halves. Keeping the halves apart is what lets the error of the denoised
// image be estimated without a reference (host/denoise/denoise_error.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "host/cl/runtime.hpp"
#include "host/denoise/denoise_variance.hpp"
#include "host/film/film_halves.hpp"
#include "host/render/aov.hpp"
#include "kernels/shared/denoise_layout.h"

namespace facet {

struct DenoiseSettings {
    std::uint32_t radius = 6;           // the window: (2 radius + 1)^2 pixels
    std::uint32_t patch_radius = 1;     // the colour distance's patch
    std::uint32_t variance_radius = 2;  // the box smoothing the variance estimate
    std::uint32_t guides = FC_DENOISE_GUIDE_ALL;
    float k_color = 1.2f;        // colour distances in standard deviations (larger: smoother)
    float sigma_albedo = 0.05f;  // albedo difference (RGB, Euclidean) at one standard deviation
    float sigma_normal = 0.15f;  // normal difference (Euclidean) at one standard deviation
    float sigma_depth = 0.05f;   // depth difference relative to the larger depth
};

struct DenoisedImage {
    std::vector<float> rgb;      // the mean of the two denoised halves, 3 floats a pixel
    std::vector<float> half[2];  // each half denoised on its own
    double seconds = 0.0;        // uploading, filtering, reading back (and the build: denoise())
    bool own_variance = false;   // each half filtered with its own variance (denoise_variance.hpp)
};

// The kernels' parameters for an image of `width` x `height` whose halves' variance is
// `variance` (the padded planes' layout included: kernels/shared/denoise_layout.h).
// Throws facet::Error when the planes would not be addressable with 32-bit indices.
FcDenoiseParams denoise_params(std::uint32_t width, std::uint32_t height, const DenoiseVariance& variance,
                               const DenoiseSettings& settings);

// facet's denoiser on one device, its program built once (at construction) and run on
// any number of images: a render's snapshots and its final image pay the build once, and a
// render session builds it on a thread of its own while the device renders.
class Denoiser {
public:
    explicit Denoiser(const ClContext& ctx);

    // Denoises the film's halves (`halves`, `width` x `height`) with the AOV `features`
    // (albedo, normal, depth: as render/aov.hpp). Throws facet::Error when a half holds no
    // sample, when the sizes disagree, or on an OpenCL failure. DenoisedImage::seconds
    // counts uploading, filtering and reading back, not the program's build.
    DenoisedImage run(std::uint32_t width, std::uint32_t height, const FilmHalves& halves, const AovImages& features,
                      const DenoiseSettings& settings = {}) const;
    double build_seconds() const { return build_seconds_; }

private:
    mutable ClContext ctx_;  // its queue runs the kernels
    cl::Program program_;
    double build_seconds_ = 0.0;
};

// Builds a Denoiser and runs it once (DenoisedImage::seconds then includes the build).
DenoisedImage denoise(ClContext& ctx, std::uint32_t width, std::uint32_t height, const FilmHalves& halves,
                      const AovImages& features, const DenoiseSettings& settings = {});

}  // namespace facet
