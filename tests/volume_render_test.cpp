// Beer-Lambert absorption inside transmissive materials (FcMaterial.attenuation,
// KHR_materials_volume; kernels/integrator/path.cl): a smooth glass slab of thickness d
// seen head-on by an orthographic camera against a white environment. Suite VolumeRender
// (the render tier).
#include <gtest/gtest.h>

#include <cmath>

#include "host/bvh/bvh.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr int kSize = 8;
constexpr float kThickness = 0.8f;
const glm::vec3 kSigma(0.5f, 1.0f, 2.0f);

// A closed box [-2, 2]^2 x [-d/2, d/2] of smooth glass of index `ior` absorbing `sigma`,
// in a white environment, seen along -z by an orthographic camera 1 unit high.
Scene slab(float ior, glm::vec3 sigma) {
    Scene scene;
    Material m = make_material("dielectric");
    m.ior = ior;
    m.attenuation = sigma;
    add_material(scene, m, "glass");
    const glm::vec3 lo(-2.0f, -2.0f, -0.5f * kThickness);
    const glm::vec3 e[3] = {{4, 0, 0}, {0, 4, 0}, {0, 0, kThickness}};
    for (int a = 0; a < 3; ++a) {
        const glm::vec3 u = e[(a + 1) % 3], v = e[(a + 2) % 3], w = e[a];
        add_quad(scene, lo, v, u, 0);      // the face at -w, facing -w
        add_quad(scene, lo + w, u, v, 0);  // the face at +w, facing +w
    }
    scene.environment = constant_environment(glm::vec3(1.0f));
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.ortho_height = 1.0f;
    scene.settings.width = scene.settings.height = kSize;
    scene.settings.max_depth = 64;
    scene.settings.rr_depth = 1 << 20;
    build_lights(scene);
    return scene;
}

// Per channel: the mean of the image and its standard error (over the pixels).
void mean_and_error(const std::vector<float>& img, int c, double* mean, double* error) {
    double s = 0.0, s2 = 0.0;
    const std::size_t n = img.size() / 3;
    for (std::size_t i = 0; i < n; ++i) {
        const double v = double(img[3 * i + std::size_t(c)]);
        s += v;
        s2 += v * v;
    }
    *mean = s / double(n);
    *error = std::sqrt(std::max(s2 / double(n) - *mean * *mean, 0.0) / double(n));
}

// Index-matched (ior 1: no reflection, no bending): every sample is exp(-sigma d) exactly.
TEST(VolumeRender, IndexMatchedSlabTransmitsExpMinusSigmaD) {
    const Scene scene = slab(1.0f, kSigma);
    EXPECT_NE(describe_features(scene_features(scene)).find("volume"), std::string::npos);
    Renderer r(test::context(), scene, build_bvh(scene.vertices));
    render_fixed(r, 16, 16);
    const std::vector<float> img = r.image();
    for (int c = 0; c < 3; ++c) {
        double mean, error;
        mean_and_error(img, c, &mean, &error);
        EXPECT_NEAR(mean, std::exp(-double(kSigma[c]) * double(kThickness)), 1e-4) << "channel " << c;
    }
}

// Glass of ior 1.5 head-on: F = 0.04 at each face, T = exp(-sigma d); the slab's
// reflectance and transmittance summed over the internal bounces (Stokes),
//   R = F + (1 - F)^2 F T^2 / (1 - F^2 T^2),  T_slab = (1 - F)^2 T / (1 - F^2 T^2),
// both see the white environment, so a pixel's mean is R + T_slab (a z-test on the
// Fresnel choices' noise). Without absorption it would be 1.
TEST(VolumeRender, GlassSlabMatchesStokes) {
    const Scene scene = slab(1.5f, kSigma);
    Renderer r(test::context(), scene, build_bvh(scene.vertices));
    render_fixed(r, 1024, 64);
    const std::vector<float> img = r.image();
    const double f = 0.04;
    for (int c = 0; c < 3; ++c) {
        const double t = std::exp(-double(kSigma[c]) * double(kThickness));
        const double denom = 1.0 - f * f * t * t;
        const double want = f + (1 - f) * (1 - f) * f * t * t / denom + (1 - f) * (1 - f) * t / denom;
        double mean, error;
        mean_and_error(img, c, &mean, &error);
        EXPECT_LT(std::fabs(mean - want), 4.0 * error + 1e-4) << "channel " << c << ": " << mean << " vs " << want;
    }
}

}  // namespace
}  // namespace facet
