// Glass's choice toward the light (kernels/integrator/glass_choice.cl): a smooth dielectric
// whose mirror direction sees the sun reflects with a probability raised toward the
// reflection's share of the light, elsewhere as dielectric_choice says; either way the
// reflections' weights average to F and the refractions' to (1 - F) / eta^2, so the estimate
// stays unbiased. Rendered, glass_metal_sky's camera-seen glints and the glints the metals see
// on the balls are the fireflies this removes (docs/sampling.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "host/scene/sky.hpp"
#include "tests/dielectric_test_util.hpp"
#include "tests/environment_test_util.hpp"

namespace facet {
namespace {

using namespace test::env;

constexpr cl_uint kPerItem = 256, kItems = 4096;

struct Choice {
    double reflect = 0.0, reflect_se = 0.0;  // mean reflection weight per sample, its standard error
    double refract = 0.0, refract_se = 0.0;
    double q = 0.0;      // the probability of reflection the kernel chose
    double share = 0.0;  // the share of samples that reflected
};

Choice estimate(const EnvironmentMap& e, const FcMaterial& m, glm::vec3 n, glm::vec3 wo, cl_uint seed) {
    DeviceEnv d(e);
    ClContext& ctx = test::context();
    cl::Buffer mb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcMaterial),
                  const_cast<FcMaterial*>(&m));
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, kItems * sizeof(cl_float4));
    cl::Kernel k(test::program("kernels/test/glass_choice_kernels.cl"), "glass_choice_estimate");
    k.setArg(0, d.params);
    k.setArg(1, d.texels);
    k.setArg(2, d.dist);
    k.setArg(3, mb);
    k.setArg(4, cl_float4{{n.x, n.y, n.z, 0.0f}});
    k.setArg(5, cl_float4{{wo.x, wo.y, wo.z, 0.0f}});
    k.setArg(6, seed);
    k.setArg(7, kPerItem);
    k.setArg(8, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(kItems));
    std::vector<cl_float4> r(kItems);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, kItems * sizeof(cl_float4), r.data());
    const double count = double(kItems) * kPerItem;
    [[maybe_unused]] const auto [sr, nr, st, unused] = sum_items(r);
    Choice c;
    c.q = double(r[0].s[3]);
    c.share = nr / count;
    // each lobe's weight is the same in every sample that takes it: a binomial count, scaled
    const double p = c.share, wr = nr > 0.0 ? sr / nr : 0.0, wt = nr < count ? st / (count - nr) : 0.0;
    c.reflect = sr / count;
    c.reflect_se = wr * std::sqrt(p * (1.0 - p) / count);
    c.refract = st / count;
    c.refract_se = wt * std::sqrt(p * (1.0 - p) / count);
    return c;
}

FcMaterial smooth_glass(float eta) {
    FcMaterial m = test::dl::glass(FC_NDF_GGX, eta, 0.0f);
    m.flags |= FC_MAT_WIDE_CHOICE;
    return m;
}

// dielectric_choice's probability of reflection (kernels/bsdf/dielectric.cl) for the widened
// choice, in double.
double wide_choice(double f) { return std::clamp(f, std::min(0.25, 4.0 * f), 1.0 - std::min(0.25, 4.0 * (1.0 - f))); }

void expect_unbiased(const char* what, const Choice& c, double f, double eta) {
    const double zr = (c.reflect - f) / std::max(c.reflect_se, 1e-12);
    const double zt = (c.refract - (1.0 - f) / (eta * eta)) / std::max(c.refract_se, 1e-12);
    std::printf("[ glass    ] %-28s q %.3f (reflected %.3f), F %.4f: reflection %.5f (%+.2f se), refraction %+.2f se\n",
                what, c.q, c.share, f, c.reflect, zr, zt);
    EXPECT_LT(std::abs(zr), 4.5) << what << ": the reflections' weights do not average to F";
    EXPECT_LT(std::abs(zt), 4.5) << what << ": the refractions' weights do not average to (1 - F) / eta^2";
    EXPECT_NEAR(c.share, c.q, 5.0 * std::sqrt(c.q * (1.0 - c.q) / (double(kItems) * kPerItem)) + 1e-6) << what;
}

