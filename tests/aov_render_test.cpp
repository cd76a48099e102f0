// The AOV pass (kernels/aov/aov.cl, host/render/aov.hpp): a Lambertian quad seen head-on
// by an orthographic camera gives its reflectance as the albedo, its normal facing the
// camera and its distance as the depth; pixels that see nothing hold 0; the pixel filter
// blends the AOVs at an edge as it blends the image. Suite AovRender (the render tier).
#include <gtest/gtest.h>

#include <cmath>

#include "host/bvh/bvh.hpp"
#include "host/render/aov.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr int kSize = 16;

// An orthographic camera 5 units above z = 0 looking down -z over [-2, 2]^2; a quad of
// reflectance (0.2, 0.5, 0.7) over x in [-2, right] (by default the image's left half).
Scene quad_scene(float right = 0.0f) {
    Scene scene;
    Material m = default_material();
    m.diffuse = glm::vec3(0.2f, 0.5f, 0.7f);
    add_material(scene, m, "paint");
    add_quad(scene, glm::vec3(-2.0f, -2.0f, 0.0f), glm::vec3(2.0f + right, 0.0f, 0.0f), glm::vec3(0.0f, 4.0f, 0.0f), 0);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.ortho_height = 4.0f;
    scene.settings.width = scene.settings.height = kSize;
    return scene;
}

TEST(AovRender, LambertianQuadAlbedoNormalDepth) {
    const Scene scene = quad_scene();
    const AovImages a = render_aovs(test::context(), scene, build_bvh(scene.vertices), 16);
    ASSERT_EQ(a.albedo.size(), std::size_t(3 * kSize * kSize));
    ASSERT_EQ(a.depth.size(), std::size_t(kSize * kSize));
    for (int y = 0; y < kSize; ++y) {
        const std::size_t on = std::size_t(y) * kSize + 3, off = std::size_t(y) * kSize + 12;
        EXPECT_NEAR(a.albedo[3 * on + 0], 0.2f, 1e-5f);
        EXPECT_NEAR(a.albedo[3 * on + 1], 0.5f, 1e-5f);
        EXPECT_NEAR(a.albedo[3 * on + 2], 0.7f, 1e-5f);
        EXPECT_NEAR(a.normal[3 * on + 2], 1.0f, 1e-5f);
        EXPECT_NEAR(a.normal[3 * on + 0], 0.0f, 1e-5f);
        EXPECT_NEAR(a.depth[on], 5.0f, 1e-4f);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a.albedo[3 * off + std::size_t(c)], 0.0f);
        EXPECT_EQ(a.depth[off], 0.0f);
    }
    // The column on the quad's edge (x = 0 between columns 7 and 8) is covered by the box
    // filter of column 7 only.
    EXPECT_NEAR(a.albedo[3 * (std::size_t(8) * kSize + 7)], 0.2f, 1e-5f);
    EXPECT_EQ(a.albedo[3 * (std::size_t(8) * kSize + 8)], 0.0f);
}

TEST(AovRender, TentFilterBlendsTheEdge) {
    Scene scene = quad_scene();
    scene.settings.filter = FC_FILTER_TENT;
    const AovImages a = render_aovs(test::context(), scene, build_bvh(scene.vertices), 256);
    // Column 7's centre is half a pixel left of the edge: a tent of radius 1 sees the quad
    // with weight 1 - 0.5^2 / 2 = 0.875 (column 8, mirrored: 0.125).
    double left = 0.0, right = 0.0;
    for (int y = 0; y < kSize; ++y) {
        left += double(a.albedo[3 * (std::size_t(y) * kSize + 7)]) / kSize;
        right += double(a.albedo[3 * (std::size_t(y) * kSize + 8)]) / kSize;
    }
    EXPECT_NEAR(left, 0.2 * 0.875, 0.005);
    EXPECT_NEAR(right, 0.2 * 0.125, 0.005);
}

