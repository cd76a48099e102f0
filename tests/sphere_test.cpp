// Analytic spheres on the real kernels (kernels/trace/sphere.cl, kernels/lights/sphere_light.cl):
// roots against the closed form in double precision (far away, grazing, from inside, far
// from the origin), the spheres' tree against brute force, rays bouncing inside a glass
// sphere that never meet the surface they leave, the sphere light's density, and renders
// against analytic answers (furnaces, a plane under a sphere light, a mirror sphere that
// shows no facets). Suite Sphere; the renders are in the render tier (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include <glm/geometric.hpp>

#include "host/bvh/bvh.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/bvh/sphere_bvh.hpp"
#include "host/util/vec3.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/scene_test_util.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

constexpr double kPiD = 3.14159265358979323846;

cl::Program& kernels() { return test::program("kernels/test/sphere_kernels.cl"); }

template <typename T>
cl::Buffer buffer(const std::vector<T>& v) {
    return cl::Buffer(test::context().context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(T),
                      const_cast<T*>(v.data()));
}

template <typename T>
std::vector<T> read(const cl::Buffer& b, std::size_t n) {
    std::vector<T> out(n);
    test::context().queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(T), out.data());
    return out;
}

void run(cl::Kernel& k, std::size_t n) {
    test::context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    test::context().queue().finish();
}

cl_float4 f4(glm::dvec3 v, double w = 0.0) { return cl_float4{{float(v.x), float(v.y), float(v.z), float(w)}}; }
glm::dvec3 d3(const cl_float4& v) { return glm::dvec3(v.s[0], v.s[1], v.s[2]); }

// The roots of |o + t d - c| = r in double precision from the float inputs (d need not be unit).
bool exact_roots(glm::dvec3 c, double r, glm::dvec3 o, glm::dvec3 d, double* t0, double* t1) {
    const glm::dvec3 f = o - c;
    const double a = glm::dot(d, d), b = glm::dot(f, d);
    const glm::dvec3 l = f - (b / a) * d;
    const double disc = r * r - glm::dot(l, l);
    if (disc < 0.0) return false;
    const double q = -(b + std::copysign(std::sqrt(a * disc), b));
    const double cc = glm::dot(f, f) - r * r;
    *t0 = std::min(cc / q, q / a);
    *t1 = std::max(cc / q, q / a);
    return true;
}

struct Rays {
    std::vector<cl_float4> o, d;
};

// The kernel's roots of each ray against sphere (c, r), and the largest error of the hits
// against the exact roots, in units of r (|d| = 1). Misses where double hits, or hits where
// it misses, count in *wrong.
double root_error(glm::dvec3 c, float r, const Rays& rays, int* wrong) {
    cl::Kernel k(kernels(), "sphere_roots_batch");
    cl::Buffer o = buffer(rays.o), d = buffer(rays.d),
               out(test::context().context(), CL_MEM_WRITE_ONLY, rays.o.size() * sizeof(cl_float2));
    k.setArg(0, f4(c, r));
    k.setArg(1, o);
    k.setArg(2, d);
    k.setArg(3, out);
    run(k, rays.o.size());
    const std::vector<cl_float2> t = read<cl_float2>(out, rays.o.size());
    const glm::dvec3 cf = d3(f4(c));
    double worst = 0.0;
    *wrong = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        double e0, e1;
        const bool hit = exact_roots(cf, double(r), d3(rays.o[i]), d3(rays.d[i]), &e0, &e1);
        const bool got = !std::isnan(t[i].s[0]);
        if (hit != got) {
            ++*wrong;
            continue;
        }
        if (!hit) continue;
        worst = std::max(
            {worst, std::abs(double(t[i].s[0]) - e0) / double(r), std::abs(double(t[i].s[1]) - e1) / double(r)});
    }
    return worst;
}

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        glm::dvec3 v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-6) return glm::normalize(v);
    }
}

// `n` spheres with centres uniform in [-10, 10]^3 and radii uniform in [0.05, 1.5], drawn
// from `rng` (which the caller goes on using).
std::vector<FcSphere> random_spheres(std::mt19937& rng, std::size_t n) {
    std::uniform_real_distribution<float> u(-10.0f, 10.0f), ur(0.05f, 1.5f);
    std::vector<FcSphere> spheres(n);
    for (FcSphere& s : spheres) {
        for (float& x : s.center) x = u(rng);
        s.radius = ur(rng);
    }
    return spheres;
}

