// The helpers of kernels/util/math.cl on the device, against double precision:
// pow_positive over the bases and exponents the BSDFs give it (cos^e of Blinn-Phong lobes,
// exponents up to 1e5), with its values at the ends of the domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

TEST(Math, PowPositiveRelativeError) {
    std::vector<cl_float2> xy;
    const int nx = 2048, ny = 512;
    for (int i = 0; i < nx; ++i) {
        const float x = float(std::pow(10.0, -8.0 * (i + 0.5) / nx));          // 1e-8 .. 1, log-spaced
        const float x_near_one = float(1.0 - std::ldexp(1.0, -24) * (i + 1));  // the last 2048 floats below 1
        for (int j = 0; j < ny; ++j) {
            const float y = float(std::pow(10.0, -3.0 + 8.0 * j / (ny - 1)));  // 1e-3 .. 1e5
            xy.push_back(cl_float2{{x, y}});
            xy.push_back(cl_float2{{x_near_one, y}});
        }
    }
    const std::vector<cl_float2> exact = {{{1.0f, 7.0f}},  {{1.0f, 1e5f}}, {{0.5f, 0.0f}},
                                          {{0.25f, 0.5f}}, {{0.0f, 2.0f}}, {{0.0f, 1e-3f}}};
    xy.insert(xy.end(), exact.begin(), exact.end());
    const std::vector<float> r =
        test::run_elementwise<cl_float2, float>("kernels/test/math_kernels.cl", "math_pow_positive", xy);
    double worst_1e6 = 0.0, worst_1e30 = 0.0;
    for (std::size_t i = 0; i + exact.size() < xy.size(); ++i) {
        const double want = std::pow(double(xy[i].s[0]), double(xy[i].s[1]));
        ASSERT_TRUE(std::isfinite(r[i]) && r[i] >= 0.0f) << xy[i].s[0] << "^" << xy[i].s[1];
        const double rel = std::fabs(double(r[i]) / want - 1.0);
        if (want >= 1e-6) worst_1e6 = std::max(worst_1e6, rel);
        if (want >= 1e-30) worst_1e30 = std::max(worst_1e30, rel);
    }
    std::printf("[ math     ] pow_positive max relative error: %.3g where x^y >= 1e-6, %.3g where >= 1e-30\n",
                worst_1e6, worst_1e30);
    EXPECT_LE(worst_1e6, 2e-6);
    EXPECT_LE(worst_1e30, 1e-5);
    const std::size_t e = xy.size() - exact.size();
    EXPECT_EQ(r[e + 0], 1.0f);
    EXPECT_EQ(r[e + 1], 1.0f);
    EXPECT_EQ(r[e + 2], 1.0f);
    EXPECT_EQ(r[e + 3], 0.5f);
    EXPECT_EQ(r[e + 4], 0.0f);
    EXPECT_EQ(r[e + 5], 0.0f);
}

}  // namespace
}  // namespace facet
