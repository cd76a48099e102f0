// The polynomial trigonometry of kernels/util/trig.cl on the device, against double
// precision over the whole domain the kernels use: sincos_turns on t in [-1, 2] and
// atan2_fast on every direction of the plane at magnitudes from 1e-30 to 1e30, with
// atan2's values on the axes and at signed zeros.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdio>
#include <numbers>
#include <vector>

#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Runs `name` of kernels/test/trig_kernels.cl on `in`, one output per element.
template <typename In, typename Out>
std::vector<Out> run(const char* name, const std::vector<In>& in) {
    return test::run_elementwise<In, Out>("kernels/test/trig_kernels.cl", name, in);
}

TEST(Trig, SincosTurnsMaxError) {
    std::vector<float> t;
    const int n = 1 << 22;
    for (int i = 0; i <= n; ++i) t.push_back(float(-1.0 + 3.0 * i / n));
    for (float s : {0.0f, -0.0f, 1e-30f, 1e-8f, 0.125f, 0.375f, 0.9999999f, 1.0f, 2.0f, -0.25f, -0.5f}) t.push_back(s);
    std::vector<cl_float2> r = run<float, cl_float2>("trig_sincos_turns", t);
    double err_s = 0.0, err_c = 0.0, rel_small = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double a = kTwoPi * double(t[i]);
        err_s = std::max(err_s, std::fabs(double(r[i].s[0]) - std::sin(a)));
        err_c = std::max(err_c, std::fabs(double(r[i].s[1]) - std::cos(a)));
        if (std::fabs(t[i]) < 0.01f && t[i] != 0.0f)
            rel_small = std::max(rel_small, std::fabs(double(r[i].s[0]) / std::sin(a) - 1.0));
        ASSERT_LE(std::fabs(r[i].s[0]), 1.0f) << t[i];
        ASSERT_LE(std::fabs(r[i].s[1]), 1.0f) << t[i];
    }
    std::printf("[ trig     ] sincos_turns max abs error: sin %.3g, cos %.3g; sin near 0 relative %.3g\n", err_s, err_c,
                rel_small);
    EXPECT_LE(err_s, 1.5e-7);
    EXPECT_LE(err_c, 1.5e-7);
    EXPECT_LE(rel_small, 2.5e-7);
    // quarter turns exactly
    std::vector<cl_float2> q = run<float, cl_float2>("trig_sincos_turns", std::vector<float>{0.0f, 0.25f, 0.5f, 0.75f});
    const float want[4][2] = {{0.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, -1.0f}, {-1.0f, 0.0f}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(q[i].s[0], want[i][0]) << i;
        EXPECT_EQ(q[i].s[1], want[i][1]) << i;
    }
}

// e^x of kernels/util/exp_lanes.cl (the Beckmann lanes'): within 2 ulp wherever the result is a
// normal float, 0, infinity and NaN at the ends, subnormals to within their spacing.
TEST(Trig, ExpPolyMaxError) {
    std::vector<float> x;
    const int n = 1 << 21;
    for (int i = 0; i <= n; ++i) x.push_back(float(-104.0 + 193.0 * i / n));
    for (float s : {0.0f, -0.0f, 1e-30f, -1e-30f, 0.5f, -0.5f, 1.0f, 88.0f, 88.7f, -87.0f, -103.0f}) x.push_back(s);
    const float inf = std::numeric_limits<float>::infinity();
    x.insert(x.end(), {-inf, inf, std::numeric_limits<float>::quiet_NaN(), -200.0f, 200.0f});
    const std::vector<float> r = run<float, float>("trig_exp_poly", x);
    double worst_ulp = 0.0, worst_sub = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (std::isnan(x[i])) {
            EXPECT_TRUE(std::isnan(r[i]));
            continue;
        }
        const double want = std::exp(double(x[i]));
        if (want > double(std::numeric_limits<float>::max())) {
            EXPECT_EQ(r[i], inf) << x[i];
        } else if (want < double(std::numeric_limits<float>::min())) {
            worst_sub =
                std::max(worst_sub, std::fabs(double(r[i]) - want) / double(std::numeric_limits<float>::denorm_min()));
        } else {
            const double ulp = std::ldexp(1.0, std::ilogb(want) - 23);
            worst_ulp = std::max(worst_ulp, std::fabs(double(r[i]) - want) / ulp);
        }
    }
    std::printf("[ trig     ] exp_poly max error: %.3g ulp (normal results), %.3g of the subnormal spacing\n",
                worst_ulp, worst_sub);
    EXPECT_LE(worst_ulp, 2.0);
    EXPECT_LE(worst_sub, 1.0);
    EXPECT_EQ(r[x.size() - 5], 0.0f);  // e^-inf
    EXPECT_EQ(r[x.size() - 4], inf);
}

