// Sampling toward glass (kernels/integrator/caustic_guide.cl): the mixture path_radiance draws
// a Lambertian vertex's directions from (the cosine lobe, the cone guide, the lens guide) must
// have the density caustic_guide_pdf gives it, or the image is biased where the guide sends
// samples (the caustics). Each case estimates the integral of cos(theta) over the hemisphere,
// pi, by cos / density over >= 2 M mixture samples (the estimate is bounded by pi / (1 - g),
// so its error is small and known): a density off by a tenth over the sun's image through a
// ball moves it by many standard errors. Also: the density the sampling reports for a lens
// draw (from its own root finding) is the one evaluated from scratch, and the mixture's share g
// follows the cones' solid angle. Host side: which objects become casters
// (host/scene/caustic_casters.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "host/scene/caustic_casters.hpp"
#include "host/scene/sky.hpp"
#include "tests/environment_test_util.hpp"

namespace facet {
namespace {

using namespace test::env;

const char* kGuideProgram = "kernels/test/caustic_guide_kernels.cl";

struct Ball {
    glm::vec3 c;
    float r, n;  // n: a smooth ball's relative index (a lens), 0 for a bound alone
};

std::vector<cl_float4> casters_of(const std::vector<Ball>& balls) {
    std::vector<cl_float4> out;
    for (const Ball& b : balls) {
        out.push_back(cl_float4{{b.c.x, b.c.y, b.c.z, b.r}});
        out.push_back(cl_float4{{b.n, 0.0f, 0.0f, 0.0f}});
    }
    return out;
}

constexpr cl_uint kPerItem = 256, kItems = 8192;

// Runs the test program's kernel `name` over kItems work-items of kPerItem samples each: its
// arguments the environment (0 to 2) and the casters (3, 4), then those `rest(kernel, out)`
// sets from 5 on; returns each work-item's float4.
template <typename Rest>
std::vector<cl_float4> run_items(const char* name, const EnvironmentMap& e, const std::vector<Ball>& balls, Rest rest) {
    DeviceEnv d(e);
    ClContext& ctx = test::context();
    const std::vector<cl_float4> casters = casters_of(balls);
    cl::Buffer cb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, casters.size() * sizeof(cl_float4),
                  const_cast<cl_float4*>(casters.data()));
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, kItems * sizeof(cl_float4));
    cl::Kernel k(test::program(kGuideProgram), name);
    k.setArg(0, d.params);
    k.setArg(1, d.texels);
    k.setArg(2, d.dist);
    k.setArg(3, cb);
    k.setArg(4, cl_uint(balls.size()));
    rest(k, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(kItems));
    std::vector<cl_float4> r(kItems);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, kItems * sizeof(cl_float4), r.data());
    return r;
}

struct Estimate {
    double mean = 0.0, stderr_ = 0.0, lens_share = 0.0;
    double gap = 0.0;  // the share of lens draws whose two densities are more than 1e-3 apart
    std::uint64_t n = 0;
};

Estimate estimate(const EnvironmentMap& e, const std::vector<Ball>& balls, glm::vec3 p, glm::vec3 n, float fraction,
                  std::uint32_t seed, float glint) {
    const std::vector<cl_float4> r = run_items("cg_estimate", e, balls, [&](cl::Kernel& k, const cl::Buffer& out) {
        k.setArg(5, cl_float4{{p.x, p.y, p.z, 0.0f}});
        k.setArg(6, cl_float4{{n.x, n.y, n.z, 0.0f}});
        k.setArg(7, fraction);
        k.setArg(8, cl_uint(seed));
        k.setArg(9, kPerItem);
        k.setArg(10, out);
        k.setArg(11, glint);
    });
    Estimate est;
    est.n = std::uint64_t(kItems) * kPerItem;
    const auto [s, s2, gaps, lens] = sum_items(r);
    est.mean = s / double(est.n);
    est.stderr_ = std::sqrt(std::max(s2 / double(est.n) - est.mean * est.mean, 0.0) / double(est.n));
    est.lens_share = lens / double(est.n);
    est.gap = lens > 0.0 ? gaps / lens : 0.0;
    return est;
}

EnvironmentMap sun_sky() {
    SunSkyParams p;
    p.elevation_degrees = 30.0f;
    p.azimuth_degrees = -60.0f;
    return sun_sky_environment(p, 512);
}