TEST(GlassChoice, ReflectsTowardTheSunAndStaysUnbiased) {
    SunSkyParams sp;
    sp.elevation_degrees = 30.0f;
    sp.azimuth_degrees = -60.0f;
    const SunSkyImage img = render_sun_sky(sp, 512);
    const EnvironmentMap e = sun_sky_environment(sp, 512);  // map frame = world
    const glm::vec3 sun = glm::normalize(glm::vec3(img.sun_direction[0], img.sun_direction[1], img.sun_direction[2]));
    const FcMaterial m = smooth_glass(1.5f);
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f));
    // wo whose mirror direction about n is the sun's
    const glm::vec3 wo_sun = 2.0f * glm::dot(sun, n) * n - sun;
    const double cos_sun = double(glm::dot(wo_sun, n)), f_sun = test::dl::fresnel(cos_sun, 1.5);
    const Choice at_sun = estimate(e, m, n, wo_sun, 1u);
    expect_unbiased("mirror toward the sun", at_sun, f_sun, 1.5);
    // the reflection carries most of the light there: chosen far more often than F widened
    EXPECT_GT(at_sun.q, 0.8) << "the choice did not follow the sun (dielectric_choice's is " << wide_choice(f_sun)
                             << ")";
    // a mirror direction into the dim sky, away from the sun: dielectric_choice's own
    const glm::vec3 away = glm::normalize(glm::vec3(-sun.x, 0.6f, -sun.z));
    const glm::vec3 wo_sky = 2.0f * glm::dot(away, n) * n - away;
    const double f_sky = test::dl::fresnel(double(glm::dot(wo_sky, n)), 1.5);
    const Choice at_sky = estimate(e, m, n, wo_sky, 2u);
    expect_unbiased("mirror toward the sky", at_sky, f_sky, 1.5);
    EXPECT_NEAR(at_sky.q, wide_choice(f_sky), 1e-5);
    // under a uniform environment the choice is dielectric_choice's everywhere
    const Choice uniform = estimate(constant_environment(glm::vec3(1.0f)), m, n, wo_sun, 3u);
    expect_unbiased("uniform environment", uniform, f_sun, 1.5);
    EXPECT_NEAR(uniform.q, wide_choice(f_sun), 1e-5);
    // from inside the ball (wo below the surface) the mirror direction stays inside: unchanged
    const Choice inside = estimate(e, m, n, -wo_sun, 4u);
    EXPECT_NEAR(inside.q, wide_choice(test::dl::fresnel(cos_sun, 1.0 / 1.5)), 1e-5);
}

// The choice reads a texel's density only where its row's bound (env_row_pdf_bound) could
// raise q: at every wo it tried, the q it makes is, to the bit, the one the density read at
// every mirror direction makes. The mirror directions sweep the sphere and crowd around the
// sun, where the bound passes the share and the density decides (both cases are counted).
TEST(GlassChoice, RowBoundLeavesTheChoiceUnchanged) {
    SunSkyParams sp;
    sp.elevation_degrees = 30.0f;
    sp.azimuth_degrees = -60.0f;
    const SunSkyImage img = render_sun_sky(sp, 512);
    EnvironmentMap e = sun_sky_environment(sp, 512);
    const glm::vec3 sun = glm::normalize(glm::vec3(img.sun_direction[0], img.sun_direction[1], img.sun_direction[2]));
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f));
    std::vector<cl_float4> wos;
    auto mirror_of = [&](glm::vec3 r) {
        const glm::vec3 wo = 2.0f * glm::dot(r, n) * n - r;
        wos.push_back(cl_float4{{wo.x, wo.y, wo.z, 0.0f}});
    };
    for (const cl_float4& v : spiral_directions(16384)) mirror_of(glm::vec3(v.s[0], v.s[1], v.s[2]));
    const glm::vec3 a = glm::normalize(glm::cross(sun, glm::vec3(0.0f, 0.0f, 1.0f))), b = glm::cross(sun, a);
    for (int i = 0; i < 16384; ++i) {  // within 3 degrees of the sun
        const float r = 0.052f * std::sqrt((float(i) + 0.5f) / 16384.0f), ph = 2.399963f * float(i);
        mirror_of(glm::normalize(sun + r * std::cos(ph) * a + r * std::sin(ph) * b));
    }
    const FcMaterial m = smooth_glass(1.5f);
    for (const bool rotated : {false, true}) {
        if (rotated) set_environment_rotation(e, test_rotation());
        DeviceEnv d(e);
        ClContext& ctx = test::context();
        cl::Buffer mb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcMaterial),
                      const_cast<FcMaterial*>(&m));
        cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, wos.size() * sizeof(cl_float4),
                      wos.data());
        cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, wos.size() * sizeof(cl_float2));
        cl::Kernel k(test::program("kernels/test/glass_choice_kernels.cl"), "glass_choice_q");
        k.setArg(0, d.params), k.setArg(1, d.texels), k.setArg(2, d.dist), k.setArg(3, mb);
        k.setArg(4, cl_float4{{n.x, n.y, n.z, 0.0f}}), k.setArg(5, in), k.setArg(6, out);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(wos.size()));
        std::vector<cl_float2> r(wos.size());
        ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, r.size() * sizeof(cl_float2), r.data());
        std::size_t raised = 0, widened = 0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            ASSERT_EQ(r[i].s[0], r[i].s[1]) << "wo " << i << (rotated ? ", the map rotated" : "");
            const float f =
                float(test::dl::fresnel(double(glm::dot(glm::vec3(wos[i].s[0], wos[i].s[1], wos[i].s[2]), n)), 1.5));
            if (r[i].s[0] > float(wide_choice(f)) + 1e-4f) ++raised;
            else ++widened;
        }
        std::printf("[ glass    ] %s: %zu choices raised toward the light, %zu left as dielectric_choice's\n",
                    rotated ? "rotated map" : "map frame = world", raised, widened);
        EXPECT_GT(raised, 100u);
        EXPECT_GT(widened, 10000u);
    }
}

}  // namespace
}  // namespace facet