// Rays from distance `dist` (in radii) toward sphere (c, r), aimed at points of the disk
// through its centre at impact parameters b / r in [b_lo, b_hi].
Rays aimed_rays(glm::dvec3 c, double r, double dist, double b_lo, double b_hi, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Rays rays;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 axis = random_unit(rng);
        glm::dvec3 side = glm::normalize(glm::cross(axis, random_unit(rng)));
        const double b = r * (b_lo + (b_hi - b_lo) * u(rng));
        const glm::dvec3 o = c + dist * r * axis + b * side;
        rays.o.push_back(f4(o));
        rays.d.push_back(f4(-axis));
    }
    return rays;
}

TEST(Sphere, RootsFromFarAway) {
    // 1e4 radii away: b^2 - 4ac cancels ~8 decimal digits there and misses or misplaces
    // most hits; the closest-point discriminant keeps the hit within ~1e-3 r.
    int wrong = 0;
    const double err =
        root_error(glm::dvec3(0.0), 1.0f, aimed_rays(glm::dvec3(0.0), 1.0, 1e4, 0.0, 0.99, 4096, 1), &wrong);
    std::printf("[ sphere   ] 1e4 radii away: largest root error %.3g r, %d wrong hit/miss\n", err, wrong);
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(err, 4e-3);
}

TEST(Sphere, RootsGrazing) {
    // Impact parameters within 1e-3 of the radius, from 10 radii: the roots close up.
    int wrong = 0;
    const double err =
        root_error(glm::dvec3(0.0), 1.0f, aimed_rays(glm::dvec3(0.0), 1.0, 10.0, 0.999, 0.99999, 4096, 2), &wrong);
    std::printf("[ sphere   ] grazing: largest root error %.3g r, %d wrong hit/miss\n", err, wrong);
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(err, 2e-3);
}

TEST(Sphere, RootsFromInside) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Rays rays;
    for (int i = 0; i < 4096; ++i) {
        rays.o.push_back(f4(0.999 * std::cbrt(u(rng)) * random_unit(rng)));
        rays.d.push_back(f4(random_unit(rng)));
    }
    int wrong = 0;
    const double err = root_error(glm::dvec3(0.0), 1.0f, rays, &wrong);
    std::printf("[ sphere   ] from inside: largest root error %.3g r\n", err);
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(err, 1e-5);
}

TEST(Sphere, RootsFarFromTheOrigin) {
    // A unit sphere 1e4 units from the origin seen from 5 radii: the root is as good as the
    // coordinates' own precision (ulp(1e4) = 1e-3) allows.
    const glm::dvec3 c(1e4, -7e3, 5e3);
    int wrong = 0;
    const double err = root_error(c, 1.0f, aimed_rays(c, 1.0, 5.0, 0.0, 0.99, 4096, 4), &wrong);
    std::printf("[ sphere   ] at 1e4 from the origin: largest root error %.3g r\n", err);
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(err, 1e-2);
}

TEST(Sphere, OffsetOriginStepsAsNextafter) {
    // sphere_offset_origin steps the three coordinates by bit arithmetic: the same bits as
    // nextafter toward n's sign, with points on and off zero (either sign), normals with zero
    // or negative-zero components, and errors of 0 (the step alone) to large.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float picks[] = {0.0f, -0.0f, 1e-38f, -1e-38f, 1e-45f, -1e-45f, 1.0f, -3.5f, 1e30f, -2e-30f};
    std::vector<cl_float4> p, err, n;
    for (int i = 0; i < 4096; ++i) {
        cl_float4 a{}, e{}, m{};
        for (int k = 0; k < 3; ++k) {
            a.s[k] = (i % 3 == 0) ? picks[(i / 3 + k) % 10] : u(rng) * std::pow(10.0f, float(i % 7) - 3.0f);
            m.s[k] = (i % 5 == k) ? ((i & 8) ? -0.0f : 0.0f) : u(rng);
            e.s[k] = (i % 4 == 0) ? 0.0f : 1e-7f * std::abs(u(rng));
        }
        p.push_back(a);
        err.push_back(e);
        n.push_back(m);
    }
    cl::Kernel k(kernels(), "sphere_offset_batch");
    cl::Buffer pb = buffer(p), eb = buffer(err), nb = buffer(n);
    cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, 2 * p.size() * sizeof(cl_float4));
    k.setArg(0, pb);
    k.setArg(1, eb);
    k.setArg(2, nb);
    k.setArg(3, out);
    run(k, p.size());
    const std::vector<cl_float4> got = read<cl_float4>(out, 2 * p.size());
    int differ = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (std::memcmp(&got[2 * i], &got[2 * i + 1], 3 * sizeof(float)) != 0) ++differ;
    EXPECT_EQ(differ, 0) << "of " << p.size() << " offset origins";
}

