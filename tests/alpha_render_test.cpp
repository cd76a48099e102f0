// AlphaRender.*: alpha cut-outs and stochastic transparency rendered through the real
// kernels (kernels/trace/alpha_test.cl) against analytic answers, each a z-test of a region's
// mean against its value with the spread of the region's pixels: a MASK quad casts the shadow
// of its texture's shape, a BLEND quad's shadow lets 1 - a of the light through, and a BLEND
// quad in front of an emitter transmits 1 - a of it to the camera.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "host/bvh/bvh.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr int kSize = 32;

std::vector<float> render(const Scene& scene, std::uint32_t spp) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp, spp);
    return r.image();
}

// The mean of channel 0 over the pixels whose ground point (x, z) `inside` accepts, against
// `expected`: |mean - expected| within 4 standard errors (the pixels' spread / sqrt(n)),
// or 1e-3 where the region is noiseless. `where` maps pixel (i, j) to its ground point.
void expect_region(const std::vector<float>& img, const std::function<bool(float, float)>& inside,
                   const std::function<glm::vec2(int, int)>& where, double expected, const char* what) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const glm::vec2 p = where(i, j);
            if (!inside(p.x, p.y)) continue;
            const double v = img[3 * std::size_t(j * kSize + i)];
            sum += v, sum2 += v * v, ++n;
        }
    ASSERT_GT(n, 10) << what;
    const double mean = sum / n;
    const double var = std::max(0.0, (sum2 - sum * mean) / (n - 1));
    const double tolerance = std::max(4.0 * std::sqrt(var / n), 1e-3);
    EXPECT_NEAR(mean, expected, tolerance) << what << " (" << n << " pixels)";
}

// A Lambertian ground (albedo 0.5) at y = 0 lit by a directional light travelling along
// (1, -1, 0) / sqrt(2), with the quad of `occluder` at height 1 over x in [-1, 0], z in
// [-1, 1]: its shadow falls on x in [0, 1]. An orthographic camera looks straight down at
// x in [-0.5, 1.5], z in [-1, 1]; direct light only. Lit ground: L = 0.5 cos 45.
Scene shadow_scene(const Material& occluder) {
    Scene s;
    Material ground = make_material("lambert");
    ground.diffuse = glm::vec3(0.5f);
    add_material(s, ground, "ground");
    add_material(s, occluder, "occluder");
    add_quad(s, glm::vec3(-3, 0, 3), glm::vec3(6, 0, 0), glm::vec3(0, 0, -6), 0);
    add_quad(s, glm::vec3(-1, 1, 1), glm::vec3(1, 0, 0), glm::vec3(0, 0, -2), 1);  // u = x + 1
    PunctualLight sun;
    sun.type = FC_LIGHT_DIRECTIONAL;
    sun.direction = glm::normalize(glm::vec3(1, -1, 0));
    s.punctual_lights.push_back(sun);
    build_lights(s);
    s.camera.eye = glm::vec3(0.5f, 5.0f, 0.0f);
    s.camera.target = glm::vec3(0.5f, 0.0f, 0.0f);
    s.camera.up = glm::vec3(0, 0, -1);  // right = +x
    s.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    s.camera.ortho_height = 2.0f;
    s.settings.width = s.settings.height = kSize;
    s.settings.max_depth = 1;
    return s;
}

glm::vec2 ground_point(int i, int j) {
    return glm::vec2(-0.5f + 2.0f * (float(i) + 0.5f) / kSize, -1.0f + 2.0f * (float(j) + 0.5f) / kSize);
}

const double kLit = 0.5 * std::sqrt(0.5);

// The texture's left half (u < 0.5) has alpha 0, its right half 1: the quad over x in
// [-1, -0.5) is cut away and lets the light through to x in [0, 0.5); its opaque half shades
// x in (0.5, 1]. Without the alpha test in shadow rays the whole of x in [0, 1] is dark.
TEST(AlphaRender, MaskQuadCastsTheShadowOfItsTexture) {
    Material cutout = make_material("lambert");
    cutout.alpha_mode = FC_ALPHA_MASK;
    cutout.alpha_cutoff = 0.5f;
    cutout.textures.alpha = 0;
    Scene s = shadow_scene(cutout);
    std::vector<float> rgba;
    for (int x = 0; x < 16; ++x) rgba.insert(rgba.end(), {1.0f, 1.0f, 1.0f, x < 8 ? 0.0f : 1.0f});
    s.textures.push_back(make_texture(16, 1, rgba, FC_WRAP_CLAMP, FC_WRAP_CLAMP));
    const std::vector<float> img = render(s, 16);
    auto z_inner = [](float z) { return std::fabs(z) < 0.85f; };
    expect_region(
        img, [&](float x, float z) { return x > 0.08f && x < 0.42f && z_inner(z); }, ground_point, kLit,
        "ground under the cut-away half: lit");
    expect_region(
        img, [&](float x, float z) { return x > 0.58f && x < 0.92f && z_inner(z); }, ground_point, 0.0,
        "ground under the opaque half: in shadow");
    expect_region(
        img, [&](float x, float z) { return x > 1.08f && z_inner(z); }, ground_point, kLit,
        "ground beyond the shadow: lit");
}

