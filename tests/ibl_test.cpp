// Exact image-based lighting: an upward-facing Lambertian plane of albedo rho lit only
// by a map has radiance (rho / pi) * integral of L(w) cos(theta) dw. The integral of
// the piecewise-constant map is summed texel by texel in closed form (the texel's band
// of cos(theta) sin(theta)), and each strategy (environment sampling alone, BSDF
// sampling alone, MIS) must agree with it within 1%, on a smooth map and on the stiff
// generated sun and sky.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "host/bvh/bvh.hpp"
#include "tests/cl_test_env.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/sky.hpp"

namespace facet {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kRho = 0.5f;

// (rho / pi) * sum over texels of L * integral of max(0, cos theta) over the texel,
// for a map with identity rotation (map +y = world up).
glm::dvec3 exact_plane_radiance(const EnvironmentMap& env) {
    const int w = env.params.width, h = env.params.height;
    glm::dvec3 sum(0.0);
    for (int y = 0; y < h; ++y) {
        double t0 = kPi * y / h, t1 = kPi * (y + 1) / h;
        if (t0 >= kPi / 2) break;
        t1 = std::min(t1, kPi / 2);
        // integral over the band of cos(theta) sin(theta) dtheta, times dphi
        double band = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) * (2.0 * kPi / w);
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                sum[c] += double(env.texels[4 * (std::size_t(y) * w + x) + c]) * double(env.params.scale[c]) * band;
    }
    return sum * double(kRho) / kPi;
}

// The same for the bilinear lookup (kernels/lights/environment.cl, env_lookup): the
// interpolated map integrated numerically, 8 x 8 midpoints a texel (the interpolation is
// linear inside each of them; the error is the cosine's curvature, far below 1e-4).
glm::dvec3 exact_plane_radiance_bilinear(const EnvironmentMap& env) {
    const int w = env.params.width, h = env.params.height, n = 8;
    auto texel = [&](int x, int y) {
        x = (x + w) % w;
        y = std::clamp(y, 0, h - 1);
        const float* t = &env.texels[4 * (std::size_t(y) * w + x)];
        return glm::dvec3(t[0], t[1], t[2]);
    };
    glm::dvec3 sum(0.0);
    for (int j = 0; j < h * n / 2; ++j) {  // the upper hemisphere: theta < pi / 2
        const double v = (j + 0.5) / (h * n), theta = kPi * v;
        const double weight = std::cos(theta) * std::sin(theta) * (kPi / (h * n)) * (2.0 * kPi / (w * n));
        const double y = v * h - 0.5, y0 = std::floor(y), fy = y - y0;
        for (int i = 0; i < w * n; ++i) {
            const double x = (i + 0.5) / n - 0.5, x0 = std::floor(x), fx = x - x0;
            const int xi = int(x0), yi = int(y0);
            const glm::dvec3 top = glm::mix(texel(xi, yi), texel(xi + 1, yi), fx);
            const glm::dvec3 bottom = glm::mix(texel(xi, yi + 1), texel(xi + 1, yi + 1), fx);
            sum += glm::mix(top, bottom, fy) * weight;
        }
    }
    for (int c = 0; c < 3; ++c) sum[c] *= double(env.params.scale[c]);
    return sum * double(kRho) / kPi;
}

glm::dvec3 render_plane(const EnvironmentMap& env, int strategy, int size, std::uint32_t spp) {
    Scene scene;
    Material m = make_material("lambert");
    for (int c = 0; c < 3; ++c) m.diffuse[c] = kRho;
    add_material(scene, m, "plane");
    add_quad(scene, glm::vec3(-50, 0, 50), glm::vec3(100, 0, 0), glm::vec3(0, 0, -100), 0);
    scene.environment = env;
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.eye = glm::vec3(0, 1, 0);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.up = glm::vec3(0, 0, -1);
    scene.camera.ortho_height = 1.0f;
    scene.settings.width = scene.settings.height = size;
    scene.settings.max_depth = 1;
    scene.settings.strategy = strategy;
    build_lights(scene);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp, 256);
    double rejected = -1.0;
    std::vector<float> img = r.image(&rejected);
    EXPECT_EQ(rejected, 0.0);
    glm::dvec3 mean(0.0);
    for (std::size_t i = 0; i < img.size(); ++i) mean[int(i % 3)] += double(img[i]);
    return mean / double(img.size() / 3);
}