// Nearest hits of the spheres' tree of node width `width` against brute force.
void tree_matches_brute_force(int width) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    const std::vector<FcSphere> spheres = random_spheres(rng, 300);
    const SphereBvh tree = build_sphere_bvh(spheres, width);
    ASSERT_EQ(tree.spheres.size(), spheres.size());
    Rays rays;
    for (int i = 0; i < 4096; ++i) {
        rays.o.push_back(f4(glm::dvec3(u(rng), u(rng), u(rng)) * 1.5));
        rays.d.push_back(f4(random_unit(rng), i % 4 == 0 ? 5.0 : 1e30));
    }
    cl::Kernel k(test::program(width == 8 ? "kernels/test/sphere_kernels8.cl" : "kernels/test/sphere_kernels.cl"),
                 "trace_spheres_batch");
    cl::Buffer nodes = buffer(tree.nodes), sph = buffer(tree.spheres), o = buffer(rays.o), d = buffer(rays.d);
    cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, rays.o.size() * sizeof(cl_float2));
    k.setArg(0, nodes);
    k.setArg(1, sph);
    k.setArg(2, o);
    k.setArg(3, d);
    k.setArg(4, out);
    run(k, rays.o.size());
    const std::vector<cl_float2> got = read<cl_float2>(out, rays.o.size());
    int mismatches = 0, hits = 0;
    for (std::size_t i = 0; i < rays.o.size(); ++i) {
        double best = double(rays.d[i].s[3]);
        int best_prim = -1;
        for (std::size_t j = 0; j < spheres.size(); ++j) {
            const FcSphere& s = spheres[j];
            double t0, t1;
            if (!exact_roots(glm::dvec3(s.center[0], s.center[1], s.center[2]), s.radius, d3(rays.o[i]), d3(rays.d[i]),
                             &t0, &t1))
                continue;
            const double t = t0 > 0.0 ? t0 : t1;
            if (t > 0.0 && t < best) best = t, best_prim = int(j);
        }
        int index;
        std::memcpy(&index, &got[i].s[1], sizeof index);
        const int prim = index >= 0 ? tree.spheres[std::size_t(index)].prim : -1;
        hits += prim >= 0;
        if (prim != best_prim || (prim >= 0 && std::abs(double(got[i].s[0]) - best) > 1e-4 * std::max(1.0, best)))
            ++mismatches;
    }
    std::printf("[ sphere   ] %d-wide tree of %zu node units: %d of %zu rays hit, %d differ from brute force\n", width,
                tree.nodes.size(), hits, rays.o.size(), mismatches);
    EXPECT_GT(hits, 500);
    EXPECT_EQ(mismatches, 0);
}

// The spheres' tree has the triangles' tree's node width: both widths.
TEST(Sphere, TreeMatchesBruteForce) {
    for (int width : {4, 8}) {
        SCOPED_TRACE(width);
        tree_matches_brute_force(width);
    }
}

TEST(Sphere, EmptyTreeIsNeverHit) {
    const SphereBvh tree = build_sphere_bvh({}, 4);
    ASSERT_EQ(tree.nodes.size(), 1u);
    for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(tree.nodes[0].count[c], 0);
        EXPECT_GT(tree.nodes[0].lo_x[c], tree.nodes[0].hi_x[c]);
    }
}

