// The variance facet's denoiser reads (host/denoise/denoise_variance.hpp): from second
// moments, each half's own, which the other half changes only through the calibration
// over a box around the pixel; from independent samples, the variance of the half's
// mean; without second moments, or with a single sample in a half, the pair's. Suite
// DenoiseVariance.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "host/denoise/denoise_variance.hpp"

namespace facet {
namespace {

constexpr std::size_t kSide = 64, kPixels = kSide * kSide;

// Halves of `n` independent samples each, every channel of every sample Gaussian of
// mean 1 and standard deviation `sigma`, with their second moments.
FilmHalves iid_halves(std::uint64_t n, float sigma, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> sample(1.0f, sigma);
    FilmHalves h;
    h.samples[0] = h.samples[1] = n;
    for (int k = 0; k < 2; ++k) {
        h.rgb[k].assign(3 * kPixels, 0.0f), h.square[k].assign(kPixels, 0.0f);
        for (std::size_t i = 0; i < kPixels; ++i)
            for (std::uint64_t s = 0; s < n; ++s)
                for (std::size_t c = 0; c < 3; ++c) {
                    const float v = sample(rng);
                    h.rgb[k][3 * i + c] += v / float(n);
                    h.square[k][i] += v * v / float(n);
                }
    }
    return h;
}

// The variance the kernel reads at pixel i of half k (its box aside): scale * source / 3.
double variance_at(const DenoiseVariance& v, int k, std::size_t i) {
    return double(v.scale[k]) * double(v.source[std::size_t(k) * kPixels + i]) / 3.0;
}

TEST(DenoiseVariance, OwnVarianceIsTheVarianceOfTheHalfMean) {
    const float sigma = 0.4f;
    const FilmHalves h = iid_halves(4, sigma, 3);
    const DenoiseVariance v = denoise_variance(kSide, kSide, h);
    ASSERT_TRUE(v.own);
    double rho = 0.0;
    for (float r : v.rho) rho += double(r) / double(kPixels);
    EXPECT_NEAR(rho, 1.0, 0.03);  // independent samples: the sample variance is right
    for (int k = 0; k < 2; ++k) {
        double mean = 0.0;
        for (std::size_t i = 0; i < kPixels; ++i) mean += variance_at(v, k, i) / double(kPixels);
        EXPECT_NEAR(mean, double(sigma * sigma) / 4.0, 0.03 * double(sigma * sigma) / 4.0) << "half " << k;
    }
}

TEST(DenoiseVariance, OwnVarianceReadsTheOtherHalfOnlyThroughTheCalibration) {
    const FilmHalves h = iid_halves(2, 0.3f, 5);
    FilmHalves strayed = h;  // half b strays far at pixel (40, 20)
    const std::size_t at = 20 * kSide + 40;
    for (std::size_t c = 0; c < 3; ++c) strayed.rgb[1][3 * at + c] = 40.0f;
    strayed.square[1][at] = 3.0f * 40.0f * 40.0f + 50.0f;
    const DenoiseVariance v = denoise_variance(kSide, kSide, h), s = denoise_variance(kSide, kSide, strayed);
    ASSERT_TRUE(v.own && s.own);
    int changed = 0;
    for (std::size_t i = 0; i < kPixels; ++i) {
        // Half a's spread (its source without the calibration) is its own
        ASSERT_FLOAT_EQ(v.source[i] / v.rho[i], s.source[i] / s.rho[i]) << "pixel " << i;
        // and the calibration moves only within its box around the strayed pixel
        const std::size_t dx = i % kSide > 40 ? i % kSide - 40 : 40 - i % kSide;
        const std::size_t dy = i / kSide > 20 ? i / kSide - 20 : 20 - i / kSide;
        if (std::max(dx, dy) > kCalibrationRadius) ASSERT_EQ(v.rho[i], s.rho[i]) << "pixel " << i;
        else changed += v.rho[i] != s.rho[i];
    }
    EXPECT_GT(changed, 0);
    EXPECT_NE(v.source[kPixels + at], s.source[kPixels + at]);  // half b's own changed
}

TEST(DenoiseVariance, PairVarianceWithoutSecondMomentsOrSamples) {
    FilmHalves h = iid_halves(3, 0.3f, 7);
    h.samples[1] = 1;  // as if b held one sample: its own variance is unknown
    DenoiseVariance v = denoise_variance(kSide, kSide, h);
    EXPECT_FALSE(v.own);
    h.samples[1] = 3;
    h.square[0].clear(), h.square[1].clear();
    v = denoise_variance(kSide, kSide, h);
    EXPECT_FALSE(v.own);
    EXPECT_FLOAT_EQ(v.scale[0], 0.5f);  // n_b / n
    EXPECT_FLOAT_EQ(v.scale[1], 0.5f);
    for (std::size_t i : {std::size_t(0), std::size_t(77)}) {
        double d2 = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = double(h.rgb[0][3 * i + c]) - double(h.rgb[1][3 * i + c]);
            d2 += d * d;
        }
        EXPECT_NEAR(v.source[i], d2, 1e-5);
        EXPECT_EQ(v.source[i], v.source[kPixels + i]);
    }
}

}  // namespace
}  // namespace facet