void expect_unbiased(const std::string& what, const EnvironmentMap& e, const std::vector<Ball>& balls, glm::vec3 p,
                     glm::vec3 n, float fraction, std::uint32_t seed, double min_lens_share, float glint = 0.0f) {
    const Estimate est = estimate(e, balls, p, n, fraction, seed, glint);
    const double z = (est.mean - kPi) / est.stderr_;
    std::printf("[ guide    ] %-34s mean %.5f (pi %+.2f se), lens draws %.3f, density apart %.1e\n", what.c_str(),
                est.mean, z, est.lens_share, est.gap);
    EXPECT_LT(std::abs(z), 4.5) << what << ": cos / density averages " << est.mean << ", not pi";
    EXPECT_LT(est.gap, 1e-3) << what << ": the sampled lens density differs from the evaluated one too often";
    EXPECT_GE(est.lens_share, min_lens_share) << what << ": the lens guide drew too few directions";
}

const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

TEST(CausticGuide, MixtureDensityIsTheSamplersUnderAConstantEnvironment) {
    const EnvironmentMap e = constant_environment(glm::vec3(1.0f));
    const std::vector<Ball> glass{{{0.0f, 0.5f, 0.0f}, 0.5f, 1.5f}};
    expect_unbiased("constant, glass ball, near", e, glass, {0.9f, 0.0f, 0.3f}, kUp, 0.5f, 1u, 0.1);
    expect_unbiased("constant, glass ball, touching", e, glass, {0.3f, 0.0f, 0.1f}, kUp, 0.5f, 2u, 0.02);
    expect_unbiased("constant, water ball, far", e, {{{0.0f, 0.5f, 0.0f}, 0.5f, 1.33f}}, {3.0f, 0.0f, 1.0f}, kUp, 0.9f,
                    3u, 0.01);
    expect_unbiased("constant, diamond ball, tilted", e, {{{0.0f, 1.0f, 0.0f}, 0.7f, 2.4f}}, {1.2f, 0.3f, 0.0f},
                    glm::normalize(glm::vec3(-0.4f, 1.0f, 0.2f)), 0.5f, 4u, 0.1);
}

TEST(CausticGuide, MixtureDensityIsTheSamplersUnderTheSun) {
    const EnvironmentMap e = sun_sky();
    const std::vector<Ball> glass{{{-1.8f, 0.5f, 1.0f}, 0.5f, 1.5f}, {{0.6f, 0.5f, 1.0f}, 0.5f, 1.33f}};
    // floor points about both balls (among them glass_metal_sky's water caustic at (-0.15, 0, 0.59))
    const glm::vec3 points[] = {{-0.15f, 0.0f, 0.59f}, {-1.2f, 0.0f, 0.2f}, {-2.5f, 0.0f, 1.6f},
                                {0.6f, 0.0f, 2.0f},    {1.4f, 0.0f, 0.9f},  {-0.6f, 0.0f, 1.0f}};
    std::uint32_t seed = 10;
    for (const glm::vec3& p : points)
        expect_unbiased("sun, two balls, (" + std::to_string(p.x) + ", " + std::to_string(p.z) + ")", e, glass, p, kUp,
                        0.5f, seed++, 0.0);
}

TEST(CausticGuide, MixtureDensityIsTheSamplersWithBoundsAndLenses) {
    const EnvironmentMap e = sun_sky();
    // a lens, a bound of rough glass (cone guide) overlapping it, and one above the point's
    // horizon only in part
    const std::vector<Ball> mixed{
        {{0.0f, 0.5f, 0.0f}, 0.5f, 1.5f}, {{0.6f, 0.6f, 0.3f}, 0.6f, 0.0f}, {{-1.5f, -0.2f, 0.0f}, 0.5f, 0.0f}};
    expect_unbiased("sun, lens and bounds", e, mixed, {0.5f, 0.0f, -0.8f}, kUp, 0.5f, 30u, 0.01);
    expect_unbiased("sun, bounds only", e, {mixed[1], mixed[2]}, {0.5f, 0.0f, -0.8f}, kUp, 0.5f, 31u, 0.0);
    // half the lens guide's draws aimed at the balls' glints (a glossy vertex's mixture)
    expect_unbiased("sun, lens and bounds, glints", e, mixed, {0.5f, 0.0f, -0.8f}, kUp, 0.5f, 32u, 0.01, 0.5f);
    expect_unbiased("sun, two balls, glints", e, {{{-1.8f, 0.5f, 1.0f}, 0.5f, 1.5f}, {{0.6f, 0.5f, 1.0f}, 0.5f, 1.33f}},
                    {-0.6f, 0.0f, 1.0f}, kUp, 0.5f, 33u, 0.05, 0.5f);
    expect_unbiased("constant, glass ball, near, glints", constant_environment(glm::vec3(1.0f)),
                    {{{0.0f, 0.5f, 0.0f}, 0.5f, 1.5f}}, {0.9f, 0.0f, 0.3f}, kUp, 0.5f, 34u, 0.1, 0.5f);
}