// Chains of rays entering a sphere, bouncing inside and leaving, each from the offset
// origin of the last hit: a leak is an inside ray that escapes or meets the surface it left,
// or a leaving ray that meets the sphere again.
TEST(Sphere, NoSelfHitInsideGlass) {
    struct Case {
        glm::dvec3 c;
        float r;
    };
    const Case cases[] = {{glm::dvec3(0.0), 1.0f},
                          {glm::dvec3(0.0), 1e-3f},
                          {glm::dvec3(0.0), 1e3f},
                          {glm::dvec3(0.3, -2.0, 1.0), 0.5f},
                          {glm::dvec3(1e4, 2e3, -5e3), 1.0f},
                          {glm::dvec3(-3e2, 0.0, 7.0), 50.0f}};
    const std::uint32_t bounces = 8;
    for (const Case& cs : cases) {
        const int n = 8192;
        Rays rays = aimed_rays(cs.c, double(cs.r), 3.0, 0.0, 0.999, n, 6);
        std::mt19937 rng(7);
        std::vector<cl_float4> inner, exits;
        for (std::uint32_t i = 0; i < n * bounces; ++i) inner.push_back(f4(random_unit(rng)));
        for (int i = 0; i < n; ++i) exits.push_back(f4(random_unit(rng)));
        cl::Kernel k(kernels(), "sphere_leaks");
        cl::Buffer o = buffer(rays.o), d = buffer(rays.d), in = buffer(inner), ex = buffer(exits);
        cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_int));
        k.setArg(0, f4(cs.c, cs.r));
        k.setArg(1, bounces);
        k.setArg(2, o);
        k.setArg(3, d);
        k.setArg(4, in);
        k.setArg(5, ex);
        k.setArg(6, out);
        run(k, std::size_t(n));
        const std::vector<cl_int> leaks = read<cl_int>(out, std::size_t(n));
        int missed = 0, leaked = 0;
        for (cl_int l : leaks) {
            if (l < 0) ++missed;
            else leaked += l;
        }
        std::printf("[ sphere   ] r %g at (%g, %g, %g): %d leaks in %d chains of %u bounces\n", double(cs.r), cs.c.x,
                    cs.c.y, cs.c.z, leaked, n, bounces);
        EXPECT_EQ(missed, 0);
        EXPECT_EQ(leaked, 0) << "r " << cs.r << " at " << cs.c.x;
    }
}

FcLight sphere_light(glm::vec3 c, float r, float orient = 1.0f) {
    FcLight l{};
    l.type = FC_LIGHT_SPHERE;
    store(l.p0, c);
    l.e1[0] = r;
    l.e1[1] = orient;
    l.area = float(4.0 * kPiD * double(r) * double(r));
    l.pick_pdf = 1.0f;
    return l;
}

// Integral of sphere_light_pdf over the directions from p, on a stratified grid in the cone
// of half-angle `cone` (radians) about the direction to the centre (pi: every direction).
double integrate_pdf(const FcLight& light, glm::dvec3 p, double cone, int n) {
    const glm::dvec3 c(light.p0[0], light.p0[1], light.p0[2]);
    const glm::dvec3 z = glm::length(c - p) > 0.0 ? glm::normalize(c - p) : glm::dvec3(0, 0, 1);
    const glm::dvec3 x = glm::normalize(glm::cross(std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), z));
    const glm::dvec3 y = glm::cross(z, x);
    const double one_minus_cos = 1.0 - std::cos(cone);
    std::vector<cl_float4> dirs;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double cos_t = 1.0 - one_minus_cos * (i + 0.5) / n, phi = 2.0 * kPiD * (j + 0.5) / n;
            const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
            dirs.push_back(f4(sin_t * std::cos(phi) * x + sin_t * std::sin(phi) * y + cos_t * z));
        }
    std::vector<FcLight> ls{light};
    cl::Kernel k(kernels(), "sphere_light_pdf_batch");
    cl::Buffer lb = buffer(ls), db = buffer(dirs);
    cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, dirs.size() * sizeof(float));
    k.setArg(0, lb);
    k.setArg(1, f4(p));
    k.setArg(2, db);
    k.setArg(3, out);
    run(k, dirs.size());
    double sum = 0.0;
    for (float v : read<float>(out, dirs.size())) sum += double(v);
    return sum / double(dirs.size()) * 2.0 * kPiD * one_minus_cos;
}