// A BLEND quad of constant alpha 0.3: shadow rays pass with probability 0.7, so the shadow
// holds 0.7 of the light in expectation. Without the test it is black; with MASK-like
// treatment (all or nothing) it would be 0 or the full light.
TEST(AlphaRender, BlendShadowTransmitsOneMinusAlpha) {
    Material veil = make_material("lambert");
    veil.alpha_mode = FC_ALPHA_BLEND;
    veil.alpha = 0.3f;
    const std::vector<float> img = render(shadow_scene(veil), 64);
    expect_region(
        img, [](float x, float z) { return x > 0.08f && x < 0.92f && std::fabs(z) < 0.85f; }, ground_point, 0.7 * kLit,
        "ground in the shadow of the veil");
}

// A black BLEND quad of alpha 0.3 in front of a two-sided emitter of radiance 1: the camera
// sees the emitter through it with probability 0.7, so every pixel's expectation is 0.7.
TEST(AlphaRender, BlendQuadTransmitsOneMinusAlphaOfTheBackground) {
    Scene s;
    Material veil = make_material("lambert");
    veil.diffuse = glm::vec3(0.0f);
    veil.alpha_mode = FC_ALPHA_BLEND;
    veil.alpha = 0.3f;
    Material light = make_material("lambert");
    light.diffuse = glm::vec3(0.0f);
    light.emission = glm::vec3(1.0f);
    light.two_sided_emission = true;
    add_material(s, veil, "veil");
    add_material(s, light, "light");
    add_quad(s, glm::vec3(-2, -2, 0), glm::vec3(4, 0, 0), glm::vec3(0, 4, 0), 0);
    add_quad(s, glm::vec3(-4, -4, -1), glm::vec3(8, 0, 0), glm::vec3(0, 8, 0), 1);
    build_lights(s);
    s.camera.eye = glm::vec3(0, 0, 3);
    s.camera.target = glm::vec3(0.0f);
    s.settings.width = s.settings.height = kSize;
    s.settings.max_depth = 1;
    const std::vector<float> img = render(s, 64);
    expect_region(
        img, [](float, float) { return true; }, [](int i, int j) { return glm::vec2(float(i), float(j)); }, 0.7,
        "emitter seen through the veil");
}

// An emitting MASK quad whose far half (x < 0) is cut away, facing down onto a Lambertian
// ground seen where the quad is not: light sampling (which picks points on the whole card) and
// BSDF sampling (whose rays pass the cut-away half) must see the same light. Without the
// coverage weight of light samples the light-sampled image is brighter by the far half's light.
TEST(AlphaRender, EmittingCutOutLightsAlikeByBothStrategies) {
    Scene s;
    Material ground = make_material("lambert");
    ground.diffuse = glm::vec3(0.5f);
    Material lamp = make_material("lambert");
    lamp.diffuse = glm::vec3(0.0f);
    lamp.emission = glm::vec3(4.0f);
    lamp.alpha_mode = FC_ALPHA_MASK;
    lamp.textures.alpha = 0;
    add_material(s, ground, "ground");
    add_material(s, lamp, "lamp");
    add_quad(s, glm::vec3(-3, 0, 3), glm::vec3(6, 0, 0), glm::vec3(0, 0, -6), 0);
    add_quad(s, glm::vec3(-0.5f, 1.0f, -0.5f), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), 1);  // faces down, u = x + 0.5
    std::vector<float> rgba;
    for (int x = 0; x < 16; ++x) rgba.insert(rgba.end(), {1.0f, 1.0f, 1.0f, x < 8 ? 0.0f : 1.0f});
    s.textures.push_back(make_texture(16, 1, rgba, FC_WRAP_CLAMP, FC_WRAP_CLAMP));
    build_lights(s);
    s.camera.eye = glm::vec3(1.5f, 5.0f, 0.0f);
    s.camera.target = glm::vec3(1.5f, 0.0f, 0.0f);
    s.camera.up = glm::vec3(0, 0, -1);
    s.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    s.camera.ortho_height = 1.8f;  // x in [0.6, 2.4]: the lamp (x <= 0.5) is out of view
    s.settings.width = s.settings.height = kSize;
    s.settings.max_depth = 1;
    double mean[2], se2[2];
    for (int k = 0; k < 2; ++k) {
        s.settings.strategy = k == 0 ? FC_STRATEGY_LIGHT : FC_STRATEGY_BSDF;
        const std::vector<float> img = render(s, k == 0 ? 16 : 256);
        double sum = 0.0, sum2 = 0.0;
        const int n = kSize * kSize;
        for (int i = 0; i < n; ++i) {
            const double v = img[3 * std::size_t(i)];
            sum += v, sum2 += v * v;
        }
        mean[k] = sum / n;
        se2[k] = std::max(0.0, (sum2 - sum * mean[k]) / (n - 1)) / n;
    }
    EXPECT_GT(mean[1], 0.0) << "the ground is lit";
    EXPECT_LT(std::fabs(mean[0] - mean[1]), 4.0 * std::sqrt(se2[0] + se2[1]) + 1e-4)
        << "light sampling " << mean[0] << ", BSDF sampling " << mean[1];
}

}  // namespace
}  // namespace facet
