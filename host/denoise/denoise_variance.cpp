#include "host/denoise/denoise_variance.hpp"

#include <algorithm>

namespace facet {
namespace {

// Sums of `v` (width w, height h) over the box of (2 r + 1)^2 pixels around each pixel,
// clipped at the border, from a summed-area table (doubles: the table's entries grow with
// the image).
std::vector<double> box_sums(const std::vector<double>& v, std::size_t w, std::size_t h, std::size_t r) {
    std::vector<double> table((w + 1) * (h + 1), 0.0);
    for (std::size_t y = 0; y < h; ++y)
        for (std::size_t x = 0; x < w; ++x)
            table[(y + 1) * (w + 1) + x + 1] =
                v[y * w + x] + table[y * (w + 1) + x + 1] + table[(y + 1) * (w + 1) + x] - table[y * (w + 1) + x];
    std::vector<double> out(w * h);
    for (std::size_t y = 0; y < h; ++y)
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t x0 = x > r ? x - r : 0, y0 = y > r ? y - r : 0;
            const std::size_t x1 = std::min(x + r + 1, w), y1 = std::min(y + r + 1, h);
            out[y * w + x] = table[y1 * (w + 1) + x1] - table[y0 * (w + 1) + x1] - table[y1 * (w + 1) + x0] +
                             table[y0 * (w + 1) + x0];
        }
    return out;
}

}  // namespace

DenoiseVariance denoise_variance(std::size_t width, std::size_t height, const FilmHalves& h) {
    DenoiseVariance v;
    const std::vector<float>&a = h.rgb[0], &b = h.rgb[1];
    const std::size_t pixels = width * height;
    v.source.resize(2 * pixels);
    // Per pixel, summed over channels: (a - b)^2, the pair's estimate and the calibration's
    std::vector<double> pair(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        double d2 = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = double(a[3 * i + c]) - double(b[3 * i + c]);
            d2 += d * d;
        }
        pair[i] = d2;
        v.source[i] = v.source[pixels + i] = float(d2);
    }
    const double n = double(h.samples[0] + h.samples[1]);
    v.own = h.samples[0] >= 2 && h.samples[1] >= 2 && h.square[0].size() == pixels && h.square[1].size() == pixels;
    if (!v.own) {
        v.scale[0] = float(double(h.samples[1]) / n);
        v.scale[1] = float(double(h.samples[0]) / n);
        return v;
    }
    // Each half's own: (q - sum_c m_c^2), to be divided by n - 1 (the scale)
    std::vector<double> own(pixels, 0.0);
    for (int k = 0; k < 2; ++k) {
        const std::vector<float>& m = h.rgb[k];
        const double to_mean = 1.0 / (double(h.samples[k]) - 1.0);
        v.scale[k] = float(to_mean);
        for (std::size_t i = 0; i < pixels; ++i) {
            double spread = double(h.square[k][i]);
            for (std::size_t c = 0; c < 3; ++c) spread -= double(m[3 * i + c]) * double(m[3 * i + c]);
            spread = std::max(spread, 0.0);  // float rounding of q - m^2
            v.source[std::size_t(k) * pixels + i] = float(spread);
            own[i] += spread * to_mean;
        }
    }
    // The calibration rho over the box around each pixel (1 where the box holds no spread)
    const std::vector<double> pair_box = box_sums(pair, width, height, kCalibrationRadius);
    const std::vector<double> own_box = box_sums(own, width, height, kCalibrationRadius);
    v.rho.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        v.rho[i] = own_box[i] > 0.0 && pair_box[i] > 0.0 ? float(pair_box[i] / own_box[i]) : 1.0f;
        v.source[i] *= v.rho[i], v.source[pixels + i] *= v.rho[i];
    }
    return v;
}

}  // namespace facet
