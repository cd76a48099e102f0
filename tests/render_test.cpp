// Whole-renderer tests on the real kernels: an analytic furnace and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>

#include "host/bvh/bvh.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/cl_test_env.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "tests/bvh_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

// The camera at the centre of a closed sphere whose inside is Lambertian with albedo
// a and emits radiance e. Every path sees L = e + a L, so L = e / (1 - a).
Scene furnace_scene(float albedo, float emission, int size, int spp) {
    Scene scene;
    Material m = default_material();
    for (int c = 0; c < 3; ++c) {
        m.diffuse[c] = albedo;
        m.emission[c] = emission;
    }
    scene.materials.push_back(m);
    scene.material_names.push_back("furnace");
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 3, 0, /*inward=*/true);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fov_y_degrees = 90.0f;
    scene.settings.width = size;
    scene.settings.height = size;
    scene.settings.spp = spp;
    scene.settings.max_depth = 1024;
    return scene;
}

std::vector<float> render(const Scene& scene, std::uint32_t spp, std::uint32_t pass, double* rejected = nullptr) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp, pass);
    return r.image(rejected);
}

TEST(Render, AnalyticFurnace) {
    Scene scene = furnace_scene(0.5f, 0.5f, 48, 48);
    double rejected = -1.0;
    std::vector<float> img = render(scene, 48, 16, &rejected);
    EXPECT_EQ(rejected, 0.0);
    double sum = 0.0;
    for (float v : img) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
        sum += double(v);
    }
    double mean = sum / double(img.size());
    EXPECT_NEAR(mean, 1.0, 0.01) << "L = e / (1 - a) = 1";
}

TEST(Render, FurnaceDirectLightOnly) {
    // With one bounce, L = e + a e = 0.75 exactly in expectation.
    Scene scene = furnace_scene(0.5f, 0.5f, 32, 32);
    scene.settings.max_depth = 1;
    std::vector<float> img = render(scene, 32, 32);
    double mean = std::accumulate(img.begin(), img.end(), 0.0) / double(img.size());
    EXPECT_NEAR(mean, 0.75, 0.0075);
}

// Russian roulette's gain (RenderSettings::roulette_gain): a path goes on with probability
// min(gain max(throughput), 0.95), so any gain keeps the furnace's mean, and a higher one keeps
// more paths and lowers each pixel's noise. Roulette from the first bounce, where the furnace's
// albedo 0.8 makes gain 1 kill a fifth of the paths at every bounce.
TEST(Render, RouletteGainKeepsTheMeanAndLowersTheNoise) {
    double rms[2] = {0.0, 0.0};
    const float gains[2] = {1.0f, 4.0f};
    for (int g = 0; g < 2; ++g) {
        Scene scene = furnace_scene(0.8f, 0.2f, 16, 64);
        scene.settings.rr_depth = 0;
        scene.settings.roulette_gain = gains[g];
        scene.settings.sampler = FC_SAMPLER_INDEPENDENT;
        double rejected = -1.0;
        std::vector<float> img = render(scene, 64, 16, &rejected);
        EXPECT_EQ(rejected, 0.0);
        double sum = 0.0;
        for (float v : img) {
            sum += double(v);
            rms[g] += (double(v) - 1.0) * (double(v) - 1.0);
        }
        rms[g] = std::sqrt(rms[g] / double(img.size()));
        std::printf("[ roulette ] gain %g: mean %.4f, rms error %.4f\n", double(gains[g]), sum / double(img.size()),
                    rms[g]);
        EXPECT_NEAR(sum / double(img.size()), 1.0, 0.02) << "gain " << gains[g] << ": L = e / (1 - a) = 1";
    }
    EXPECT_LT(rms[1], 0.8 * rms[0]) << "a higher gain keeps more paths";
}

TEST(Render, SameSeedIsBitIdentical) {
    Scene scene = furnace_scene(0.7f, 0.3f, 24, 8);
    std::vector<float> a = render(scene, 8, 4);
    std::vector<float> b = render(scene, 8, 4);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
    scene.settings.seed = 12345;
    std::vector<float> c = render(scene, 8, 4);
    EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(float))) << "the seed must change the image";
}

TEST(Render, PassSplitDoesNotChangeSamples) {
    // The random stream depends on (seed, pixel, sample) only: 8 samples in one pass or
    // in four passes differ only by float summation order.
    Scene scene = furnace_scene(0.7f, 0.3f, 24, 8);
    std::vector<float> one = render(scene, 8, 8);
    std::vector<float> four = render(scene, 8, 2);
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_NEAR(one[i], four[i], 1e-5f * std::max(1.0f, one[i])) << i;
}

// Every node layout traces the same hits (quantised boxes contain the float ones and the
// leaves are the same), so a scene renders to the same image bit for bit whichever the
// session picks: small trees take float boxes, large ones quantised (kQuantiseAboveTriangles),
// and the demo scenes' render programs would otherwise no longer run the quantised decode.
TEST(Render, EveryNodeLayoutGivesTheSameImage) {
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    scene.settings.width = 40;
    scene.settings.height = 40;
    std::vector<std::vector<float>> images;
    using bvh_test::kLayouts;
    for (const bvh_test::Layout& layout : kLayouts) {
        Bvh bvh = build_bvh(scene.vertices, bvh_test::with_layout({}, layout));
        ASSERT_EQ(bvh.stats.quantised, layout.quantised) << layout.name;
        Renderer r(test::context(), scene, bvh);
        render_fixed(r, 8, 8);
        images.push_back(r.image());
    }
    for (std::size_t k = 1; k < images.size(); ++k) {
        ASSERT_EQ(images[k].size(), images[0].size());
        EXPECT_EQ(0, std::memcmp(images[k].data(), images[0].data(), images[0].size() * sizeof(float)))
            << kLayouts[k].name << " against " << kLayouts[0].name;
    }
}

}  // namespace
}  // namespace facet
