// facet's denoiser on the real kernels (kernels/denoise/denoise.cl through
// host/denoise/denoiser.hpp), on synthetic half-images with known truth: a constant image
// comes out exactly; white noise on a flat albedo falls to the variance of the window's
// mean; a step in albedo or in normal that the colour alone cannot tell from the noise
// stays sharp with the feature guides and blurs without them; the offset-wise kernels give
// what the filter written directly gives (kernels/test/denoise_direct_kernels.cl). Suite
// Denoiser.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "host/denoise/denoiser.hpp"
#include "host/error.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/denoise_test_util.hpp"

namespace facet {
namespace {

constexpr std::uint32_t kWidth = 32, kHeight = 64;
constexpr std::size_t kPixels = std::size_t(kWidth) * kHeight;

AovImages flat_features() { return test::flat_features(kPixels); }

// Two halves of `spp_half` samples each: truth(x, y) plus Gaussian noise of standard
// deviation `sigma` in every channel, independent between the halves.
template <typename Truth>
FilmHalves noisy_halves(Truth truth, float sigma, std::uint64_t spp_half, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    FilmHalves h;
    h.samples[0] = h.samples[1] = spp_half;
    for (int k = 0; k < 2; ++k) {
        h.rgb[k].resize(3 * kPixels);
        for (std::size_t i = 0; i < kPixels; ++i)
            for (int c = 0; c < 3; ++c)
                h.rgb[k][3 * i + std::size_t(c)] =
                    truth(std::uint32_t(i % kWidth)) + (sigma > 0.0f ? noise(rng) : 0.0f);
    }
    return h;
}

// The mean over the rows of column x of the denoised image's first channel.
double column_mean(const std::vector<float>& rgb, std::uint32_t x) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y < kHeight; ++y) sum += double(rgb[3 * (std::size_t(y) * kWidth + x)]);
    return sum / kHeight;
}

TEST(Denoiser, ConstantImageIsKeptExactly) {
    FilmHalves h;
    h.samples[0] = h.samples[1] = 4;
    for (int k = 0; k < 2; ++k) {
        h.rgb[k].resize(3 * kPixels);
        for (std::size_t i = 0; i < kPixels; ++i)
            h.rgb[k][3 * i] = 0.3f, h.rgb[k][3 * i + 1] = 0.7f, h.rgb[k][3 * i + 2] = 1.9f;
    }
    // Features that vary from pixel to pixel change the weights, never the result
    AovImages f = flat_features();
    for (std::size_t i = 0; i < kPixels; ++i) f.albedo[3 * i] = float(i % 7) * 0.1f, f.depth[i] = 1.0f + float(i % 5);
    const DenoisedImage d = denoise(test::context(), kWidth, kHeight, h, f);
    for (std::size_t i = 0; i < kPixels; ++i) {
        ASSERT_EQ(d.rgb[3 * i], 0.3f) << "pixel " << i;
        ASSERT_EQ(d.rgb[3 * i + 1], 0.7f) << "pixel " << i;
        ASSERT_EQ(d.rgb[3 * i + 2], 1.9f) << "pixel " << i;
    }
}

// Each half: 0.5 plus noise of sigma 0.2. Away from the border the window holds
// N = (2 radius + 1)^2 pixels of equal features, so a filter that weighs them evenly
// leaves sigma^2 / N in a half; the colour term weighs some neighbours less, which
// leaves a little more, at most 1.5x.
TEST(Denoiser, WhiteNoiseOnFlatAlbedoFallsToTheWindowVariance) {
    const float sigma = 0.2f;
    const FilmHalves h = noisy_halves([](std::uint32_t) { return 0.5f; }, sigma, 8, 11);
    const DenoiseSettings s;
    const DenoisedImage d = denoise(test::context(), kWidth, kHeight, h, flat_features(), s);
    const int r = int(s.radius);
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = r; y < int(kHeight) - r; ++y)
        for (int x = r; x < int(kWidth) - r; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = double(d.half[0][3 * (std::size_t(y) * kWidth + std::size_t(x)) + std::size_t(c)]);
                sum += v, sum2 += v * v, ++n;
            }
    const double mean = sum / n, var = sum2 / n - mean * mean;
    const double window = double((2 * r + 1) * (2 * r + 1));
    const double expected = double(sigma) * double(sigma) / window;
    EXPECT_NEAR(mean, 0.5, 0.01);
    EXPECT_GT(var, 0.8 * expected) << "expected about " << expected;
    EXPECT_LT(var, 1.5 * expected) << "expected about " << expected;
}

