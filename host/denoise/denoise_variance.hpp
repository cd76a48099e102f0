// The variance of each half-image's pixel means, as facet's denoiser reads it to scale its
// colour distances (kernels/denoise/denoise.cl, Rousselle et al. 2012). The kernel takes,
// per pixel and half, a value summed over the channels (`source`), smooths it over a box
// and multiplies the mean over the box and the channels by the half's `scale`.
//
// Each half's own variance, when the film holds its second moments (film/film_layout.hpp):
// with m_c the half's mean of channel c over its n samples and q its mean of
// r^2 + g^2 + b^2, the variance of the half's mean, summed over channels, is
//     (q - sum_c m_c^2) / (n - 1)
// (the sample variance over n). It reads the half alone, so the denoised half D(a) does
// not depend on b, which the error estimate needs (denoise_error.hpp): with a variance
// read from (a - b)^2 the filter smooths a more where b strays, toward b, and at 4 spp on
// the Cornell box the estimate read 27 % low over 12 renders (3 % with a variance from
// independent samples). The sample variance assumes independent samples; Owen-scrambled
// Sobol' points vary less than that, and by how much depends on the image (at 4 spp on
// the Cornell box about half over the whole image, less at the light's edge than on the
// walls), so both halves' variances are scaled by a calibration read over a box of
// (2 kCalibrationRadius + 1)^2 pixels around each pixel:
//     rho = sum over the box of (a - b)^2 / sum over the box of the halves' own variances
// (both summed over channels), which matches their sum to E[(a - b)^2] = Var(a) + Var(b)
// there while reading each pixel of b with the weight of one pixel in a thousand. One
// factor for the whole image kept the estimate unbiased as well but cost the filter 8 to
// 13 % of its RMSE at 64 spp on the Cornell box and material_grid; a 16 x 16 box read b
// closely enough to bias the estimate at 4 spp by -14 % (docs/performance.md).
//
// Without second moments (an older film), or below 2 samples in a half, the variance of
// both halves is E[(a - b)^2] n_other / n, read from the pair.
#pragma once

#include <cstddef>
#include <vector>

#include "host/film/film_halves.hpp"

namespace facet {

// The box of the calibration rho: (2 kCalibrationRadius + 1)^2 pixels.
inline constexpr std::size_t kCalibrationRadius = 16;

struct DenoiseVariance {
    std::vector<float> source;      // 2 * pixels floats: half a's plane, then half b's
    float scale[2] = {1.0f, 1.0f};  // each half's variance over the box mean of its source / 3
    bool own = false;               // each half's own variance (else the pair's)
    std::vector<float> rho;         // own only: the calibration, 1 float a pixel, folded into `source`
};

// The variance source of `halves`, an image of `width` x `height` (sizes checked by the
// caller).
DenoiseVariance denoise_variance(std::size_t width, std::size_t height, const FilmHalves& halves);

}  // namespace facet
