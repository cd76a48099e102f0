// Pixel filters (kernels/camera/filter.cl) through the whole renderer: an orthographic
// camera, one world unit per pixel, looks at an emitting half-plane x >= edge of
// radiance E. A pixel centred at c then holds, for a filter f1 (x) f1 (y) of radius r,
//     V(c) = E * (integral of f1 over [edge - c, r]) / (integral of f1 over [-r, r]),
// and each sample is E * w * [inside] with |w| = (integral of |f1| / integral of f1)^2,
// so its variance is known too. With independent samples every column's mean is
// z-tested against V (the image's rows see the same edge). The filters are written
// here from their definitions and integrated numerically, independently of the
// kernel's closed forms. Thin-lens depth of field: an edge on the plane of focus stays
// sharp, one off it is blurred by the circle of confusion. Suite FilterRender (the
// render tier).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr int kWidth = 32, kHeight = 4;
constexpr float kEdge = 0.3f;  // world x of the edge; image x = world x + 16
constexpr double kRadiance = 2.0;

// The one-dimensional filter profile f1 of each filter, from its definition.
double filter_1d(int filter, double r, double x) {
    const double a = std::abs(x);
    if (a > r) return 0.0;
    switch (filter) {
        case FC_FILTER_TENT:
            return 1.0 - a / r;
        case FC_FILTER_GAUSSIAN: {
            const double sigma = r / 3.0;
            return std::exp(-a * a / (2 * sigma * sigma)) - std::exp(-r * r / (2 * sigma * sigma));
        }
        case FC_FILTER_MITCHELL: {
            const double B = 1.0 / 3.0, C = 1.0 / 3.0, t = 2.0 * a / r;
            if (t < 1.0) return ((12 - 9 * B - 6 * C) * t * t * t + (-18 + 12 * B + 6 * C) * t * t + (6 - 2 * B)) / 6;
            return ((-B - 6 * C) * t * t * t + (6 * B + 30 * C) * t * t + (-12 * B - 48 * C) * t + (8 * B + 24 * C)) /
                   6;
        }
        default:
            return 1.0;
    }
}

// The integral of g over [lo, hi] by the midpoint rule (the profiles are smooth
// between a few kinks; 20000 steps are far below the test's noise).
double integrate(const std::function<double(double)>& g, double lo, double hi) {
    if (!(hi > lo)) return 0.0;
    const int n = 20000;
    const double h = (hi - lo) / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += g(lo + (i + 0.5) * h);
    return sum * h;
}

Scene half_plane_scene(int filter, float radius, int spp) {
    Scene scene;
    Material m = default_material();
    m.diffuse = glm::vec3(0.0f);
    m.emission = glm::vec3(float(kRadiance));
    add_material(scene, m, "emitter");
    add_quad(scene, glm::vec3(kEdge, -100.0f, 0.0f), glm::vec3(100.0f, 0.0f, 0.0f), glm::vec3(0.0f, 200.0f, 0.0f), 0);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.ortho_height = float(kHeight);  // one world unit per pixel
    scene.settings.width = kWidth;
    scene.settings.height = kHeight;
    scene.settings.spp = spp;
    scene.settings.max_depth = 1;
    scene.settings.sampler = FC_SAMPLER_INDEPENDENT;  // independent samples: the z-test's variance is exact
    scene.settings.filter = filter;
    scene.settings.filter_radius = radius;
    scene.settings.seed = 7u + std::uint32_t(filter);
    return scene;
}

std::vector<float> render(const Scene& scene) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, std::uint64_t(scene.settings.spp), 256);
    double rejected = -1.0;
    std::vector<float> img = r.image(&rejected);
    EXPECT_EQ(rejected, 0.0);
    return img;
}

// The column means of channel 0 (every row and channel sees the same edge).
std::vector<double> column_means(const std::vector<float>& img) {
    std::vector<double> col(kWidth, 0.0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) col[x] += double(img[3 * (std::size_t(y) * kWidth + x)]) / kHeight;
    return col;
}

// The largest |z| over the columns of `filter`'s render against the closed form of
// `expected_filter` (the same, except to check that the test tells filters apart).
double worst_z(int filter, int expected_filter, float radius, int spp) {
    const std::vector<double> col = column_means(render(half_plane_scene(filter, radius, spp)));
    const double r = pixel_filter_radius(expected_filter, radius);
    auto f = [&](double x) { return filter_1d(expected_filter, r, x); };
    auto abs_f = [&](double x) { return std::abs(f(x)); };
    const double total = integrate(f, -r, r), abs_total = integrate(abs_f, -r, r);
    const double w2 = std::pow(abs_total / total, 4.0);  // w^2 for a sample of weight +-(abs_total / total)^2
    const double samples = double(spp) * kHeight;
    double worst = 0.0;
    for (int x = 0; x < kWidth; ++x) {
        const double d = (double(kEdge) + 16.0) - (x + 0.5);  // edge - pixel centre, in pixels
        const double lo = std::max(d, -r);
        const double mean = kRadiance * integrate(f, lo, r) / total;
        const double second = kRadiance * kRadiance * w2 * integrate(abs_f, lo, r) / abs_total;
        const double sd = std::sqrt(std::max(second - mean * mean, 0.0) / samples);
        const double err = std::abs(col[x] - mean);
        const double z = sd > 1e-9 ? err / sd : (err < 1e-4 ? 0.0 : HUGE_VAL);
        worst = std::max(worst, z);
    }
    return worst;
}

