// Lights against analytic answers on the real kernels: punctual lights above a
// Lambertian plane (Hoffman's convention, Lo = pi f c (n.l) / d^2) and furnaces in
// a constant environment.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/scene_test_util.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet {
namespace {

constexpr float kAlbedo = 0.6f;

// A 20 x 20 Lambertian plane at y = 0 seen from above by an orthographic camera
// covering [-2, 2]^2: pixel (i, j) sees the point x = -2 + 4 (i + 0.5) / n, z likewise.
Scene plane_scene(int n) {
    Scene scene;
    Material m = make_material("lambert");
    for (int c = 0; c < 3; ++c) m.diffuse[c] = kAlbedo;
    add_material(scene, m, "plane");
    test::add_plane_seen_from_above(scene, 0, n);
    return scene;
}

std::vector<float> render(Scene& scene, std::uint32_t spp, double* rejected = nullptr) {
    build_lights(scene);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp);
    return r.image(rejected);
}

// The world point seen at the centre of pixel (i, j) of plane_scene(n).
glm::vec3 plane_point(int n, int i, int j) {
    return glm::vec3(-2.0f + 4.0f * (float(i) + 0.5f) / float(n), 0.0f, -2.0f + 4.0f * (float(j) + 0.5f) / float(n));
}

TEST(Lights, PointLightAbovePlane) {
    const int n = 64;
    Scene scene = plane_scene(n);
    PunctualLight light;
    light.type = FC_LIGHT_POINT;
    light.position = glm::vec3(0.3f, 1.5f, -0.2f);
    light.color = glm::vec3(2.0f, 1.0f, 0.5f);
    scene.punctual_lights.push_back(light);
    std::vector<float> img = render(scene, 256);  // pixel jitter averages the footprint
    for (auto [i, j] : {std::pair{32, 32}, std::pair{10, 50}, std::pair{60, 5}, std::pair{40, 20}}) {
        glm::vec3 p = plane_point(n, i, j);
        glm::vec3 to = light.position - p;
        float d2 = glm::dot(to, to), cos_theta = to.y / std::sqrt(d2);
        for (int c = 0; c < 3; ++c) {
            // Lo = pi (rho / pi) c cos / d^2; pixel (i, j) is image column i, row j.
            float expected = kAlbedo * light.color[c] * cos_theta / d2;
            float got = img[3 * (std::size_t(j) * n + i) + c];
            EXPECT_NEAR(got, expected, 0.01f * expected) << "pixel " << i << "," << j << " channel " << c;
        }
    }
}

TEST(Lights, SpotAndDirectionalLights) {
    const int n = 32;
    Scene scene = plane_scene(n);
    PunctualLight sun;
    sun.type = FC_LIGHT_DIRECTIONAL;
    sun.direction = glm::vec3(1.0f, -2.0f, 0.0f);
    sun.color = glm::vec3(1.0f);
    scene.punctual_lights.push_back(sun);
    std::vector<float> img = render(scene, 4);
    float cos_theta = 2.0f / std::sqrt(5.0f);
    EXPECT_NEAR(img[3 * (16 * n + 16)], kAlbedo * cos_theta, 1e-3f);

    Scene spot_scene = plane_scene(n);
    PunctualLight spot;
    spot.type = FC_LIGHT_SPOT;
    spot.position = glm::vec3(0.0f, 1.0f, 0.0f);
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.color = glm::vec3(1.0f);
    spot.inner_degrees = 20.0f;
    spot.outer_degrees = 30.0f;
    spot_scene.punctual_lights.push_back(spot);
    std::vector<float> s = render(spot_scene, 256);
    // Inside the inner cone the pixel is the footprint's mean of rho cos / d^2.
    double expected = 0.0;
    for (int a = 0; a < 16; ++a)
        for (int b = 0; b < 16; ++b) {
            double x = 4.0 * (16 + (a + 0.5) / 16.0) / n - 2.0, z = 4.0 * (16 + (b + 0.5) / 16.0) / n - 2.0;
            double d2 = 1.0 + x * x + z * z;
            expected += double(kAlbedo) / (d2 * std::sqrt(d2)) / 256.0;
        }
    EXPECT_NEAR(s[3 * (16 * n + 16)], expected, 0.002 * expected) << "inside the inner cone";
    EXPECT_EQ(s[3 * (16 * n + 2)], 0.0f) << "outside the outer cone (about 60 degrees off the axis)";
}

// A convex white Lambertian sphere inside a constant environment of radiance L sees L
// in every direction, so it reflects exactly L: every pixel is L.
TEST(Lights, ConstantEnvironmentFurnace) {
    Scene scene;
    Material m = make_material("lambert");
    for (int c = 0; c < 3; ++c) m.diffuse[c] = 1.0f;
    add_material(scene, m, "white");
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 4, 0, false);
    scene.environment = constant_environment(glm::vec3(0.7f));
    scene.camera.eye = glm::vec3(0, 0, 4);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fov_y_degrees = 35.0f;
    scene.settings.width = scene.settings.height = 32;
    scene.settings.max_depth = 64;
    double rejected = -1;
    std::vector<float> img = render(scene, 64, &rejected);
    EXPECT_EQ(rejected, 0.0);
    double sum = 0.0;
    for (float v : img) {
        ASSERT_TRUE(std::isfinite(v));
        sum += double(v);
    }
    EXPECT_NEAR(sum / double(img.size()), 0.7, 0.007);
    // The centre pixels see the sphere.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(img[3 * (16 * 32 + 16) + c], 0.7f, 0.07f);
}