// glTF's metallic mix (kernels/bsdf/metallic.cl): the albedo is (1 - M) times the
// dielectric's (base + F0 0.04 head-on) plus M times the metal's (F = base head-on), here
// base + 0.02 at M = 0.5. The albedo had left the mix out and read base + 0.04, the
// dielectric's alone (issue 28).
TEST(AovRender, MetallicMixAlbedo) {
    Scene scene = quad_scene();
    Material& m = scene.materials[0];
    m.specular_model = FC_SPECULAR_MICROFACET;  // GGX, Schlick's Fresnel, as glTF's reader sets it
    set_metallic_roughness(m, glm::vec3(0.2f, 0.5f, 0.7f), 0.5f, 0.04f);
    const AovImages a = render_aovs(test::context(), scene, build_bvh(scene.vertices), 4);
    const std::size_t on = std::size_t(8) * kSize + 3;
    EXPECT_NEAR(a.albedo[3 * on + 0], 0.22f, 1e-4f);
    EXPECT_NEAR(a.albedo[3 * on + 1], 0.52f, 1e-4f);
    EXPECT_NEAR(a.albedo[3 * on + 2], 0.72f, 1e-4f);
}

// A clearcoat (weight 1, a mirror coat) over the same dielectric seen head-on: the coat's
// albedo 0.04 plus the rest, 0.96, of the base's (0.2, 0.5, 0.7) + 0.04, as the BRDF layers them.
TEST(AovRender, ClearcoatAlbedo) {
    Scene scene = quad_scene();
    Material& m = scene.materials[0];
    m.specular_model = FC_SPECULAR_MICROFACET;
    set_metallic_roughness(m, glm::vec3(0.2f, 0.5f, 0.7f), 0.0f, 0.04f);
    m.clearcoat = 1.0f;
    m.clearcoat_alpha = 0.0f;
    const AovImages a = render_aovs(test::context(), scene, build_bvh(scene.vertices), 4);
    const std::size_t on = std::size_t(8) * kSize + 3;
    EXPECT_NEAR(a.albedo[3 * on + 0], 0.04f + 0.96f * 0.24f, 1e-4f);
    EXPECT_NEAR(a.albedo[3 * on + 1], 0.04f + 0.96f * 0.54f, 1e-4f);
    EXPECT_NEAR(a.albedo[3 * on + 2], 0.04f + 0.96f * 0.74f, 1e-4f);
}

// The AOV pass draws camera samples of its own (aov_seed), not the render's: an emitting
// quad whose edge cuts the middle of column 32 of 64, one sample a pixel in both passes.
// With shared samples the image and the depth AOV would agree in every row of that column
// on which side of the edge the sample fell (they did, 64 of 64); with samples of their
// own they disagree in about half the rows.
TEST(AovRender, SamplesAreNotTheRendersOwn) {
    constexpr int kSide = 64;
    Scene scene = quad_scene(2.0f / kSide);  // columns are 4 / kSide wide
    scene.settings.width = scene.settings.height = kSide;
    scene.materials[0].diffuse = glm::vec3(0.0f);
    scene.materials[0].emission = glm::vec3(1.0f);
    build_lights(scene);
    const Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, 1);
    const FilmHalves h = r.halves();
    const AovImages a = render_aovs(test::context(), scene, bvh, 1);
    int differ = 0, covered = 0;
    for (int y = 0; y < kSide; ++y) {
        const std::size_t i = std::size_t(y) * kSide + kSide / 2;
        const bool image_hit = h.rgb[0][3 * i] > 0.5f, aov_hit = a.depth[i] > 0.0f;
        differ += image_hit != aov_hit;
        covered += aov_hit;
    }
    EXPECT_GT(covered, kSide / 4);  // the edge does cut the column
    EXPECT_LT(covered, 3 * kSide / 4);
    EXPECT_GE(differ, kSide / 4);  // 32 expected, binomial sd 4
}

}  // namespace
}  // namespace facet