// A step of 0.3 under noise of 0.5 a pixel: the colour term alone weighs the other
// side at about exp(-0.3^2 / (k^2 2 0.5^2)) ~ 0.7, so the columns beside the step are
// pulled about 0.1 toward the other side; a feature guide that sees the step cuts the
// other side off.
void expect_step_kept(const AovImages& features, std::uint32_t guide) {
    auto truth = [](std::uint32_t x) { return x < kWidth / 2 ? 0.2f : 0.5f; };
    const FilmHalves h = noisy_halves(truth, 0.5f, 8, 23);
    DenoiseSettings with;
    const DenoisedImage sharp = denoise(test::context(), kWidth, kHeight, h, features, with);
    DenoiseSettings without;
    without.guides = FC_DENOISE_GUIDE_ALL & ~guide;
    const DenoisedImage blurred = denoise(test::context(), kWidth, kHeight, h, features, without);
    for (std::uint32_t x : {kWidth / 2 - 1, kWidth / 2}) {
        EXPECT_NEAR(column_mean(sharp.rgb, x), double(truth(x)), 0.03) << "column " << x << " with the guide";
        EXPECT_GT(std::abs(column_mean(blurred.rgb, x) - double(truth(x))), 0.06)
            << "column " << x << " without the guide";
    }
}

TEST(Denoiser, AlbedoStepStaysSharp) {
    AovImages f = flat_features();
    for (std::size_t i = 0; i < kPixels; ++i)
        if (i % kWidth < kWidth / 2)
            for (int c = 0; c < 3; ++c) f.albedo[3 * i + std::size_t(c)] = 0.2f;
    expect_step_kept(f, FC_DENOISE_GUIDE_ALBEDO);
}

TEST(Denoiser, NormalStepStaysSharp) {
    AovImages f = flat_features();
    for (std::size_t i = 0; i < kPixels; ++i)
        if (i % kWidth < kWidth / 2) f.normal[3 * i + 1] = 1.0f, f.normal[3 * i + 2] = 0.0f;
    expect_step_kept(f, FC_DENOISE_GUIDE_NORMAL);
}

TEST(Denoiser, DepthStepStaysSharp) {
    AovImages f = flat_features();
    for (std::size_t i = 0; i < kPixels; ++i)
        if (i % kWidth < kWidth / 2) f.depth[i] = 2.0f;
    expect_step_kept(f, FC_DENOISE_GUIDE_DEPTH);
}

// The filter written directly (every pixel's window, every patch, the variance box in one
// piece) on the colours and features of the planes that denoise_prepare makes: half k of
// `h`, 3 floats a pixel.
std::vector<float> denoise_directly(std::uint32_t width, std::uint32_t height, const FilmHalves& h, const AovImages& f,
                                    const DenoiseSettings& s, cl_uint k) {
    ClContext& ctx = test::context();
    const std::size_t pixels = std::size_t(width) * height;
    const DenoiseVariance variance = denoise_variance(width, height, h);
    FcDenoiseParams p = denoise_params(width, height, variance, s);
    auto in = [&](const std::vector<float>& v) {
        return cl::Buffer(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(float),
                          const_cast<float*>(v.data()));
    };
    auto scratch = [&](std::size_t floats) {
        return cl::Buffer(ctx.context(), CL_MEM_READ_WRITE, floats * sizeof(float));
    };
    cl::Buffer params(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof p, &p);
    cl::Buffer a = in(h.rgb[0]), b = in(h.rgb[1]), albedo = in(f.albedo), normal = in(f.normal), depth = in(f.depth);
    cl::Buffer colour = scratch(8 * std::size_t(p.plane)), features = scratch(7 * std::size_t(p.plane));
    cl::Buffer source = in(variance.source), rows = scratch(2 * pixels), out = scratch(3 * pixels);
    cl::Program& program = test::program("kernels/test/denoise_direct_kernels.cl");
    cl::Kernel variance_rows(program, "denoise_variance_rows"), prepare(program, "denoise_prepare");
    cl::Kernel direct(program, "denoise_direct");
    variance_rows.setArg(0, params), variance_rows.setArg(1, source), variance_rows.setArg(2, rows);
    ctx.queue().enqueueNDRangeKernel(variance_rows, cl::NullRange, cl::NDRange(2 * pixels));
    prepare.setArg(0, params), prepare.setArg(1, a), prepare.setArg(2, b), prepare.setArg(3, rows);
    prepare.setArg(4, albedo), prepare.setArg(5, normal), prepare.setArg(6, depth), prepare.setArg(7, colour);
    prepare.setArg(8, features);
    ctx.queue().enqueueNDRangeKernel(prepare, cl::NullRange, cl::NDRange(p.plane));
    direct.setArg(0, params), direct.setArg(1, colour), direct.setArg(2, features), direct.setArg(3, source);
    direct.setArg(4, k), direct.setArg(5, out);
    ctx.queue().enqueueNDRangeKernel(direct, cl::NullRange, cl::NDRange(pixels));
    std::vector<float> result(3 * pixels);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, result.size() * sizeof(float), result.data());
    return result;
}