// A glossy vertex's estimate of its directional albedo (red) by the mixture, against the
// BSDF's own (fraction 0): (mean, standard error, share of guided draws).
struct GlossyEstimate {
    double mean = 0.0, stderr_ = 0.0, guided = 0.0;
};

GlossyEstimate glossy_estimate(const EnvironmentMap& e, const std::vector<Ball>& balls, const FcMaterial& m,
                               glm::vec3 p, glm::vec3 n, glm::vec3 wo, float fraction, std::uint32_t seed) {
    cl::Buffer mb(test::context().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcMaterial),
                  const_cast<FcMaterial*>(&m));
    const std::vector<cl_float4> r =
        run_items("cg_glossy_estimate", e, balls, [&](cl::Kernel& k, const cl::Buffer& out) {
            k.setArg(5, mb);
            k.setArg(6, cl_float4{{p.x, p.y, p.z, 0.0f}});
            k.setArg(7, cl_float4{{n.x, n.y, n.z, 0.0f}});
            k.setArg(8, cl_float4{{wo.x, wo.y, wo.z, 0.0f}});
            k.setArg(9, fraction);
            k.setArg(10, cl_uint(seed));
            k.setArg(11, kPerItem);
            k.setArg(12, out);
        });
    const double count = double(kItems) * double(kPerItem);
    [[maybe_unused]] const auto [s, s2, g, unused] = sum_items(r);
    GlossyEstimate est;
    est.mean = s / count;
    est.stderr_ = std::sqrt(std::max(s2 / count - est.mean * est.mean, 0.0) / count);
    est.guided = g / count;
    return est;
}

FcMaterial glossy(float alpha, float diffuse, float f0) {
    FcMaterial m{};
    for (int c = 0; c < 3; ++c) {
        m.diffuse[c] = diffuse;
        m.specular[c] = f0;
        m.eta[c] = 1.5f;
    }
    m.diffuse_model = diffuse > 0.0f ? FC_DIFFUSE_LAMBERT : FC_DIFFUSE_NONE;
    m.specular_model = FC_SPECULAR_MICROFACET;
    m.ndf = FC_NDF_GGX;
    m.sampling = FC_SAMPLE_VISIBLE;
    m.geometry = FC_G_SMITH_CORRELATED;
    m.fresnel = FC_FRESNEL_SCHLICK;
    m.alpha_x = m.alpha_y = alpha;
    m.ior = 1.5f;
    return m;
}

// At a glossy vertex (a rough metal-like lobe, a plastic) whose lobe points at a glass ball
// under the sun, the mixture's weights f cos / density average to the BSDF's own albedo: the
// density is the mixture's, and the BSDF's choice rescaled past the guide's share is still its
// own.
TEST(CausticGuide, GlossyMixtureKeepsTheBsdfsAlbedo) {
    const EnvironmentMap e = sun_sky();
    const std::vector<Ball> balls{{{0.0f, 0.5f, 0.0f}, 0.5f, 1.5f}, {{0.9f, 0.5f, 0.5f}, 0.4f, 0.0f}};
    const glm::vec3 p{0.8f, 0.0f, -0.7f};
    const glm::vec3 d = glm::normalize(glm::vec3(0.0f, 0.5f, 0.0f) - p);
    const glm::vec3 wo{-d.x, d.y, -d.z};  // its mirror direction is the lens's centre
    std::uint32_t seed = 40;
    for (const auto& [what, m] : {std::pair<const char*, FcMaterial>{"rough metal", glossy(0.15f, 0.0f, 0.9f)},
                                  std::pair<const char*, FcMaterial>{"plastic", glossy(0.3f, 0.5f, 0.04f)}}) {
        const GlossyEstimate own = glossy_estimate(e, balls, m, p, kUp, wo, 0.0f, seed++);
        const GlossyEstimate mix = glossy_estimate(e, balls, m, p, kUp, wo, 0.5f, seed++);
        const double z = (mix.mean - own.mean) / std::hypot(mix.stderr_, own.stderr_);
        std::printf("[ guide    ] glossy, %-12s albedo %.5f (BSDF) / %.5f (mixture, %+.2f se), guided %.3f\n", what,
                    own.mean, mix.mean, z, mix.guided);
        EXPECT_LT(std::abs(z), 4.5) << what;
        EXPECT_GT(mix.guided, 0.1) << what;
    }
}