TEST(Sphere, LightPdfIntegratesToOne) {
    const FcLight l = sphere_light(glm::vec3(0.5f, 1.0f, -2.0f), 0.75f);
    const glm::dvec3 c(0.5, 1.0, -2.0);
    // From outside at 1.05, 3, 20 and 2000 radii (the last cone below 1.5 degrees), and from
    // inside (area sampling).
    for (double dist : {1.05, 3.0, 20.0, 2000.0}) {
        const double cone = 1.2 * std::asin(std::min(1.0, 1.0 / dist));
        const double total = integrate_pdf(l, c + dist * 0.75 * glm::dvec3(0.6, 0.0, 0.8), cone, 1024);
        std::printf("[ sphere   ] light pdf from %g radii integrates to %.5f\n", dist, total);
        EXPECT_NEAR(total, 1.0, 2e-3) << dist << " radii";
    }
    const double inside = integrate_pdf(l, c + glm::dvec3(0.2, -0.3, 0.1), kPiD, 1024);
    std::printf("[ sphere   ] light pdf from inside integrates to %.5f\n", inside);
    EXPECT_NEAR(inside, 1.0, 2e-3);
}

TEST(Sphere, LightSamplesLieOnTheVisibleCap) {
    const FcLight l = sphere_light(glm::vec3(0.0f), 2.0f);
    std::vector<FcLight> ls{l};
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<cl_float2> us(4096);
    for (cl_float2& x : us) x = cl_float2{{u(rng), u(rng)}};
    for (double dist : {1.01, 4.0, 3000.0}) {
        const glm::dvec3 p = dist * 2.0 * glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
        cl::Kernel k(kernels(), "sphere_light_sample_batch");
        cl::Buffer lb = buffer(ls), ub = buffer(us);
        cl::Buffer points(test::context().context(), CL_MEM_WRITE_ONLY, us.size() * sizeof(cl_float4));
        cl::Buffer check(test::context().context(), CL_MEM_WRITE_ONLY, us.size() * sizeof(cl_float4));
        k.setArg(0, lb);
        k.setArg(1, f4(p));
        k.setArg(2, ub);
        k.setArg(3, points);
        k.setArg(4, check);
        run(k, us.size());
        const std::vector<cl_float4> pt = read<cl_float4>(points, us.size()), ck = read<cl_float4>(check, us.size());
        int off = 0, hidden = 0, pdf_differs = 0;
        for (std::size_t i = 0; i < us.size(); ++i) {
            if (!(ck[i].s[0] < 1e-5f)) ++off;
            if (!(ck[i].s[2] > -1e-3f)) ++hidden;
            // The point reached by the ray toward it has the density the sample reported (the
            // ray may meet the near side first at the silhouette's edge, within rounding).
            if (!(std::abs(ck[i].s[1] - pt[i].s[3]) <= 1e-3f * pt[i].s[3])) ++pdf_differs;
        }
        std::printf("[ sphere   ] %zu light samples from %g radii: %d off the sphere, %d facing away, %d pdfs differ\n",
                    us.size(), dist, off, hidden, pdf_differs);
        EXPECT_EQ(off, 0);
        EXPECT_EQ(hidden, 0);
        EXPECT_EQ(pdf_differs, 0);
    }
}