TEST(FilterRender, HalfPlaneEdgeMatchesEachFilterClosedForm) {
    // 32 columns x 5 renders: |z| > 5 has a chance of about 1e-4 in all.
    EXPECT_LT(worst_z(FC_FILTER_BOX, FC_FILTER_BOX, 0.0f, 2048), 5.0) << "box";
    EXPECT_LT(worst_z(FC_FILTER_BOX, FC_FILTER_BOX, 1.5f, 2048), 5.0) << "box of radius 1.5";
    EXPECT_LT(worst_z(FC_FILTER_TENT, FC_FILTER_TENT, 0.0f, 2048), 5.0) << "tent";
    EXPECT_LT(worst_z(FC_FILTER_GAUSSIAN, FC_FILTER_GAUSSIAN, 0.0f, 2048), 5.0) << "gaussian";
    // Mitchell's samples, of weight +-1.145, are noisier: more of them for the same power.
    EXPECT_LT(worst_z(FC_FILTER_MITCHELL, FC_FILTER_MITCHELL, 0.0f, 8192), 5.0) << "mitchell";
}

TEST(FilterRender, ZTestTellsFiltersApart) {
    // The test has the power to see a wrong filter: a tent render is far from the box's profile.
    EXPECT_GT(worst_z(FC_FILTER_TENT, FC_FILTER_BOX, 0.0f, 2048), 10.0);
    EXPECT_GT(worst_z(FC_FILTER_MITCHELL, FC_FILTER_TENT, 2.0f, 2048), 10.0);
}

TEST(FilterRender, MitchellNegativeLobesUndershoot) {
    // Just outside the edge the Mitchell filter's negative lobe makes the pixel negative.
    const std::vector<double> col = column_means(render(half_plane_scene(FC_FILTER_MITCHELL, 0.0f, 2048)));
    EXPECT_LT(col[14], 0.0) << "the column whose centre is 1.8 pixels left of the edge";
    EXPECT_GT(col[18], kRadiance) << "the column whose centre is 2.2 pixels right of the edge overshoots";
}

// A perspective camera 10 units from a half-plane edge at x = 0.1 (inside a column near
// the image's centre: a sharp edge leaves one partly lit pixel), with a thin lens of radius `aperture` focused at
// `focus`: how many columns of the middle row are partly lit (the edge's width in pixels).
int edge_width(float plane_distance, float aperture, float focus) {
    Scene scene = half_plane_scene(FC_FILTER_BOX, 0.0f, 256);
    scene.vertices.clear();
    scene.shading.clear();
    add_quad(scene, glm::vec3(0.1f, -100.0f, -plane_distance), glm::vec3(100.0f, 0.0f, 0.0f),
             glm::vec3(0.0f, 200.0f, 0.0f), 0);
    build_lights(scene);
    scene.camera.projection = FC_PROJECTION_PERSPECTIVE;
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fov_y_degrees = 10.0f;
    scene.camera.aperture = aperture;
    scene.camera.focus_distance = focus;
    scene.settings.width = 64;
    scene.settings.height = 8;
    scene.settings.sampler = FC_SAMPLER_SOBOL;
    const std::vector<float> img = render(scene);
    int partial = 0;
    for (int x = 0; x < 64; ++x) {
        const float v = img[3 * (std::size_t(4) * 64 + x)];
        partial += double(v) > 0.02 * kRadiance && double(v) < 0.98 * kRadiance;
    }
    return partial;
}

TEST(FilterRender, ThinLensBlursOnlyOffTheFocusPlane) {
    EXPECT_LE(edge_width(10.0f, 0.0f, 0.0f), 2) << "pinhole";
    EXPECT_LE(edge_width(10.0f, 0.2f, 10.0f), 2) << "on the plane of focus";
    // Focused at 5, a lens of radius 1: the circle of confusion on the plane at 10 has
    // radius 1 * (10 - 5) / 5 = 1 unit, and a pixel there spans 2 * 10 * tan(5 deg) / 8 =
    // 0.219 units, so the edge spreads over a disk of diameter 9.1 pixels (8.2 of them
    // between 2% and 98%, plus up to a pixel at each end).
    const int blurred = edge_width(10.0f, 1.0f, 5.0f);
    EXPECT_GE(blurred, 7);
    EXPECT_LE(blurred, 11);
}

}  // namespace
}  // namespace facet
