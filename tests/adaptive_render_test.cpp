// Per-tile adaptive sampling (render/session_tiles.hpp, render/adaptive_bands.hpp) on the
// Cornell box: bands of rows get different sample counts, each pixel is the mean of its
// own samples, so the image must be unbiased: its mean, and each band's, agree with a
// uniform render of many more samples within their noise (z-tests, the variance from
// the half-buffer estimates). Also: noisy bands get more samples than quiet ones, and
// resolving a uniform layout gives Renderer::image(). Suite AdaptiveRender (the render tier).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "host/bvh/bvh.hpp"
#include "host/render/device_group.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/render/session_tiles.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

Scene cornell(int spp) {
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    scene.settings.width = scene.settings.height = 32;
    scene.settings.spp = spp;
    return scene;
}

// The mean over a band of rows [y0, y1) and the variance of that mean (pixels and
// channels independent), from an image and its per-pixel variance estimate.
struct BandMean {
    double mean = 0.0, variance = 0.0;
};
BandMean band_mean(const std::vector<float>& rgb, double pixel_mse, int width, int y0, int y1) {
    BandMean b;
    const std::size_t begin = std::size_t(3 * width * y0), end = std::size_t(3 * width * y1);
    for (std::size_t i = begin; i < end; ++i) b.mean += double(rgb[i]);
    const double n = double(end - begin);
    b.mean /= n;
    b.variance = pixel_mse / n;
    return b;
}

TEST(AdaptiveRender, TilesAreUnbiasedAgainstAUniformRender) {
    // The uniform reference: 1024 samples.
    const Scene uniform_scene = cornell(1024);
    const Bvh bvh = build_bvh(uniform_scene.vertices);
    Renderer uniform(test::context(), uniform_scene, bvh);
    render_fixed(uniform, 1024, 256);
    const std::vector<float> reference = uniform.image();
    const Renderer::Halves h = uniform.halves();
    const double reference_mse = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]).mse;

    // Adaptive: 16 uniform samples, then bands doubled up to 256 while above the threshold.
    Scene scene = cornell(256);
    scene.settings.seed = 99;  // independent of the reference
    // Two contexts on the test device: each band's samples are dealt out between them.
    const char* device = std::getenv("FACET_TEST_DEVICE");
    std::vector<ClContext> two;
    for (int i = 0; i < 2; ++i) two.push_back(ClContext::create(device ? device : ""));
    DeviceGroup r(std::move(two), scene, bvh);
    render_fixed(r, 16);
    TileOptions opt;
    opt.threshold = 0.02;
    opt.max_spp = 256;
    const TileRun run = render_tiles(r, opt);
    ASSERT_GT(run.rounds, 0);
    const auto [lo, hi] = std::minmax_element(run.layout.spp.begin(), run.layout.spp.end());
    EXPECT_LT(*lo, *hi) << "the bands should end with different sample counts";
    EXPECT_EQ(*lo, 16u * (*lo / 16u));

    // The whole image and each band against the reference (band -1: the whole image).
    double worst = 0.0;
    for (int band = -1; band < run.layout.bands(); ++band) {
        const int y0 = band < 0 ? 0 : band * run.layout.band_rows;
        const int y1 = band < 0 ? 32 : std::min(32, y0 + run.layout.band_rows);
        const double mse = band < 0 ? run.image.estimate.mse : run.image.band_mse[std::size_t(band)];
        const BandMean a = band_mean(run.image.rgb, mse, 32, y0, y1);
        const BandMean b = band_mean(reference, reference_mse, 32, y0, y1);
        const double z = std::abs(a.mean - b.mean) / std::sqrt(a.variance + b.variance);
        worst = std::max(worst, z);
    }
    EXPECT_LT(worst, 4.5);
}

TEST(AdaptiveRender, UniformBandsResolveToTheRendererImage) {
    const Scene scene = cornell(8);
    Renderer r(test::context(), scene, build_bvh(scene.vertices));
    render_fixed(r, 8);
    BandLayout layout;
    layout.width = layout.height = 32;
    layout.spp.assign(std::size_t(layout.bands()), 8);
    const ResolvedBands resolved = resolve_bands(r.accumulation(), layout);
    const std::vector<float> image = r.image();
    ASSERT_EQ(resolved.rgb.size(), image.size());
    for (std::size_t i = 0; i < image.size(); ++i) ASSERT_NEAR(resolved.rgb[i], image[i], 1e-5f * (1 + image[i]));
    const Renderer::Halves h = r.halves();
    const ErrorMetrics e = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
    EXPECT_NEAR(resolved.estimate.mse, e.mse, 1e-6 * e.mse + 1e-12);
    EXPECT_DOUBLE_EQ(resolved.mean_spp, 8.0);
}

}  // namespace
}  // namespace facet