TEST(Sphere, UvAndTangentFollowTheParametrisation) {
    // u = phi / 2pi about +y, v = theta / pi from the +y pole: n = (sin theta cos phi,
    // cos theta, sin theta sin phi), and the tangent is dn/dphi's direction.
    std::mt19937 rng(9);
    std::vector<cl_float4> normals;
    for (int i = 0; i < 4096; ++i) normals.push_back(f4(random_unit(rng)));
    cl::Kernel k(kernels(), "sphere_uv_batch");
    cl::Buffer nb = buffer(normals);
    cl::Buffer uv(test::context().context(), CL_MEM_WRITE_ONLY, normals.size() * sizeof(cl_float2));
    cl::Buffer tb(test::context().context(), CL_MEM_WRITE_ONLY, normals.size() * sizeof(cl_float4));
    k.setArg(0, nb);
    k.setArg(1, uv);
    k.setArg(2, tb);
    run(k, normals.size());
    const std::vector<cl_float2> got = read<cl_float2>(uv, normals.size());
    const std::vector<cl_float4> tangents = read<cl_float4>(tb, normals.size());
    double worst_n = 0.0, worst_t = 0.0;
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const double u = got[i].s[0], v = got[i].s[1];
        ASSERT_TRUE(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0) << u << " " << v;
        const double phi = 2.0 * kPiD * u, theta = kPiD * v;
        const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        worst_n = std::max(worst_n, glm::length(n - d3(normals[i])));
        worst_t = std::max(worst_t, glm::length(glm::dvec3(-std::sin(phi), 0.0, std::cos(phi)) - d3(tangents[i])));
    }
    std::printf("[ sphere   ] uv: normal rebuilt within %.2g, tangent within %.2g\n", worst_n, worst_t);
    EXPECT_LT(worst_n, 1e-5);
    EXPECT_LT(worst_t, 1e-4);
}

TEST(Sphere, JsonSpheresAreAnalytic) {
    test::TempDir d;
    const Scene a = load_scene(test::scene(d, "a.json", R"("shapes": [{"type": "sphere", "center": [0, 1, 0],
        "radius": 0.5, "subdivisions": 4}])"));
    ASSERT_EQ(a.spheres.size(), 1u);
    EXPECT_EQ(a.triangle_count(), 0u);
    EXPECT_EQ(a.spheres[0].radius, 0.5f);
    EXPECT_EQ(a.spheres[0].flags, 0);
    EXPECT_NE(scene_features(a) & (1u << 10), 0u) << "FC_HAS_SPHERES";
    const Scene t = load_scene(test::scene(d, "t.json", R"("shapes": [{"type": "sphere", "center": [0, 1, 0],
        "radius": 0.5, "subdivisions": 1, "tessellate": true, "inward": true}])"));
    EXPECT_TRUE(t.spheres.empty());
    EXPECT_EQ(t.triangle_count(), 80u);
    EXPECT_EQ(scene_features(t) & (1u << 10), 0u) << "a scene without spheres builds no sphere code";
    const Bounds b = scene_bounds(a);
    EXPECT_EQ(b.lo.y, 0.5f);
    EXPECT_EQ(b.hi.y, 1.5f);
}

// --- renders (the render tier) ----------------------------------------------------------

std::vector<float> render(Scene& scene, std::uint32_t spp, double* rejected = nullptr,
                          Renderer::Halves* halves = nullptr) {
    build_lights(scene);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp, 16);
    if (halves) *halves = r.halves();
    return r.image(rejected);
}

Scene sphere_in_view(const Material& m, float fov = 40.0f) {
    Scene scene;
    add_material(scene, m, "m");
    add_analytic_sphere(scene, glm::vec3(0.0f), 1.0f, 0, false);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 3.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fov_y_degrees = fov;
    scene.settings.width = scene.settings.height = 24;
    return scene;
}

TEST(Sphere, DiffuseFurnace) {
    // A white Lambertian sphere in a constant environment L reflects exactly L everywhere.
    Material m = make_material("lambert");
    m.diffuse = glm::vec3(1.0f);
    Scene scene = sphere_in_view(m);
    scene.environment = constant_environment(glm::vec3(0.7f));
    scene.settings.max_depth = 64;
    double rejected = -1.0;
    const std::vector<float> img = render(scene, 64, &rejected);
    double worst = 0.0, mean = 0.0;
    for (float v : img) {
        worst = std::max(worst, std::abs(double(v) - 0.7));
        mean += double(v) / double(img.size());
    }
    std::printf("[ sphere   ] white diffuse sphere in L = 0.7: mean %.5f, worst pixel error %.3g\n", mean, worst);
    EXPECT_EQ(rejected, 0.0);
    EXPECT_NEAR(mean, 0.7, 0.002);
    EXPECT_LT(worst, 0.07);
}

