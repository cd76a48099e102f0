// Per-tile adaptive sampling (--adaptive tiles): the image cut into bands of rows, each
// with its own sample count, as Cycles and LuxCore spend the remaining samples where the
// noise is (pbrt-v4 and Mitsuba 3 do not). Tiles are bands of whole rows because a
// launch covers rows (render/device_group.hpp: launch_band); a band's samples are
// [0, spp[band]) of each of its pixels, so its even and odd samples still form two
// independent half-images and the reference-free estimate (film/error_metrics.hpp) holds
// band by band. Pure functions on the accumulation buffer: no device.
#pragma once

#include <cstdint>
#include <vector>

#include "host/film/error_metrics.hpp"

namespace facet {

struct BandLayout {
    int width = 0, height = 0;
    int band_rows = 8;               // rows per band (the last may be shorter)
    std::vector<std::uint64_t> spp;  // samples per pixel of each band
    int bands() const { return (height + band_rows - 1) / band_rows; }
    int band_of_row(int y) const { return y / band_rows; }
};

struct ResolvedBands {
    std::vector<float> rgb;           // the mean of each pixel's own samples, 3 floats a pixel
    ErrorMetrics estimate;            // of the whole image, from the half-images
    std::vector<double> band_relmse;  // the estimate's relMSE, band by band (NaN below 2 spp)
    std::vector<double> band_mse;     // and its MSE (the variance of a pixel channel)
    double mean_spp = 0.0;            // samples per pixel over the image
};

// The image and the error estimate from the accumulation buffer (Renderer::accumulation:
// 2 * width * height RGBA sums, the even-sample half then the odd-sample half) of a render
// whose bands hold `layout.spp` samples.
ResolvedBands resolve_bands(const std::vector<float>& sums, const BandLayout& layout);

// The bands to sample further: relMSE above `threshold` or unknown (a band of fewer than 2
// samples has no estimate: NaN) and fewer than `max_spp` samples.
std::vector<int> bands_above(const ResolvedBands& r, const BandLayout& layout, double threshold, std::uint64_t max_spp);

}  // namespace facet
