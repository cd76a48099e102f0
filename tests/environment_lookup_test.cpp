// The environment map's direction <-> (u, v) mapping (env_map_dir_to_uv and
// env_uv_to_map_dir in kernels/lights/environment.cl, computed with kernels/util/trig.cl)
// on the device against double precision over the whole sphere, poles and seam included:
// the (u, v) of a direction, the texel it falls in, the direction of a (u, v), and the
// round trip. Sampling against the pdf on the sun-dominated map is checked through the
// same lookup by Environment.SunSky* and EnvironmentChi2.*.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr double kPi = std::numbers::pi;

template <typename In, typename Out>
std::vector<Out> run(const char* name, const std::vector<In>& in) {
    return test::run_elementwise<In, Out>("kernels/test/environment_lookup_kernels.cl", name, in);
}

// The exact (u, v) of a float map-frame direction (unit or not), in double.
void reference_uv(const cl_float4& m, double& u, double& v) {
    const double x = m.s[0], y = m.s[1], z = m.s[2];
    double phi = std::atan2(x, -z);
    if (phi < 0.0) phi += 2.0 * kPi;
    u = phi / (2.0 * kPi);
    v = std::atan2(std::hypot(x, z), y) / kPi;
}

// Float directions on a theta x phi grid, denser toward the poles, plus the poles and
// the seam (phi = 0, where u wraps).
std::vector<cl_float4> sphere_directions() {
    std::vector<cl_float4> d;
    auto add = [&](double th, double ph) {
        d.push_back(cl_float4{
            {float(std::sin(th) * std::sin(ph)), float(std::cos(th)), float(-std::sin(th) * std::cos(ph)), 0.0f}});
    };
    const int nt = 1024, np = 2048;
    for (int i = 0; i <= nt; ++i)
        for (int j = 0; j < np; ++j) add(kPi * i / nt, 2.0 * kPi * (j + 0.25) / np);
    for (double th : {1e-7, 1e-5, 1e-4, 1e-3, kPi - 1e-4, kPi - 1e-6})
        for (int j = 0; j < 64; ++j) add(th, 2.0 * kPi * j / 64);
    for (int i = 1; i < 256; ++i) add(kPi * i / 256, 0.0), add(kPi * i / 256, 1e-7), add(kPi * i / 256, -1e-7);
    return d;
}

TEST(EnvironmentLookup, DirToUvMaxError) {
    std::vector<cl_float4> dirs = sphere_directions();
    std::vector<cl_float2> uv = run<cl_float4, cl_float2>("env_lookup_dir_to_uv", dirs);
    double err_u = 0.0, err_v = 0.0;
    std::size_t texel_mismatch = 0;
    const int w = 1024, h = 512;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        double u, v;
        reference_uv(dirs[i], u, v);
        ASSERT_TRUE(uv[i].s[0] >= 0.0f && uv[i].s[0] <= 1.0f && uv[i].s[1] >= 0.0f && uv[i].s[1] <= 1.0f) << i;
        double du = std::fabs(double(uv[i].s[0]) - u);
        du = std::min(du, 1.0 - du); /* u wraps at the seam */
        const double sin_t = std::hypot(dirs[i].s[0], dirs[i].s[2]);
        if (sin_t > 0.0) err_u = std::max(err_u, du); /* u is undefined at the poles */
        err_v = std::max(err_v, std::fabs(double(uv[i].s[1]) - v));
        // The texel of a 1024 x 512 map, unless the exact (u, v) lies within float
        // rounding of a texel boundary.
        const double fu = u * w, fv = v * h;
        const bool near_edge = std::fabs(fu - std::round(fu)) < 4e-7 * w || std::fabs(fv - std::round(fv)) < 4e-7 * h;
        const int tx = std::min(int(uv[i].s[0] * float(w)), w - 1), ty = std::min(int(uv[i].s[1] * float(h)), h - 1);
        if (!near_edge && sin_t > 0.0 && (tx != std::min(int(fu), w - 1) || ty != std::min(int(fv), h - 1)))
            ++texel_mismatch;
    }
    std::printf("[ env map  ] direction -> (u, v) max error over %zu directions: u %.3g, v %.3g\n", dirs.size(), err_u,
                err_v);
    EXPECT_LE(err_u, 1.5e-7);
    EXPECT_LE(err_v, 1.5e-7);
    EXPECT_EQ(texel_mismatch, 0u);
}

TEST(EnvironmentLookup, UvToDirAndRoundTrip) {
    std::vector<cl_float2> uv;
    const int nu = 2048, nv = 1024;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i < nu; ++i) uv.push_back(cl_float2{{float((i + 0.3) / nu), float(double(j) / nv)}});
    std::vector<cl_float4> dirs = run<cl_float2, cl_float4>("env_lookup_uv_to_dir", uv);
    std::vector<cl_float2> back = run<cl_float4, cl_float2>("env_lookup_dir_to_uv", dirs);
    double err_dir = 0.0, err_len = 0.0, err_rt = 0.0;
    for (std::size_t i = 0; i < uv.size(); ++i) {
        const double th = kPi * double(uv[i].s[1]), ph = 2.0 * kPi * double(uv[i].s[0]);
        const double ref[3] = {std::sin(th) * std::sin(ph), std::cos(th), -std::sin(th) * std::cos(ph)};
        double e2 = 0.0, l2 = 0.0;
        for (int c = 0; c < 3; ++c)
            e2 += std::pow(double(dirs[i].s[c]) - ref[c], 2), l2 += std::pow(double(dirs[i].s[c]), 2);
        err_dir = std::max(err_dir, std::sqrt(e2));
        err_len = std::max(err_len, std::fabs(std::sqrt(l2) - 1.0));
        // Round trip: v everywhere; u where it is defined, its tolerance growing as
        // 1 / sin(theta) (a direction error e moves u by e / (2 pi sin theta)).
        err_rt = std::max(err_rt, std::fabs(double(back[i].s[1]) - double(uv[i].s[1])));
        const double st = std::sin(th);
        if (st > 1e-3) {
            double du = std::fabs(double(back[i].s[0]) - double(uv[i].s[0]));
            du = std::min(du, 1.0 - du);
            err_rt = std::max(err_rt, du * st);
        }
    }
    std::printf("[ env map  ] (u, v) -> direction max error %.3g (length %.3g); round trip %.3g\n", err_dir, err_len,
                err_rt);
    EXPECT_LE(err_dir, 3e-7);
    EXPECT_LE(err_len, 3e-7);
    EXPECT_LE(err_rt, 3e-7);
}

}  // namespace
}  // namespace facet