TEST(Sphere, GlassFurnace) {
    // Clear glass in a white environment: every path leaves with weight 1 (as GlassRender's
    // icosphere, without the facets' trapped paths), so a leak through the surface or a
    // self-hit shows as a pixel off 1.
    for (float eta : {1.5f, 2.4f}) {
        Material m = make_material("dielectric");
        m.ior = eta;
        Scene scene = sphere_in_view(m, 45.0f);
        scene.environment = constant_environment(glm::vec3(1.0f));
        scene.settings.max_depth = 1 << 20;
        scene.settings.rr_depth = 1 << 20;
        double rejected = -1.0;
        const std::vector<float> img = render(scene, 32, &rejected);
        double worst = 0.0;
        for (float v : img) worst = std::max(worst, std::abs(double(v) - 1.0));
        std::printf("[ sphere   ] glass sphere eta %g in white: worst pixel error %.3g\n", double(eta), worst);
        EXPECT_EQ(rejected, 0.0);
        EXPECT_LT(worst, 1e-3) << "eta " << eta;
    }
}

TEST(Sphere, EmissiveEnclosureFurnace) {
    // The camera inside an inward-facing sphere of albedo a and emission E (scenes/
    // furnace_sphere.json): radiance E / (1 - a) everywhere; the light is sampled by area
    // from inside.
    Scene scene;
    Material m = make_material("lambert");
    m.diffuse = glm::vec3(0.5f);
    m.emission = glm::vec3(0.5f);
    add_material(scene, m, "furnace");
    add_analytic_sphere(scene, glm::vec3(0.0f), 1.0f, 0, true);
    scene.camera.eye = glm::vec3(0.2f, -0.1f, 0.3f);
    scene.camera.target = glm::vec3(0.2f, -0.1f, -1.0f);
    scene.camera.fov_y_degrees = 60.0f;
    scene.settings.width = scene.settings.height = 16;
    scene.settings.max_depth = 64;
    double rejected = -1.0;
    const std::vector<float> img = render(scene, 256, &rejected);
    double mean = 0.0;
    for (float v : img) mean += double(v);
    mean /= double(img.size());
    std::printf("[ sphere   ] emissive enclosure: mean %.4f (expected 1)\n", mean);
    EXPECT_EQ(rejected, 0.0);
    EXPECT_NEAR(mean, 1.0, 0.01);
}

TEST(Sphere, LightAbovePlaneMatchesClosedForm) {
    // A sphere of radiance Le, radius r, centre height h above a Lambertian plane of albedo
    // rho: wholly above the horizon it is seen as a cap of solid angle 2 pi (1 - cos), and the
    // plane's radiance at distance d from the centre is rho Le r^2 h / d^3.
    const float rho = 0.6f, le = 2.0f, r = 0.4f, h = 1.0f;
    const int n = 32;
    for (int strategy : {FC_STRATEGY_MIS, FC_STRATEGY_LIGHT, FC_STRATEGY_BSDF}) {
        Scene scene;
        Material plane = make_material("lambert");
        plane.diffuse = glm::vec3(rho);
        add_material(scene, plane, "plane");
        Material light = make_material("lambert");
        light.diffuse = glm::vec3(0.0f);
        light.emission = glm::vec3(le);
        add_material(scene, light, "light");
        test::add_plane_seen_from_above(scene, 0, n);
        add_analytic_sphere(scene, glm::vec3(0.0f, h, 0.0f), r, 1, false);
        scene.settings.strategy = strategy;
        Renderer::Halves halves;
        render(scene, 64, nullptr, &halves);
        const test::PixelEstimates est = test::pixel_estimates(halves);
        double z_sum = 0.0, var_sum = 0.0, worst_z = 0.0;
        int pixels = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double x = -2.0 + 4.0 * (i + 0.5) / n, z = -2.0 + 4.0 * (j + 0.5) / n;
                if (x * x + z * z < 1.7 * double(r) * double(r)) continue;  // the sphere is in front
                // The closed form averaged over the pixel (the camera jitters within it).
                double expected = 0.0;
                for (int a = 0; a < 4; ++a)
                    for (int b = 0; b < 4; ++b) {
                        const double px = x + 4.0 / n * ((a + 0.5) / 4 - 0.5), pz = z + 4.0 / n * ((b + 0.5) / 4 - 0.5);
                        const double d = std::sqrt(px * px + pz * pz + double(h) * double(h));
                        expected += double(rho) * double(le) * double(r) * double(r) * double(h) / (d * d * d) / 16.0;
                    }
                const std::size_t k = 3 * std::size_t(j * n + i);
                const double diff = est.mean[k] - expected, var = std::max(est.var[k], 1e-12);
                z_sum += diff;
                var_sum += var;
                worst_z = std::max(worst_z, std::abs(diff) / std::sqrt(var + 1e-4 * expected * expected));
                ++pixels;
            }
        const double z = z_sum / std::sqrt(var_sum);
        std::printf("[ sphere   ] plane under a sphere light, strategy %d: z of the sum %.2f, worst pixel |z| %.2f\n",
                    strategy, z, worst_z);
        EXPECT_GT(pixels, 800);
        EXPECT_LT(std::abs(z), 4.0) << "strategy " << strategy;
        // BSDF sampling alone rarely finds the small light: its pixels are too heavy-tailed for a
        // per-pixel z from two halves.
        if (strategy != FC_STRATEGY_BSDF) {
            EXPECT_LT(worst_z, 6.0) << "strategy " << strategy;
        }
    }
}