TEST(CausticGuide, ShareFollowsTheConesSolidAngle) {
    ClContext& ctx = test::context();
    const std::vector<cl_float4> casters =
        casters_of({{{0.0f, 0.5f, 0.0f}, 0.5f, 1.5f}, {{5.0f, 0.5f, 0.0f}, 0.5f, 0.0f}});
    cl::Buffer cb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, casters.size() * sizeof(cl_float4),
                  const_cast<cl_float4*>(casters.data()));
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, sizeof(cl_float4));
    auto at = [&](glm::vec3 p, glm::vec3 n) {
        cl::Kernel k(test::program(kGuideProgram), "cg_at");
        k.setArg(0, cb);
        k.setArg(1, cl_uint(2));
        k.setArg(2, cl_float4{{p.x, p.y, p.z, 0.0f}});
        k.setArg(3, cl_float4{{n.x, n.y, n.z, 0.0f}});
        k.setArg(4, 0.5f);
        k.setArg(5, out);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
        cl_float4 r;
        ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(cl_float4), &r);
        return r;
    };
    // the cones' solid angle from which a vertex takes the full share (FC_CAUSTIC_GUIDE_FULL, sr)
    constexpr float kFullShareCones = 1.0f;
    // beside the ball: its cone is wide (1.17 sr), the full share; both casters count, one a lens
    cl_float4 near = at({0.7f, 0.0f, 0.0f}, kUp);
    EXPECT_GT(near.s[2], kFullShareCones);
    EXPECT_FLOAT_EQ(near.s[0], 0.5f);
    EXPECT_FLOAT_EQ(near.s[1], 0.5f);
    EXPECT_FLOAT_EQ(near.s[3], 1.0f);
    // far from both: a share in proportion to the cones' solid angle
    cl_float4 far = at({2.5f, 0.0f, 30.0f}, kUp);
    EXPECT_GT(far.s[0], 0.0f);
    EXPECT_LT(far.s[0], 0.05f);
    EXPECT_NEAR(far.s[0], 0.5f * far.s[2] / kFullShareCones, 1e-6f);
    // inside the ball: only the other bound counts, no lens
    cl_float4 inside = at({0.0f, 0.5f, 0.1f}, kUp);
    EXPECT_EQ(inside.s[3], 0.0f);
    EXPECT_EQ(inside.s[1], 0.0f);
    EXPECT_NEAR(inside.s[2], 2.0f * float(kPi) * (1.0f - std::sqrt(1.0f - 0.25f / 25.01f)), 1e-4f);
    // both cones below the horizon: not guided
    EXPECT_EQ(at({2.5f, 3.0f, 0.0f}, kUp).s[0], 0.0f);
}

Scene scene_with(const Material& glass) {
    Scene s;
    s.materials.push_back(default_material());
    s.materials.push_back(glass);
    return s;
}

TEST(CausticGuide, CastersAreTheGlassObjects) {
    Material smooth = default_material();
    smooth.specular_model = FC_SPECULAR_DIELECTRIC;
    smooth.diffuse_model = FC_DIFFUSE_NONE;
    smooth.ior = 1.5f;
    smooth.alpha_x = smooth.alpha_y = 0.0f;
    Scene s = scene_with(smooth);
    add_analytic_sphere(s, {1.0f, 2.0f, 3.0f}, 0.5f, 1, false);
    add_analytic_sphere(s, {4.0f, 2.0f, 3.0f}, 0.25f, 0, false);  // Lambertian: not a caster
    add_sphere(s, {-3.0f, 0.0f, 0.0f}, 2.0f, 2, 1, false);        // a glass mesh: its bound only
    std::vector<float> c = caustic_casters(s);
    ASSERT_EQ(c.size(), 16u);
    EXPECT_EQ(c[0], 1.0f);
    EXPECT_EQ(c[3], 0.5f);
    EXPECT_EQ(c[4], 1.5f);  // a smooth ball: a lens of its index
    EXPECT_NEAR(c[8], -3.0f, 1e-5f);
    EXPECT_GE(c[11], 2.0f);  // the mesh's bound holds its vertices
    EXPECT_LT(c[11], 2.0f * 1.01f);
    EXPECT_EQ(c[12], 0.0f);  // not a lens
    // rough glass: a bound, not a lens; no guide at 0; none without a Lambertian material
    Material rough = smooth;
    rough.alpha_x = rough.alpha_y = 0.2f;
    Scene r = scene_with(rough);
    add_analytic_sphere(r, {0.0f, 0.0f, 0.0f}, 1.0f, 1, false);
    ASSERT_EQ(caustic_casters(r).size(), 8u);
    EXPECT_EQ(caustic_casters(r)[4], 0.0f);
    r.settings.caustic_guide = 0.0f;
    EXPECT_TRUE(caustic_casters(r).empty());
    r.settings.caustic_guide = 0.5f;
    r.materials[0].diffuse_model = FC_DIFFUSE_OREN_NAYAR;
    EXPECT_TRUE(caustic_casters(r).empty());
}

}  // namespace
}  // namespace facet