// On an image smaller than some windows (19 x 13, radius 6), with noise, a varying
// variance, textured features and patches of radius 1 and 2 (the written-out 3 x 3 box
// and the loop), both halves of the offset-wise filter with its separable variance box
// agree with the direct one to float rounding, with the pair's variance and with each
// half's own (second moments given).
TEST(Denoiser, OffsetWiseFilterEqualsTheDirectOne) {
    constexpr std::uint32_t w = 19, h = 13;
    constexpr std::size_t pixels = std::size_t(w) * h;
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    FilmHalves halves;
    halves.samples[0] = 5, halves.samples[1] = 3;
    AovImages f = test::flat_features(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float truth = (i % w) < 9 ? 0.3f : 0.8f, sigma = 0.05f + 0.3f * float(i / w) / float(h);
        for (int k = 0; k < 2; ++k)
            for (int c = 0; c < 3; ++c) halves.rgb[k].push_back(truth + sigma * noise(rng));
        f.albedo[3 * i] = (i % w) < 9 ? 0.2f : 0.6f, f.normal[3 * i] = 0.3f * float(i % 3);
        f.depth[i] = 1.0f + 0.5f * float((i / w) % 4);
    }
    FilmHalves own = halves;  // second moments: the means' squares plus a varying spread
    std::uniform_real_distribution<float> spread(0.0f, 0.5f);
    for (int k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < pixels; ++i) {
            float q = spread(rng);
            for (std::size_t c = 0; c < 3; ++c) q += own.rgb[k][3 * i + c] * own.rgb[k][3 * i + c];
            own.square[k].push_back(q);
        }
    ASSERT_FALSE(denoise_variance(w, h, halves).own);
    ASSERT_TRUE(denoise_variance(w, h, own).own);
    const Denoiser denoiser(test::context());  // built once, run for both patch sizes
    for (const FilmHalves* input : {&halves, &own})
        for (std::uint32_t patch : {1u, 2u}) {
            DenoiseSettings s;
            s.patch_radius = patch;
            s.sigma_depth = 0.3f;  // depth weights neither 0 nor 1
            const DenoisedImage d = denoiser.run(w, h, *input, f, s);
            EXPECT_EQ(d.own_variance, input == &own);
            for (int k = 0; k < 2; ++k) {
                const std::vector<float> direct = denoise_directly(w, h, *input, f, s, cl_uint(k));
                for (std::size_t i = 0; i < 3 * pixels; ++i)
                    ASSERT_NEAR(d.half[k][i], direct[i], 1e-5f) << "half " << k << ", value " << i << ", patch "
                                                                << patch << ", own variance " << d.own_variance;
            }
        }
}

// A Denoiser (one program build) run on one image and then on another of another size
// gives the second exactly what a denoiser built for it alone gives.
TEST(Denoiser, ReusedOnAnotherImageGivesTheOneShotResult) {
    const Denoiser denoiser(test::context());
    const FilmHalves first = noisy_halves([](std::uint32_t x) { return x < kWidth / 2 ? 0.2f : 0.7f; }, 0.1f, 4, 4);
    denoiser.run(kWidth, kHeight, first, flat_features());
    constexpr std::uint32_t w = 11, h = 7;
    std::mt19937 rng(9);
    std::normal_distribution<float> noise(0.0f, 0.2f);
    FilmHalves second;
    second.samples[0] = second.samples[1] = 2;
    for (int k = 0; k < 2; ++k)
        for (std::uint32_t i = 0; i < 3 * w * h; ++i) second.rgb[k].push_back(0.5f + noise(rng));
    const AovImages f = test::flat_features(std::size_t(w) * h);
    const DenoisedImage reused = denoiser.run(w, h, second, f), alone = denoise(test::context(), w, h, second, f);
    EXPECT_EQ(reused.rgb, alone.rgb);
    EXPECT_EQ(reused.half[1], alone.half[1]);
}

TEST(Denoiser, HalfWithoutSamplesIsRefused) {
    FilmHalves h = noisy_halves([](std::uint32_t) { return 0.5f; }, 0.0f, 1, 1);
    h.samples[1] = 0;
    EXPECT_THROW(denoise(test::context(), kWidth, kHeight, h, flat_features()), Error);
}

}  // namespace
}  // namespace facet