TEST(Trig, Atan2FastMaxError) {
    std::vector<cl_float2> yx;
    const int n = 1 << 20;
    for (double r : {1e-30, 1e-3, 1.0, 7.5e4, 1e30})
        for (int i = 0; i < n; ++i) {
            const double a = kTwoPi * (i + 0.37) / n;
            yx.push_back(cl_float2{{float(r * std::sin(a)), float(r * std::cos(a))}});
        }
    // tiny and huge ratios
    for (float y : {1e-30f, 1e-12f, 3e-8f, -2e-7f})
        for (float x : {1.0f, -1.0f, 1e30f}) yx.push_back(cl_float2{{y, x}}), yx.push_back(cl_float2{{x, y}});
    const std::size_t special = yx.size();
    for (float y : {0.0f, -0.0f, 1.0f, -1.0f})
        for (float x : {0.0f, -0.0f, 1.0f, -1.0f})
            if (x == 0.0f || y == 0.0f) yx.push_back(cl_float2{{y, x}});
    std::vector<float> r = run<cl_float2, float>("trig_atan2", yx);
    double err_abs = 0.0, err_rel = 0.0;
    for (std::size_t i = 0; i < special; ++i) {
        const double ref = std::atan2(double(yx[i].s[0]), double(yx[i].s[1]));
        const double e = std::fabs(double(r[i]) - ref);
        err_abs = std::max(err_abs, e);
        // relative where the result is a normal float (atan2(1e-30, 1e30) = 1e-60 is not)
        if (std::fabs(ref) >= 1e-37) err_rel = std::max(err_rel, e / std::fabs(ref));
    }
    std::printf("[ trig     ] atan2_fast max error: %.3g absolute, %.3g relative\n", err_abs, err_rel);
    EXPECT_LE(err_abs, 3.5e-7); /* near +-pi: 1.5 ulp of pi */
    EXPECT_LE(err_rel, 2.5e-7);
    // the axes and signed zeros give atan2's float values exactly
    for (std::size_t i = special; i < yx.size(); ++i)
        EXPECT_EQ(r[i], std::atan2(yx[i].s[0], yx[i].s[1])) << yx[i].s[0] << ", " << yx[i].s[1];
}

// Beckmann's projected area z (1 + Lambda) and Lambda (kernels/bsdf/beckmann_lanes.cl), their
// erfc approximations and e^x included, against double precision: roughness 0.001 to 1, polar
// angles from 0 to 89.99 degrees. The area reads erfc only as 2 - erfc (an absolute error
// suffices: Abramowitz & Stegun's 7.1.26 on the e^x it shares), Lambda needs a relative one
// (Press et al.'s erfcc).
TEST(Trig, BeckmannAreaAndLambdaMaxError) {
    std::vector<cl_float4> in;
    for (int ia = 0; ia <= 60; ++ia)
        for (int it = 0; it <= 2000; ++it) {
            const double alpha = std::pow(10.0, -3.0 + 3.0 * ia / 60.0);
            const double theta = 89.99 * std::pow(it / 2000.0, 0.5) * std::numbers::pi / 180.0;
            in.push_back(cl_float4{
                {float(std::sin(theta) * 0.6), float(std::sin(theta) * 0.8), float(std::cos(theta)), float(alpha)}});
        }
    const std::vector<cl_float2> r = run<cl_float4, cl_float2>("trig_beckmann_area", in);
    double worst_area = 0.0, worst_lambda = 0.0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double x = in[i].s[0], y = in[i].s[1], z = in[i].s[2], alpha = in[i].s[3];
        const double s = alpha * std::sqrt(x * x + y * y);
        double lambda = 0.0;
        if (s > 0.0) {
            const double a = z / s;
            lambda = 0.5 * (std::exp(-a * a) / (a * std::sqrt(std::numbers::pi)) - std::erfc(a));
        }
        const double area = z * (1.0 + lambda);
        worst_area = std::max(worst_area, std::fabs(double(r[i].s[0]) - area) / area);
        if (lambda > 1e-3) worst_lambda = std::max(worst_lambda, std::fabs(double(r[i].s[1]) - lambda) / lambda);
    }
    std::printf("[ trig     ] Beckmann area max relative error %.3g, Lambda (> 1e-3) %.3g\n", worst_area, worst_lambda);
    EXPECT_LE(worst_area, 5e-7);
    EXPECT_LE(worst_lambda, 1e-5);
}

}  // namespace
}  // namespace facet
