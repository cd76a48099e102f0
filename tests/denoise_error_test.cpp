// The denoised image's error without a reference (host/denoise/denoise_error.hpp): for
// the identity "denoiser" it is the noisy image's half-buffer estimate; for facet's
// denoiser it tracks the true error, on synthetic halves with a known truth and on a
// rendered Cornell box against a long reference. Suite DenoiseError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "host/denoise/denoise_error.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/session.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/denoise_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

TEST(DenoiseError, IdentityDenoiserGivesTheNoisyEstimate) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    FilmHalves h;
    h.samples[0] = h.samples[1] = 4;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 300; ++i) h.rgb[k].push_back(u(rng));
    DenoisedImage d;
    d.half[0] = h.rgb[0], d.half[1] = h.rgb[1];
    d.rgb = film_mean(h);
    EXPECT_NEAR(estimate_denoised_error(h, d).mse, estimate_error(h.rgb[0], h.rgb[1], 4, 4).mse, 1e-9);
    h.samples[1] = 0;
    EXPECT_TRUE(std::isnan(estimate_denoised_error(h, d).mse));
}

// 256 x 256 pixels: a ramp under an albedo that changes from pixel to pixel (so that the
// guide keeps the denoiser to few neighbours, as texture does), noise of 0.2 in each
// half, the truth known exactly. The estimate's own noise is about sigma^2 / sqrt(3
// pixels) = 1e-4 (its per-pixel term is, to first order, the product of the halves'
// noises), a tenth of the error here.
TEST(DenoiseError, TracksTheTrueErrorOnSyntheticHalves) {
    constexpr std::uint32_t w = 256, h = 256;
    const std::size_t pixels = std::size_t(w) * h;
    std::mt19937 rng(17);
    std::normal_distribution<float> noise(0.0f, 0.2f);
    std::uniform_real_distribution<float> texture(0.2f, 0.8f);
    AovImages f;
    f.albedo.resize(3 * pixels), f.normal.assign(3 * pixels, 0.0f), f.depth.assign(pixels, 1.0f);
    std::vector<float> truth(3 * pixels);
    FilmHalves halves;
    halves.samples[0] = halves.samples[1] = 8;
    halves.rgb[0].resize(3 * pixels), halves.rgb[1].resize(3 * pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float albedo = texture(rng), shade = 0.5f + float(i % w) / float(w);
        f.normal[3 * i + 2] = 1.0f;
        for (std::size_t c = 0; c < 3; ++c) {
            f.albedo[3 * i + c] = albedo;
            truth[3 * i + c] = albedo * shade;
            for (int k = 0; k < 2; ++k) halves.rgb[k][3 * i + c] = truth[3 * i + c] + noise(rng);
        }
    }
    const DenoisedImage d = denoise(test::context(), w, h, halves, f);
    const double truth_mse = compare_images(d.rgb, truth).mse;
    const double estimate = estimate_denoised_error(halves, d).mse;
    const double noisy = compare_images(film_mean(halves), truth).mse;
    std::printf("synthetic: noisy mse %.3g, denoised mse %.3g, estimate %.3g\n", noisy, truth_mse, estimate);
    EXPECT_LT(truth_mse, noisy / 3.0) << "the denoiser removes most of the noise";
    EXPECT_NEAR(estimate, truth_mse, 0.2 * truth_mse);
}

// Halves of 2 samples each over 64 x 64 pixels: emitters of radiance 10 (squares of 8 x 8
// pixels, one every 16) on a background of 0.5 with noise of 0.3 a sample, and on each
// emitter's edge pixels that it covers by a quarter, a half or three quarters, where a
// sample sees the emitter or the background (the heavy-tailed noise of a light's edge at
// few samples). Flat features: the emitter's edge is kept by the colour alone, as the
// Cornell box's light. `truth` is the exact image.
FilmHalves emitter_edge_halves(unsigned seed, std::vector<float>& truth) {
    constexpr int kSide = 64, kSamples = 2;
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, 0.3f);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    FilmHalves h;
    h.samples[0] = h.samples[1] = kSamples;
    truth.assign(3 * kSide * kSide, 0.0f);
    for (int k = 0; k < 2; ++k) h.rgb[k].assign(3 * kSide * kSide, 0.0f), h.square[k].assign(kSide * kSide, 0.0f);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            // Inside an emitter: 4..11 of every 16 in x and y; its edge the ring around it
            const int ex = x % 16, ey = y % 16;
            const bool inside = ex >= 4 && ex < 12 && ey >= 4 && ey < 12;
            const bool ring = !inside && ex >= 3 && ex < 13 && ey >= 3 && ey < 13;
            const float cover = inside ? 1.0f : ring ? 0.25f * float(1 + (x + y) % 3) : 0.0f;
            const std::size_t i = std::size_t(y) * kSide + std::size_t(x);
            for (std::size_t c = 0; c < 3; ++c) truth[3 * i + c] = cover * 10.0f + (1.0f - cover) * 0.5f;
            for (int k = 0; k < 2; ++k)
                for (int s = 0; s < kSamples; ++s) {
                    const bool lit = u(rng) < cover;
                    float q = 0.0f;
                    for (std::size_t c = 0; c < 3; ++c) {
                        const float v = lit ? 10.0f : 0.5f + noise(rng);
                        h.rgb[k][3 * i + c] += v / kSamples;
                        q += v * v;
                    }
                    h.square[k][i] += q / kSamples;
                }
        }
    return h;
}

