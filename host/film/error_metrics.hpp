// Image error metrics, against a reference or estimated without one, and the fitted
// convergence rate of an error series.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace facet {

struct ErrorMetrics {
    double mse = 0.0;     // mean over pixels and channels of (v - ref)^2
    double rmse = 0.0;    // sqrt(mse)
    double relmse = 0.0;  // mean of (v - ref)^2 / (ref + 0.01)^2, pbrt-v4's relative MSE
};

// Metrics of `image` against `reference` (both 3 floats a pixel, same size). Throws
// facet::Error naming `what` when the sizes differ or the reference holds NaN/Inf.
ErrorMetrics compare_images(const std::vector<float>& image, const std::vector<float>& reference,
                            const std::string& what = "reference");

// Estimated error of the mean of two independent half-images a and b (n_a and n_b
// samples per pixel), with no reference. For a pixel, Var(a - b) = Var(a) + Var(b);
// with per-sample variance s^2 that is s^2 (1/n_a + 1/n_b), while the combined mean
// of n = n_a + n_b samples has variance s^2 / n. So
//     mse_hat = (a - b)^2 * n_a n_b / n^2
// is an unbiased estimate of the combined image's variance, pixel by pixel, for any
// unbiased renderer. It sees variance only: bias (a wrong integrator, truncated
// paths) is invisible to it, which is why a reference is better when there is one.
// relmse divides by (m + 0.01)^2 with m the combined image itself, which makes it
// slightly biased (the denominator is noisy); rmse and mse are unbiased for the
// variance part of the error.
ErrorMetrics estimate_error(const std::vector<float>& a, const std::vector<float>& b, std::uint64_t n_a,
                            std::uint64_t n_b);

// The same over `count` values of each half that get(j, a_j, b_j) supplies, j in order, for
// halves that are never stored whole (film_halves.hpp's estimate_film_error).
template <class Get>
ErrorMetrics estimate_error_streamed(std::size_t count, std::uint64_t n_a, std::uint64_t n_b, Get&& get) {
    ErrorMetrics m;
    if (n_a == 0 || n_b == 0 || count == 0) {
        m.mse = m.rmse = m.relmse = std::numeric_limits<double>::quiet_NaN();
        return m;
    }
    const double n = double(n_a + n_b);
    const double scale = double(n_a) * double(n_b) / (n * n);
    const double wa = double(n_a) / n, wb = double(n_b) / n;
    for (std::size_t j = 0; j < count; ++j) {
        float a = 0.0f, b = 0.0f;
        get(j, a, b);
        const double d = double(a) - double(b);
        const double var = d * d * scale;
        const double mean = wa * double(a) + wb * double(b);
        m.mse += var;
        m.relmse += var / ((mean + 0.01) * (mean + 0.01));
    }
    m.mse /= double(count);
    m.relmse /= double(count);
    m.rmse = std::sqrt(m.mse);
    return m;
}

// Least-squares slope of log(y) against log(x) over the points with x > 0 and y > 0;
// NaN when fewer than 3 such points or x spans no range.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace facet