// A white rough conductor with F = 1 loses energy to shadowing-masking: <= L.
TEST(Lights, RoughConductorInEnvironmentReflectsAtMostL) {
    Scene scene;
    Material m = make_material("microfacet");
    m.diffuse_model = FC_DIFFUSE_NONE;
    m.fresnel = FC_FRESNEL_ONE;
    m.ndf = FC_NDF_GGX;
    m.geometry = FC_G_SMITH_CORRELATED;
    m.alpha_x = m.alpha_y = 0.6f;
    m.energy_compensation = false;  // the single-scattering loss below (energy_compensation_test.cpp: with it)
    add_material(scene, m, "conductor");
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 4, 0, false);
    scene.environment = constant_environment(glm::vec3(1.0f));
    scene.camera.eye = glm::vec3(0, 0, 4);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fov_y_degrees = 20.0f;  // only the sphere in view
    scene.settings.width = scene.settings.height = 24;
    scene.settings.max_depth = 64;
    std::vector<float> img = render(scene, 64);
    double sum = 0.0;
    for (float v : img) sum += double(v);
    double mean = sum / double(img.size());
    EXPECT_LE(mean, 1.0 + 0.005);
    // Single scattering at alpha 0.6 loses about 40% at normal incidence, 15% at grazing
    // angles (docs/brdf.md's table): the disk averages about 0.62.
    EXPECT_GT(mean, 0.55);
    EXPECT_LT(mean, 0.70);
}

// The light pick is the cdf's inverse: light k for u in [cdf[k], cdf[k + 1]), for any number of
// lights, lights of zero power (equal entries) never picked, and u at each entry and just below;
// the same picks from its lane forms at W = 8 and 16 (the packets' light pick, by gathers where
// the CPU has them).
TEST(Lights, PickInvertsTheCdf) {
    ClContext& ctx = test::context();
    cl::Kernel k(test::program("kernels/test/light_pick_kernels.cl"), "light_pick_batch");
    cl::Kernel lanes(test::program("kernels/test/light_pick_kernels.cl"), "light_pick_lanes");
    for (std::uint32_t count = 1; count <= 19; ++count) {
        // powers 1, 0, 3, 4, 0, 2, ... (every third light dark from the second on)
        std::vector<double> power(count);
        std::vector<float> cdf(count + 1, 0.0f);
        double total = 0.0;
        for (std::uint32_t i = 0; i < count; ++i)
            total += power[i] = (i % 3 == 1 && count > 1) ? 0.0 : 1.0 + double(i % 4);
        double run = 0.0;
        for (std::uint32_t i = 0; i < count; ++i) cdf[i + 1] = float((run += power[i]) / total);
        cdf[count] = 1.0f;
        std::vector<float> u;
        for (int s = 0; s < 997; ++s) u.push_back((float(s) + 0.5f) / 997.0f);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (cdf[i] < 1.0f) u.push_back(cdf[i]);  // u lies in [0, 1)
            if (cdf[i] > 0.0f) u.push_back(std::nextafter(cdf[i], 0.0f));
        }
        u.push_back(std::nextafter(1.0f, 0.0f));
        while (u.size() % 16 != 0) u.push_back(0.0f);  // whole vectors for the lane forms
        cl::Buffer c(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, cdf.size() * sizeof(float), cdf.data());
        cl::Buffer ub(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, u.size() * sizeof(float), u.data());
        cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, u.size() * sizeof(int));
        cl::Buffer o8(ctx.context(), CL_MEM_WRITE_ONLY, u.size() * sizeof(int));
        cl::Buffer o16(ctx.context(), CL_MEM_WRITE_ONLY, u.size() * sizeof(int));
        k.setArg(0, c), k.setArg(1, count), k.setArg(2, ub), k.setArg(3, ob);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(u.size()));
        lanes.setArg(0, c), lanes.setArg(1, count), lanes.setArg(2, ub), lanes.setArg(3, o8), lanes.setArg(4, o16);
        ctx.queue().enqueueNDRangeKernel(lanes, cl::NullRange, cl::NDRange(u.size() / 16));
        std::vector<int> picked(u.size()), picked8(u.size()), picked16(u.size());
        ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, picked.size() * sizeof(int), picked.data());
        ctx.queue().enqueueReadBuffer(o8, CL_TRUE, 0, picked8.size() * sizeof(int), picked8.data());
        ctx.queue().enqueueReadBuffer(o16, CL_TRUE, 0, picked16.size() * sizeof(int), picked16.data());
        for (std::size_t s = 0; s < u.size(); ++s) {
            int expected = 0;  // the last k with cdf[k] <= u
            for (std::uint32_t kk = 1; kk < count; ++kk)
                if (cdf[kk] <= u[s]) expected = int(kk);
            ASSERT_EQ(picked[s], expected) << count << " lights, u " << u[s];
            ASSERT_GT(power[std::size_t(picked[s])], 0.0) << count << " lights, u " << u[s];
            ASSERT_EQ(picked8[s], expected) << "W = 8, " << count << " lights, u " << u[s];
            ASSERT_EQ(picked16[s], expected) << "W = 16, " << count << " lights, u " << u[s];
        }
    }
}

}  // namespace
}  // namespace facet