void expect_close(glm::dvec3 got, glm::dvec3 want, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 0.01 * want[c]) << what << ", channel " << c;
}

// A smooth map: a bright zenith fading to a coloured horizon and a dark ground.
EnvironmentMap smooth_map() {
    const int w = 64, h = 32;
    std::vector<float> rgb(3 * w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double theta = kPi * (y + 0.5) / h, phi = 2 * kPi * (x + 0.5) / w;
            double sky = theta < kPi / 2 ? 1.0 + 2.0 * std::cos(theta) + 0.5 * std::sin(phi) : 0.1;
            rgb[3 * (y * w + x) + 0] = float(sky);
            rgb[3 * (y * w + x) + 1] = float(0.8 * sky);
            rgb[3 * (y * w + x) + 2] = float(0.6 * sky + 0.2);
        }
    std::vector<std::string> warnings;
    return environment_from_pixels(w, h, rgb, glm::vec3(1.0f), glm::mat3(1.0f), "smooth", warnings);
}

TEST(Ibl, ExactPlaneRadianceSmoothMap) {
    EnvironmentMap env = smooth_map();
    glm::dvec3 exact = exact_plane_radiance(env);
    expect_close(render_plane(env, FC_STRATEGY_MIS, 16, 256), exact, "MIS, 65k samples");
    expect_close(render_plane(env, FC_STRATEGY_LIGHT, 16, 256), exact, "environment sampling, 65k samples");
    expect_close(render_plane(env, FC_STRATEGY_BSDF, 16, 1024), exact, "BSDF sampling, 262k samples");
}

// The generated sun and sky at 64 x 32 texels: the sun (one texel, over half of the
// power) is what makes BSDF sampling alone slow, so it gets 34 million samples; the
// seed is fixed, so the result is reproducible.
TEST(Ibl, ExactPlaneRadianceStiffSunSky) {
    SunSkyParams params;
    params.elevation_degrees = 35.0;
    EnvironmentMap env = sun_sky_environment(params, 64);
    SunSkyImage img = render_sun_sky(params, 64);
    ASSERT_GT(img.sun_power_fraction, 0.5);
    glm::dvec3 exact = exact_plane_radiance(env);
    expect_close(render_plane(env, FC_STRATEGY_MIS, 16, 256), exact, "MIS, 65k samples");
    expect_close(render_plane(env, FC_STRATEGY_LIGHT, 16, 256), exact, "environment sampling, 65k samples");
    expect_close(render_plane(env, FC_STRATEGY_BSDF, 64, 8192), exact, "BSDF sampling, 34M samples");
}

// The bilinear lookup, with the distribution built from each texel's mean interpolated
// luminance: every strategy still converges to the interpolated map's integral (light
// sampling alone included: a texel next to the sun, dark itself, is lit by the
// interpolation and has to be sampled, and a distribution of the texels' own luminance
// would leave it out). The two lookups' integrals differ little here (0.12 % on the
// stiff sun): what the lookup is, Environment.BilinearLookup tests.
TEST(Ibl, ExactPlaneRadianceBilinear) {
    EnvironmentMap smooth = smooth_map();
    set_environment_filter(smooth, FC_ENV_FILTER_BILINEAR);
    glm::dvec3 exact = exact_plane_radiance_bilinear(smooth);
    expect_close(render_plane(smooth, FC_STRATEGY_MIS, 16, 256), exact, "smooth, bilinear, MIS");
    expect_close(render_plane(smooth, FC_STRATEGY_LIGHT, 16, 256), exact, "smooth, bilinear, environment sampling");
    expect_close(render_plane(smooth, FC_STRATEGY_BSDF, 16, 1024), exact, "smooth, bilinear, BSDF sampling");
    SunSkyParams params;
    params.elevation_degrees = 35.0;
    EnvironmentMap sky = sun_sky_environment(params, 64);
    const glm::dvec3 nearest = exact_plane_radiance(sky);
    set_environment_filter(sky, FC_ENV_FILTER_BILINEAR);
    exact = exact_plane_radiance_bilinear(sky);
    std::printf("[ ibl      ] stiff sun and sky 64x32, plane radiance: bilinear %.5f, nearest %.5f (green)\n", exact.y,
                nearest.y);
    expect_close(render_plane(sky, FC_STRATEGY_MIS, 16, 256), exact, "sun and sky, bilinear, MIS");
    expect_close(render_plane(sky, FC_STRATEGY_LIGHT, 16, 256), exact, "sun and sky, bilinear, environment sampling");
}

