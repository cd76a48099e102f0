// The error of a denoised image without a reference, from the film's two independent
// half-images a and b (docs/denoising.md). facet's denoiser (denoiser.hpp) denoises each
// half on its own, D(a) and D(b), and writes F = (D(a) + D(b)) / 2. For a pixel, with
// D(a) independent of b:
//     E[(D(a) - b)^2] = mse(D(a)) + Var(b),    Var(b) = E[(a - b)^2] n_a / n,
// and, the halves being denoised alike (the same bias beta, variances v_a and v_b),
//     E[(D(a) - D(b))^2] = v_a + v_b,    mse(F) = beta^2 + (v_a + v_b) / 4.
// So
//     mse_hat(F) = 1/2 [(D(a) - b)^2 - Var(b) + (D(b) - a)^2 - Var(a)] - (D(a) - D(b))^2 / 4
// is unbiased for the denoised image's MSE, pixel by pixel, as long as each denoised half
// is independent of the other half. For D = identity it is the noisy image's estimate
// (error_metrics.hpp). A pixel's term can be negative; an image mean that is not positive
// is NaN (unknown): it means the halves were not independent (docs/denoising.md).
#pragma once

#include "host/denoise/denoiser.hpp"
#include "host/film/error_metrics.hpp"
#include "host/film/film_halves.hpp"

namespace facet {

// The estimated error of `denoised.rgb` from the halves it was made of. relmse divides
// by (F + 0.01)^2 with F the denoised image itself (slightly biased, as for the noisy
// estimate). NaN when a half holds no sample or the sizes differ.
ErrorMetrics estimate_denoised_error(const FilmHalves& halves, const DenoisedImage& denoised);

}  // namespace facet
