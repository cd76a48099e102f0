#include "host/denoise/denoise_error.hpp"

#include <cmath>
#include <limits>

namespace facet {

ErrorMetrics estimate_denoised_error(const FilmHalves& halves, const DenoisedImage& denoised) {
    const std::vector<float>&a = halves.rgb[0], &b = halves.rgb[1];
    const std::vector<float>&da = denoised.half[0], &db = denoised.half[1];
    ErrorMetrics m;
    const std::size_t size = a.size();
    if (halves.samples[0] == 0 || halves.samples[1] == 0 || size == 0 || b.size() != size || da.size() != size ||
        db.size() != size || denoised.rgb.size() != size) {
        m.mse = m.rmse = m.relmse = std::numeric_limits<double>::quiet_NaN();
        return m;
    }
    const double n = double(halves.samples[0] + halves.samples[1]);
    const double share_a = double(halves.samples[0]) / n, share_b = double(halves.samples[1]) / n;
    for (std::size_t i = 0; i < size; ++i) {
        const double d = double(a[i]) - double(b[i]);
        const double var_a = d * d * share_b, var_b = d * d * share_a;  // each half's variance
        const double ea = double(da[i]) - double(b[i]), eb = double(db[i]) - double(a[i]);
        const double spread = double(da[i]) - double(db[i]);
        const double mse = 0.5 * (ea * ea - var_b + eb * eb - var_a) - 0.25 * spread * spread;
        const double f = double(denoised.rgb[i]) + 0.01;
        m.mse += mse;
        m.relmse += mse / (f * f);
    }
    m.mse /= double(size);
    m.relmse /= double(size);
    // Negative: the halves were not independent (docs/denoising.md), not a perfect image
    if (!(m.mse > 0.0)) m.mse = m.relmse = std::numeric_limits<double>::quiet_NaN();
    m.rmse = std::sqrt(m.mse);
    return m;
}

}  // namespace facet
