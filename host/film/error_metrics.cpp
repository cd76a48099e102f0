#include "host/film/error_metrics.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {

ErrorMetrics compare_images(const std::vector<float>& image, const std::vector<float>& reference,
                            const std::string& what) {
    if (image.size() != reference.size())
        throw Error(fmt::format("{}: has {} pixels, the image {}", what, reference.size() / 3, image.size() / 3));
    if (image.empty()) throw Error(fmt::format("{}: empty image", what));
    ErrorMetrics m;
    for (std::size_t i = 0; i < image.size(); ++i) {
        double ref = reference[i];
        if (!std::isfinite(ref)) throw Error(fmt::format("{}: texel {} (pixel {}) is not finite", what, i % 3, i / 3));
        double d = double(image[i]) - ref;
        m.mse += d * d;
        m.relmse += d * d / ((ref + 0.01) * (ref + 0.01));
    }
    m.mse /= double(image.size());
    m.relmse /= double(image.size());
    m.rmse = std::sqrt(m.mse);
    return m;
}

ErrorMetrics estimate_error(const std::vector<float>& a, const std::vector<float>& b, std::uint64_t n_a,
                            std::uint64_t n_b) {
    if (a.size() != b.size()) return estimate_error_streamed(0, n_a, n_b, [](std::size_t, float&, float&) {});
    return estimate_error_streamed(a.size(), n_a, n_b, [&](std::size_t j, float& x, float& y) {
        x = a[j];
        y = b[j];
    });
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0) || !std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
        double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        ++n;
    }
    double denom = n * sxx - sx * sx;
    if (n < 3 || !(denom > 1e-12)) return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / denom;
}

}  // namespace facet