// The estimate needs each denoised half to read its own half alone. With the variance
// of the pair, E[(a - b)^2], the filter smooths a more where b strays, toward b, and the
// estimate reads low at an emitter's edge at few samples (here 0.77 of the truth,
// pooled over 8 renders; on the Cornell box at 4 spp 0.73 over 12); with each half's
// own variance (its second moments) it is unbiased to its noise.
TEST(DenoiseError, OwnVarianceKeepsTheEstimateUnbiasedAtAnEmitterEdge) {
    constexpr std::uint32_t kSide = 64;
    const AovImages f = test::flat_features(std::size_t(kSide) * kSide);
    const Denoiser denoiser(test::context());
    double truth[2] = {0.0, 0.0}, estimate[2] = {0.0, 0.0};  // pooled: own variance, the pair's
    for (unsigned seed = 0; seed < 8; ++seed) {
        std::vector<float> exact;
        FilmHalves h = emitter_edge_halves(seed, exact);
        for (int pair = 0; pair < 2; ++pair) {
            if (pair) h.square[0].clear(), h.square[1].clear();
            const DenoisedImage d = denoiser.run(kSide, kSide, h, f);
            ASSERT_EQ(d.own_variance, pair == 0);
            truth[pair] += compare_images(d.rgb, exact).mse;
            const double e = estimate_denoised_error(h, d).mse;
            estimate[pair] += std::isnan(e) ? 0.0 : e;
        }
    }
    std::printf("emitter edge: own variance estimate / true %.3f (%.3g / %.3g), pair's %.3f (%.3g / %.3g)\n",
                estimate[0] / truth[0], estimate[0], truth[0], estimate[1] / truth[1], estimate[1], truth[1]);
    EXPECT_NEAR(estimate[0] / truth[0], 1.0, 0.12);
    EXPECT_LT(estimate[1] / truth[1], 0.85) << "the pair's variance no longer biases the estimate: say so in the docs";
}

SessionOptions on_test_device(std::uint64_t spp) {
    SessionOptions opt;
    if (const char* device = std::getenv("FACET_TEST_DEVICE")) opt.device = device;
    opt.stop.spp = spp;
    opt.denoise = true;
    return opt;
}

// The Cornell box at 96 x 96 and 64 spp against 512 spp of another seed: the true
// error of the denoised image is its MSE against the reference less the reference's own
// variance (its half-buffer estimate). The half-buffer estimate of the denoised error is
// within 25 % of it (measured: -9 %; at 16 spp +23 %). At 8 spp both this estimate and
// the noisy image's run low, by 66 % and 45 % (docs/denoising.md).
TEST(DenoiseError, TracksTheTrueErrorOnTheCornellBox) {
    const std::uint64_t spp = 64;
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    scene.settings.width = scene.settings.height = 96;
    Scene other_seed = scene;  // the reference's samples are not the render's
    other_seed.settings.seed = scene.settings.seed + 1000;
    RenderSession reference(other_seed, on_test_device(512));
    reference.run({});
    const FilmState rf = reference.film();
    const FilmHalves rh = film_halves(rf);
    const double reference_var = estimate_error(rh.rgb[0], rh.rgb[1], rh.samples[0], rh.samples[1]).mse;
    const std::vector<float> ref = reference.image();

    RenderSession session(scene, on_test_device(spp));
    session.run({});
    const FilmState film = session.film();
    const FilmHalves halves = film_halves(film);
    const DenoisedImage d = session.denoised();
    const double truth_mse = compare_images(d.rgb, ref).mse - reference_var;
    const double estimate = estimate_denoised_error(halves, d).mse;
    const double noisy = compare_images(session.image(), ref).mse - reference_var;
    const double noisy_estimate =
        estimate_error(halves.rgb[0], halves.rgb[1], halves.samples[0], halves.samples[1]).mse;
    std::printf(
        "cornell %d spp: noisy mse %.3g (estimate %.3g), denoised mse %.3g (estimate %.3g), reference variance %.3g\n",
        int(spp), noisy, noisy_estimate, truth_mse, estimate, reference_var);
    EXPECT_LT(truth_mse, noisy / 2.0) << "the denoiser removes most of the noise";
    EXPECT_NEAR(estimate, truth_mse, 0.25 * truth_mse);
}

}  // namespace
}  // namespace facet