// MIS compensation (environment_map.hpp) keeps the estimator unbiased: the mean of a scene
// under the sun and sky (a diffuse and a glossy sphere on a diffuse ground, 4 bounces)
// is the same with the compensated and the plain distribution. Each is rendered with 8
// seeds; the image means of the two sets are compared by a two-sample z-test.
TEST(Ibl, CompensationKeepsTheMean) {
    SunSkyParams params;
    params.elevation_degrees = 35.0;
    Scene scene;
    Material diffuse = make_material("lambert"), glossy = make_material("ggx"), ground = make_material("lambert");
    glossy.alpha_x = glossy.alpha_y = 0.2f;
    for (int c = 0; c < 3; ++c) diffuse.diffuse[c] = 0.7f, glossy.diffuse[c] = 0.2f, glossy.f0[c] = 0.5f;
    for (int c = 0; c < 3; ++c) ground.diffuse[c] = 0.4f;
    add_material(scene, diffuse, "diffuse");
    add_material(scene, glossy, "glossy");
    add_material(scene, ground, "ground");
    add_sphere(scene, glm::vec3(-1.1f, 1.0f, 0.0f), 1.0f, 3, 0, false);
    add_sphere(scene, glm::vec3(1.1f, 1.0f, 0.0f), 1.0f, 3, 1, false);
    add_quad(scene, glm::vec3(-20, 0, 20), glm::vec3(40, 0, 0), glm::vec3(0, 0, -40), 2);
    scene.environment = sun_sky_environment(params, 128);
    scene.camera.eye = glm::vec3(0.0f, 2.0f, 6.0f);
    scene.camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
    scene.camera.fov_y_degrees = 40.0f;
    scene.settings.width = 32;
    scene.settings.height = 24;
    scene.settings.max_depth = 4;
    build_lights(scene);
    Bvh bvh = build_bvh(scene.vertices);
    auto image_means = [&](EnvironmentSampling sampling, std::uint32_t seed0) {
        std::vector<double> means;
        Scene s = scene;
        s.environment.sampling = sampling;
        for (std::uint32_t k = 0; k < 8; ++k) {
            s.settings.seed = seed0 + k;
            Renderer r(test::context(), s, bvh);
            render_fixed(r, 64, 64);
            double rejected = -1.0;
            std::vector<float> img = r.image(&rejected);
            EXPECT_EQ(rejected, 0.0);
            double sum = 0.0;
            for (std::size_t i = 0; i < img.size(); ++i)
                sum += double(img[i]) * (i % 3 == 0 ? 0.2126 : i % 3 == 1 ? 0.7152 : 0.0722);
            means.push_back(sum / double(img.size() / 3));
        }
        return means;
    };
    auto mean_var = [](const std::vector<double>& v) {
        double m = 0.0, q = 0.0;
        for (double x : v) m += x;
        m /= double(v.size());
        for (double x : v) q += (x - m) * (x - m);
        return std::pair{m, q / double(v.size() - 1) / double(v.size())};  // the mean and its variance
    };
    auto [mc, vc] = mean_var(image_means(EnvironmentSampling::compensated, 100));
    auto [mp, vp] = mean_var(image_means(EnvironmentSampling::plain, 200));
    const double z = (mc - mp) / std::sqrt(vc + vp);
    std::printf("[ mis-comp ] image mean: compensated %.6f +- %.6f, plain %.6f +- %.6f, z = %.2f\n", mc, std::sqrt(vc),
                mp, std::sqrt(vp), z);
    EXPECT_LT(std::fabs(z), 4.0);
}

}  // namespace
}  // namespace facet
