// Area lights sampled by solid angle (kernels/lights/spherical_triangle.cl, area.cl):
// the spherical-triangle sampler is uniform in solid angle (chi-square over sub-
// triangles), its solid angle is exact, and renders with light sampling, BSDF sampling
// and MIS agree near a light, where the solid-angle sampler is the one in use.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "tests/chi2_test_util.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

using D3 = std::array<double, 3>;
D3 sub(D3 a, D3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
D3 mid(D3 a, D3 b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }
double dot(D3 a, D3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 cross(D3 a, D3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
D3 unit(D3 a) {
    double l = std::sqrt(dot(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
}

// Van Oosterom and Strackee in double: the reference solid angle.
double solid_angle(D3 p, D3 v0, D3 v1, D3 v2) {
    D3 a = unit(sub(v0, p)), b = unit(sub(v1, p)), c = unit(sub(v2, p));
    return 2.0 * std::atan2(std::fabs(dot(a, cross(b, c))), 1.0 + dot(a, b) + dot(b, c) + dot(c, a));
}

struct Tri {
    D3 v0, v1, v2;
};
// The triangle cut into 4^levels similar sub-triangles.
std::vector<Tri> subdivide(Tri t, int levels) {
    std::vector<Tri> out{t};
    for (int l = 0; l < levels; ++l) {
        std::vector<Tri> next;
        for (const Tri& s : out) {
            D3 a = mid(s.v0, s.v1), b = mid(s.v1, s.v2), c = mid(s.v2, s.v0);
            next.insert(next.end(), {{s.v0, a, c}, {a, s.v1, b}, {c, b, s.v2}, {a, b, c}});
        }
        out = next;
    }
    return out;
}

// Which sub-triangle the ray p + t w crosses (Moeller-Trumbore), or -1.
int hit_index(D3 p, D3 w, const std::vector<Tri>& tris) {
    for (std::size_t i = 0; i < tris.size(); ++i) {
        D3 e1 = sub(tris[i].v1, tris[i].v0), e2 = sub(tris[i].v2, tris[i].v0), q = cross(w, e2);
        double det = dot(e1, q);
        if (std::fabs(det) < 1e-300) continue;
        D3 s = sub(p, tris[i].v0);
        double u = dot(s, q) / det;
        D3 r = cross(s, e1);
        double v = dot(w, r) / det, t = dot(e2, r) / det;
        const double eps = 1e-5;  // float directions
        if (u >= -eps && v >= -eps && u + v <= 1.0 + eps && t > 0.0) return int(i);
    }
    return -1;
}

TEST(AreaLight, SphericalTriangleIsUniformInSolidAngle) {
    struct Case {
        const char* what;
        D3 p;
        Tri tri;
    };
    const Tri t{{-1.0, 0.0, 1.0}, {1.0, -0.5, 1.0}, {0.3, 1.0, 1.0}};
    const Case cases[] = {
        // Solid angles from 0.012 sr (FC_SPHERICAL_SAMPLE_MIN is 0.01) to 6 sr.
        {"overhead, close (1.27 sr)", {0.0, 0.0, 0.2}, t},
        {"overhead, far (0.016 sr)", {0.0, 0.0, -8.0}, t},
        {"grazing (0.024 sr)", {2.0, 0.0, 0.9}, t},
        {"grazing, beside it (0.012 sr)", {1.3, 0.2, 0.99}, t},
        {"almost on it (6.17 sr)", {0.2, 0.1, 0.99}, t},
        {"thin sliver (0.017 sr)", {0.0, 0.0, 0.0}, {{-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {0.0, 0.02, 1.0}}},
    };
    const std::uint32_t n = 200000;
    ClContext& ctx = test::context();
    const double level = test::chi2::sidak(0.01, int(std::size(cases)));
    for (const Case& c : cases) {
        auto f4 = [](D3 v) { return cl_float4{{float(v[0]), float(v[1]), float(v[2]), 0.0f}}; };
        cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, n * 4 * sizeof(float));
        cl::Buffer omega(ctx.context(), CL_MEM_WRITE_ONLY, sizeof(float));
        cl::Kernel k(test::program("kernels/test/light_kernels.cl"), "spherical_triangle_samples");
        k.setArg(0, f4(c.p)), k.setArg(1, f4(c.tri.v0)), k.setArg(2, f4(c.tri.v1)), k.setArg(3, f4(c.tri.v2));
        k.setArg(4, std::uint32_t(7)), k.setArg(5, out), k.setArg(6, omega);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
        std::vector<float> w(4 * n);
        float om = 0.0f;
        ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, w.size() * sizeof(float), w.data());
        ctx.queue().enqueueReadBuffer(omega, CL_TRUE, 0, sizeof(float), &om);

        const double total = solid_angle(c.p, c.tri.v0, c.tri.v1, c.tri.v2);
        EXPECT_NEAR(double(om), total, 1e-5 * total + 1e-7) << c.what;
        const std::vector<Tri> cells = subdivide(c.tri, 3);  // 64 cells
        std::vector<double> expected(cells.size());
        for (std::size_t i = 0; i < cells.size(); ++i)
            expected[i] = double(n) * solid_angle(c.p, cells[i].v0, cells[i].v1, cells[i].v2) / total;
        std::vector<double> count(cells.size(), 0.0);
        std::uint32_t missed = 0, refused = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (w[4 * i + 3] == 0.0f) {
                ++refused;
                continue;
            }
            int h = hit_index(c.p, {double(w[4 * i]), double(w[4 * i + 1]), double(w[4 * i + 2])}, cells);
            if (h < 0) ++missed;
            else count[std::size_t(h)] += 1.0;
        }
        EXPECT_EQ(refused, 0u) << c.what;
        EXPECT_LE(missed, n / 10000) << c.what << ": directions that miss the triangle";
        double chi2 = 0.0;
        for (std::size_t i = 0; i < cells.size(); ++i)
            chi2 += (count[i] - expected[i]) * (count[i] - expected[i]) / expected[i];
        const double dof = double(cells.size() - 1);
        const double p = test::chi2::gamma_q(0.5 * dof, 0.5 * chi2);
        EXPECT_GT(p, level) << c.what << ": chi2 " << chi2 << " over " << dof << " degrees of freedom";
    }
}

// A white Lambertian floor under a small emitting triangle 0.15 above it: light
// sampling, BSDF sampling and MIS estimate the same image (the MIS weight uses the
// solid-angle density that light sampling used).
TEST(AreaLight, StrategiesAgreeNearTheLight) {
    Scene scene;
    Material floor = default_material();
    floor.diffuse = glm::vec3(0.8f);
    Material lamp = default_material();
    lamp.diffuse = glm::vec3(0.0f);
    lamp.emission = glm::vec3(5.0f);
    const int m_floor = add_material(scene, floor, "floor"), m_lamp = add_material(scene, lamp, "lamp");
    add_quad(scene, glm::vec3(-1.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(2.0f, 0.0f, 0.0f), m_floor);
    add_triangle(scene, glm::vec3(-0.2f, 0.15f, -0.2f), glm::vec3(0.25f, 0.15f, -0.1f), glm::vec3(0.0f, 0.15f, 0.25f),
                 glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), m_lamp);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 2.5f, 0.01f);
    scene.camera.target = glm::vec3(0.0f);
    scene.settings.width = scene.settings.height = 24;
    scene.settings.max_depth = 1;
    Bvh bvh = build_bvh(scene.vertices);
    const std::uint32_t spp = 256;
    struct Result {
        double sum = 0.0, var = 0.0;
    };
    auto render = [&](int strategy) {
        scene.settings.strategy = strategy;
        Renderer r(test::context(), scene, bvh);
        r.render(spp);
        const test::PixelEstimates e = test::pixel_estimates(r.halves());
        Result out;
        for (std::size_t i = 0; i < e.mean.size(); ++i) out.sum += e.mean[i], out.var += e.var[i];
        return out;
    };
    const Result mis = render(FC_STRATEGY_MIS), light = render(FC_STRATEGY_LIGHT), bsdf = render(FC_STRATEGY_BSDF);
    EXPECT_GT(mis.sum, 0.0);
    for (const Result* other : {&light, &bsdf}) {
        const double z = (other->sum - mis.sum) / std::sqrt(other->var + mis.var);
        EXPECT_LT(std::fabs(z), 4.0) << (other == &light ? "light" : "bsdf") << " sampling against MIS: " << other->sum
                                     << " vs " << mis.sum;
    }
    EXPECT_LT(light.var, bsdf.var) << "solid-angle light sampling should be the better strategy here";
}

}  // namespace
}  // namespace facet
