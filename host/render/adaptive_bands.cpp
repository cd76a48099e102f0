#include "host/render/adaptive_bands.hpp"

#include <cmath>
#include <cstddef>

#include "host/error.hpp"
#include "host/film/film_layout.hpp"

namespace facet {

ResolvedBands resolve_bands(const std::vector<float>& sums, const BandLayout& layout) {
    const std::size_t w = std::size_t(layout.width), h = std::size_t(layout.height), n = w * h;
    if (sums.size() != film_floats(n) || layout.spp.size() != std::size_t(layout.bands()))
        throw Error("adaptive tiles: the accumulation buffer or the band counts do not fit the image");
    ResolvedBands r;
    r.rgb.assign(3 * n, 0.0f);
    r.band_relmse.assign(layout.spp.size(), 0.0);
    r.band_mse.assign(layout.spp.size(), 0.0);
    std::vector<double> band_values(layout.spp.size(), 0.0);
    double mse = 0.0, relmse = 0.0;
    for (std::size_t y = 0; y < h; ++y) {
        const std::size_t band = std::size_t(layout.band_of_row(int(y)));
        const std::uint64_t spp = layout.spp[band];
        // Sample i goes to half i % 2: the even half holds ceil(spp / 2) samples.
        const double n_a = double((spp + 1) / 2), n_b = double(spp / 2), total = n_a + n_b;
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t p = y * w + x;
            for (std::size_t c = 0; c < 3; ++c) {
                const double sa = double(sums[4 * p + c]), sb = double(sums[4 * (n + p) + c]);
                const double m = total > 0 ? (sa + sb) / total : 0.0;
                r.rgb[3 * p + c] = float(m);
                if (n_a > 0 && n_b > 0) {
                    const double d = sa / n_a - sb / n_b;
                    const double e = d * d * n_a * n_b / (total * total);
                    mse += e;
                    relmse += e / ((m + 0.01) * (m + 0.01));
                    r.band_relmse[band] += e / ((m + 0.01) * (m + 0.01));
                    r.band_mse[band] += e;
                }
                band_values[band] += 1.0;
            }
            r.mean_spp += double(spp) / double(n);
        }
    }
    // A band of fewer than 2 samples has an empty half: no estimate (NaN), and then neither
    // has the image, rather than a zero error that would read as converged.
    bool estimated = true;
    for (std::size_t b = 0; b < band_values.size(); ++b) {
        if (layout.spp[b] < 2) {
            r.band_relmse[b] = r.band_mse[b] = std::nan("");
            estimated = false;
        } else if (band_values[b] > 0) {
            r.band_relmse[b] /= band_values[b], r.band_mse[b] /= band_values[b];
        }
    }
    const double none = std::nan("");
    r.estimate.mse = estimated ? mse / double(3 * n) : none;
    r.estimate.rmse = std::sqrt(r.estimate.mse);
    r.estimate.relmse = estimated ? relmse / double(3 * n) : none;
    return r;
}

std::vector<int> bands_above(const ResolvedBands& r, const BandLayout& layout, double threshold,
                             std::uint64_t max_spp) {
    std::vector<int> out;
    for (int b = 0; b < layout.bands(); ++b)
        if (!(r.band_relmse[std::size_t(b)] <= threshold) && layout.spp[std::size_t(b)] < max_spp) out.push_back(b);
    return out;
}

}  // namespace facet