// A radiance linear in the direction (so bilinear filtering of the map is exact up to its
// curvature across a texel): r, g, b = 0.5 + 0.4 (x, y, z).
glm::dvec3 smooth_sky(glm::dvec3 w) { return glm::dvec3(0.5) + 0.4 * w; }

TEST(Sphere, MirrorShowsNoFaceting) {
    // A mirror sphere under a smooth environment, seen by an orthographic camera: each pixel
    // is the environment along the reflection of the view ray about the exact normal,
    // averaged over the pixel. An icosphere's flat facets tilt the normals by degrees (at 5
    // subdivisions, as the demo scenes had, the worst pixel is off by several times the bound).
    const int w = 512, hgt = 256;
    std::vector<float> texels;
    for (int j = 0; j < hgt; ++j)
        for (int i = 0; i < w; ++i) {
            const double phi = 2.0 * kPiD * (i + 0.5) / w, theta = kPiD * (j + 0.5) / hgt;
            const glm::dvec3 dir(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            const glm::dvec3 l = smooth_sky(dir);
            texels.insert(texels.end(), {float(l.x), float(l.y), float(l.z)});
        }
    Material m = make_material("conductor");
    m.fresnel = FC_FRESNEL_ONE;
    m.alpha_x = m.alpha_y = 0.0f;
    Scene scene;
    add_material(scene, m, "mirror");
    add_analytic_sphere(scene, glm::vec3(0.0f), 1.0f, 0, false);
    std::vector<std::string> warnings;
    scene.environment = environment_from_pixels(w, hgt, texels, glm::vec3(1.0f), glm::mat3(1.0f), "sky", warnings);
    const int n = 96;
    const double half = 1.2;
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.eye = glm::vec3(0, 0, 5);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.ortho_height = float(2.0 * half);
    scene.settings.width = scene.settings.height = n;
    scene.settings.max_depth = 4;
    const std::vector<float> img = render(scene, 64);
    double worst = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // Away from the silhouette, where the reflection turns fast within a pixel.
            const double cx = -half + 2.0 * half * (i + 0.5) / n, cy = half - 2.0 * half * (j + 0.5) / n;
            if (cx * cx + cy * cy > 0.85 * 0.85) continue;
            glm::dvec3 expected(0.0);
            const int s = 8;
            for (int a = 0; a < s; ++a)
                for (int b = 0; b < s; ++b) {
                    const double x = cx + 2.0 * half / n * ((a + 0.5) / s - 0.5);
                    const double y = cy + 2.0 * half / n * ((b + 0.5) / s - 0.5);
                    const glm::dvec3 nn(x, y, std::sqrt(1.0 - x * x - y * y));
                    const glm::dvec3 d(0, 0, -1);
                    expected += smooth_sky(d - 2.0 * glm::dot(d, nn) * nn) / double(s * s);
                }
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(double(img[3 * std::size_t(j * n + i) + c]) - expected[c]));
        }
    std::printf("[ sphere   ] mirror sphere: worst pixel error %.4f against the exact normals\n", worst);
    EXPECT_LT(worst, 0.0015);
}

}  // namespace
}  // namespace facet
