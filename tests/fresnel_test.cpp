// Fresnel reflectance (kernels/bsdf/fresnel.cl) on the device: the conductor's three
// channels, computed together as a float3, against the Fresnel equations in double
// complex arithmetic, at every incidence, for metals and extreme indices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

// Unpolarised reflectance of a conductor of complex index n at incidence cosine c.
double conductor_reference(double c, std::complex<double> n) {
    const std::complex<double> sin2 = 1.0 - c * c;
    const std::complex<double> cos_t = std::sqrt(1.0 - sin2 / (n * n));
    const std::complex<double> rs = (c - n * cos_t) / (c + n * cos_t);
    const std::complex<double> rp = (n * c - cos_t) / (n * c + cos_t);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(Fresnel, ConductorMatchesComplexFresnelEquations) {
    // (eta, k) per channel: gold, aluminium, copper-like, a near-dielectric, an extreme
    const float eta[][3] = {{0.143f, 0.374f, 1.442f},
                            {1.657f, 0.880f, 0.521f},
                            {0.200f, 0.924f, 1.102f},
                            {1.5f, 1.0f, 2.4f},
                            {0.01f, 5.0f, 30.0f}};
    const float kk[][3] = {{3.983f, 2.385f, 1.603f},
                           {9.224f, 6.270f, 4.837f},
                           {3.912f, 2.452f, 2.142f},
                           {1e-4f, 0.0f, 0.5f},
                           {10.0f, 0.01f, 100.0f}};
    std::vector<cl_float4> c, k;
    const int steps = 4096;
    for (int m = 0; m < 5; ++m)
        for (int i = 0; i <= steps; ++i) {
            c.push_back(cl_float4{{eta[m][0], eta[m][1], eta[m][2], float(double(i) / steps)}});
            k.push_back(cl_float4{{kk[m][0], kk[m][1], kk[m][2], 0.0f}});
        }
    // outside [0, 1]: clamped
    c.push_back(cl_float4{{0.2f, 1.0f, 3.0f, -0.5f}}), k.push_back(cl_float4{{3.0f, 0.0f, 1.0f, 0.0f}});
    c.push_back(cl_float4{{0.2f, 1.0f, 3.0f, 1.5f}}), k.push_back(cl_float4{{3.0f, 0.0f, 1.0f, 0.0f}});
    ClContext& ctx = test::context();
    const std::size_t n = c.size();
    cl::Buffer bc(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(cl_float4), c.data());
    cl::Buffer bk(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(cl_float4), k.data());
    cl::Buffer bo(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Kernel kern(test::program("kernels/test/fresnel_kernels.cl"), "fresnel_conductor_batch");
    kern.setArg(0, bc), kern.setArg(1, bk), kern.setArg(2, bo);
    ctx.queue().enqueueNDRangeKernel(kern, cl::NullRange, cl::NDRange(n));
    std::vector<cl_float4> out(n);
    ctx.queue().enqueueReadBuffer(bo, CL_TRUE, 0, n * sizeof(cl_float4), out.data());
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double cos_i = std::clamp(double(c[i].s[3]), 0.0, 1.0);
            const double ref = conductor_reference(cos_i, {double(c[i].s[ch]), double(k[i].s[ch])});
            const float got = out[i].s[ch];
            ASSERT_TRUE(got >= 0.0f && got <= 1.0f) << i << " " << ch;
            worst = std::max(worst, std::fabs(double(got) - ref));
        }
    std::printf("[ fresnel  ] conductor: max abs error %.3g against double complex arithmetic\n", worst);
    EXPECT_LE(worst, 2e-5);
}

}  // namespace
}  // namespace facet
