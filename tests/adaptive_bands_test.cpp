// render/adaptive_bands.hpp on hand-made accumulation buffers: each band's pixels are
// divided by their own sample counts, the half-buffer estimate is computed band by band,
// and the bands above the threshold (and below the sample limit) are the ones chosen.
#include <gtest/gtest.h>

#include <cmath>

#include "host/film/film_layout.hpp"
#include "host/error.hpp"
#include "host/render/adaptive_bands.hpp"

namespace facet {
namespace {

// A 2x4 image in bands of 2 rows; band 0 with 4 samples, band 1 with 16. Every sample of
// a pixel is `even` (even indices) or `odd` (odd indices).
std::vector<float> sums_for(const BandLayout& l, float even, float odd) {
    const std::size_t n = std::size_t(l.width * l.height);
    std::vector<float> s(film_floats(n), 0.0f);
    for (std::size_t p = 0; p < n; ++p) {
        const std::uint64_t spp = l.spp[std::size_t(l.band_of_row(int(p) / l.width))];
        for (int c = 0; c < 3; ++c) {
            s[4 * p + std::size_t(c)] = even * float((spp + 1) / 2);
            s[4 * (n + p) + std::size_t(c)] = odd * float(spp / 2);
        }
    }
    return s;
}

BandLayout layout() {
    BandLayout l;
    l.width = 2;
    l.height = 4;
    l.band_rows = 2;
    l.spp = {4, 16};
    return l;
}

TEST(AdaptiveBands, EachBandIsTheMeanOfItsOwnSamples) {
    const BandLayout l = layout();
    const ResolvedBands r = resolve_bands(sums_for(l, 1.0f, 3.0f), l);
    for (float v : r.rgb) EXPECT_FLOAT_EQ(v, 2.0f);
    EXPECT_DOUBLE_EQ(r.mean_spp, 10.0);
    // (a - b)^2 n_a n_b / n^2 = 4 * (n/2)^2 / n^2 = 1 in every band, whatever its count.
    EXPECT_NEAR(r.estimate.mse, 1.0, 1e-12);
    ASSERT_EQ(r.band_mse.size(), 2u);
    EXPECT_NEAR(r.band_mse[0], 1.0, 1e-12);
    EXPECT_NEAR(r.band_relmse[1], 1.0 / (2.01 * 2.01), 1e-12);
}

TEST(AdaptiveBands, ChoosesNoisyBandsBelowTheLimit) {
    BandLayout l = layout();
    ResolvedBands r = resolve_bands(sums_for(l, 1.0f, 3.0f), l);
    r.band_relmse = {0.5, 0.01};
    EXPECT_EQ(bands_above(r, l, 0.1, 1024), std::vector<int>{0});
    EXPECT_TRUE(bands_above(r, l, 0.1, 4).empty()) << "band 0 is at the sample limit";
    EXPECT_EQ(bands_above(r, l, 0.001, 1024), (std::vector<int>{0, 1}));
}

// A band of 1 sample has an empty half: its estimate and the image's are unknown (NaN),
// not 0 (which read as "threshold reached" at --spp 1), and it is sampled further while
// below the limit.
TEST(AdaptiveBands, OneSampleHasNoEstimate) {
    BandLayout l = layout();
    l.spp = {1, 16};
    const ResolvedBands r = resolve_bands(sums_for(l, 1.0f, 3.0f), l);
    EXPECT_TRUE(std::isnan(r.band_relmse[0]));
    EXPECT_FALSE(std::isnan(r.band_relmse[1]));
    EXPECT_TRUE(std::isnan(r.estimate.relmse));
    EXPECT_EQ(bands_above(r, l, 10.0, 1024), std::vector<int>{0});
    EXPECT_TRUE(bands_above(r, l, 10.0, 1).empty()) << "band 0 is at the sample limit";
}

TEST(AdaptiveBands, RefusesAMismatchedBuffer) {
    const BandLayout l = layout();
    EXPECT_THROW(resolve_bands(std::vector<float>(7), l), Error);
}

}  // namespace
}  // namespace facet
