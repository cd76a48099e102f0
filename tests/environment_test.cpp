// The environment light (kernels/lights/environment.cl, host/scene/environment_map.cpp,
// host/scene/sky.cpp): consistency of env_sample with env_radiance / env_pdf, the pdf's
// normalisation, the direction convention under rotation, robust loading (sanitising,
// 1x1, non-2:1, black, missing maps) and the sun-and-sky map. The chi-square tests are in
// environment_chi2_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <random>

#include "tests/environment_test_util.hpp"
#include "host/error.hpp"
#include "host/util/color.hpp"
#include "host/image/image_io.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/sky.hpp"
#include "kernels/shared/render_layout.h"
#include "tests/temp_dir.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace test::env;
namespace fs = std::filesystem;

bool close(float a, float b) { return std::fabs(a - b) <= 1e-5f * std::max(std::fabs(a), std::fabs(b)); }

// env_sample's radiance and pdf equal env_radiance / env_pdf at the sampled direction;
// everything finite and non-negative; returns the share of refused samples.
double check_consistency(const EnvironmentMap& e, std::size_t n, const char* what) {
    SampleBatch b = sample_batch(e, n, 7u);
    std::size_t refused = 0, bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const cl_float4 &d = b.dir_pdf[i], &L = b.radiance[i], &ev = b.eval[i];
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(d.s[c]) || !std::isfinite(L.s[c]) || !std::isfinite(ev.s[c]) || L.s[c] < 0.0f) ++bad;
        if (d.s[3] == 0.0f) ++refused;
        bool ok = close(d.s[3], ev.s[3]);
        for (int c = 0; c < 3; ++c) ok = ok && close(L.s[c], ev.s[c]);
        if (!ok && bad < 10) {
            ADD_FAILURE() << what << ": sample " << i << " pdf " << d.s[3] << " vs " << ev.s[3] << ", L.x " << L.s[0]
                          << " vs " << ev.s[0];
            ++bad;
        }
    }
    EXPECT_EQ(bad, 0u) << what;
    return double(refused) / double(n);
}

// The integral of env_pdf over the sphere, by the midpoint rule at texel centres.
double pdf_integral(const EnvironmentMap& e) {
    std::vector<cl_float4> dirs;
    std::vector<double> wts;
    texel_centres(e, dirs, wts);
    std::vector<cl_float4> r = eval_batch(e, dirs);
    double sum = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) sum += double(r[i].s[3]) * wts[i];
    return sum;
}

// The map with its distribution swapped for MIS compensation's, as the renderer uploads it.
EnvironmentMap compensated_copy(const EnvironmentMap& e) {
    EnvironmentMap c = e;
    c.distribution = compensated_environment_distribution(e);
    return c;
}

EnvironmentMap smooth_env(int w, int h, const glm::mat3& rot) {
    std::vector<std::string> warnings;
    return environment_from_pixels(w, h, smooth_map(w, h), glm::vec3(1.0f, 0.5f, 2.0f), rot, "smooth", warnings);
}

TEST(Environment, SunSkyMap) {
    SunSkyParams p;
    SunSkyImage img = render_sun_sky(p, 1024);
    ASSERT_EQ(img.width, 1024);
    ASSERT_EQ(img.height, 512);
    for (float v : img.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    std::printf("[ sun-sky  ] elevation %.0f, azimuth %.0f, turbidity %.1f: the sun carries %.1f%% of the power\n",
                p.elevation_degrees, p.azimuth_degrees, p.turbidity, 100.0 * img.sun_power_fraction);
    EXPECT_GT(img.sun_power_fraction, 0.5);
    for (double elev : {2.0, 60.0, 90.0, -5.0}) {
        p.elevation_degrees = elev;
        SunSkyImage o = render_sun_sky(p, 256);
        for (float v : o.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << elev;
        std::printf("[ sun-sky  ] elevation %.0f: sun %.1f%% of the power\n", elev, 100.0 * o.sun_power_fraction);
    }
    p.turbidity = 20.0;
    EXPECT_THROW(render_sun_sky(p, 256), Error);
}

TEST(Environment, SunSkyExrRoundTrip) {
    const test::TempDir dir;
    const std::string path = dir.path("sky.exr");
    write_sun_sky_exr(path, 256, SunSkyParams{});
    std::vector<std::string> warnings;
    EnvironmentMap e = load_environment_map(path, glm::vec3(1.0f), glm::mat3(1.0f), warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(e.params.width, 256);
    EXPECT_GT(e.params.total, 0.0f);
}

TEST(Environment, PdfEvalConsistency) {
    SunSkyParams p;
    EnvironmentMap sky = sun_sky_environment(p, 1024);
    set_environment_rotation(sky, test_rotation());
    EXPECT_LT(check_consistency(sky, 1u << 18, "sun-sky"), 1e-4);
    EnvironmentMap bilinear = sky;
    set_environment_filter(bilinear, FC_ENV_FILTER_BILINEAR);
    EXPECT_NE(bilinear.distribution, sky.distribution) << "the weights follow the lookup";
    EXPECT_LT(check_consistency(bilinear, 1u << 18, "sun-sky, bilinear"), 1e-4);
    EXPECT_LT(check_consistency(compensated_copy(bilinear), 1u << 18, "sun-sky, bilinear, compensated"), 1e-4);
    EXPECT_LT(check_consistency(smooth_env(256, 128, test_rotation()), 1u << 18, "smooth"), 1e-4);
    EXPECT_EQ(check_consistency(constant_environment(glm::vec3(0.5f, 1.0f, 2.0f)), 1u << 14, "constant"), 0.0);
}

TEST(Environment, PdfIntegratesToOne) {
    SunSkyParams p;
    EnvironmentMap sky = sun_sky_environment(p, 1024);
    EXPECT_NEAR(pdf_integral(sky), 1.0, 1e-4);
    set_environment_rotation(sky, test_rotation());
    EXPECT_NEAR(pdf_integral(sky), 1.0, 1e-4);
    EnvironmentMap bilinear = sky;
    set_environment_filter(bilinear, FC_ENV_FILTER_BILINEAR);
    EXPECT_NEAR(pdf_integral(bilinear), 1.0, 1e-4);
    // the filter moves no power: the (1/8, 3/4, 1/8) weights sum to 1 (to the sin(theta)
    // of the neighbouring rows, which differ by a texel)
    EXPECT_NEAR(bilinear.mean_luminance / sky.mean_luminance, 1.0, 1e-3);
    EXPECT_NEAR(pdf_integral(smooth_env(256, 128, glm::mat3(1.0f))), 1.0, 1e-4);
    EXPECT_NEAR(pdf_integral(smooth_env(64, 64, glm::mat3(1.0f))), 1.0, 1e-4);  // not 2:1
    // mean luminance: the solid-angle mean of the radiance's luminance
    EXPECT_NEAR(constant_environment(glm::vec3(1.0f, 2.0f, 3.0f)).mean_luminance, 0.2126 + 1.4304 + 0.2166, 1e-6);
}

// MIS compensation's distribution (environment_map.hpp): the map with its distribution
// swapped for the compensated one, as the renderer uploads it.
EnvironmentMap compensated(const EnvironmentMap& e) {
    EnvironmentMap c = e;
    c.distribution = compensated_environment_distribution(e);
    return c;
}

// A w x h map of one radiance in every texel.
EnvironmentMap constant_map(int w, int h, const glm::mat3& rot) {
    std::vector<float> rgb(std::size_t(w) * h * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.3f + 0.2f * float(i % 3);
    std::vector<std::string> warnings;
    return environment_from_pixels(w, h, rgb, glm::vec3(1.0f), rot, "constant map", warnings);
}

// The compensated pdf integrates to 1; on the sun and sky (the sun > 50% of the power)
// texels at or below the mean get density 0 (Karlik et al.'s max(0, L - mean)), and the
// sun's density grows; a
// constant map falls back to the plain distribution (nothing is left after subtracting
// the mean); a constant environment keeps its uniform density.
TEST(Environment, CompensatedPdf) {
    SunSkyParams p;
    EnvironmentMap sky = sun_sky_environment(p, 1024);
    set_environment_rotation(sky, test_rotation());
    const EnvironmentMap csky = compensated(sky);
    ASSERT_EQ(csky.distribution.size(), sky.distribution.size());
    EXPECT_NE(csky.distribution, sky.distribution);
    EXPECT_NEAR(pdf_integral(csky), 1.0, 1e-4);
    std::vector<cl_float4> dirs;
    std::vector<double> wts;
    texel_centres(sky, dirs, wts);
    const std::vector<cl_float4> plain = eval_batch(sky, dirs), comp = eval_batch(csky, dirs);
    std::size_t kept = 0, below = 0;
    double brightest = 0.0, brightest_plain = 0.0, brightest_comp = 0.0, ratio_lo = 1e30, ratio_hi = 0.0;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        const double lum =
            0.2126 * double(plain[i].s[0]) + 0.7152 * double(plain[i].s[1]) + 0.0722 * double(plain[i].s[2]);
        if (lum <= sky.mean_luminance && plain[i].s[3] > 0.0f) {
            ++below;
            const double ratio = double(comp[i].s[3]) / double(plain[i].s[3]);
            ratio_lo = std::min(ratio_lo, ratio), ratio_hi = std::max(ratio_hi, ratio);
        } else if (lum > sky.mean_luminance) ++kept;
        if (lum > brightest) brightest = lum, brightest_plain = plain[i].s[3], brightest_comp = comp[i].s[3];
    }
    std::printf(
        "[ mis-comp ] sun and sky 1024x512: %zu texels above the mean, %zu at or below it, their pdf "
        "%.4g-%.4g x the plain one\n",
        kept, below, ratio_lo, ratio_hi);
    EXPECT_GT(kept, 0u);
    EXPECT_GT(below, 5 * kept);
    EXPECT_EQ(ratio_hi, 0.0) << "max(0, L - mean): at or below the mean no density (left to BSDF sampling)";
    // the sun's texel: (L - mean) / (P - mean 4 pi) against L / P, P the map's power
    EXPECT_GT(brightest_comp, brightest_plain);
    EXPECT_NEAR(pdf_integral(compensated(smooth_env(256, 128, test_rotation()))), 1.0, 1e-4);

    const EnvironmentMap flat = constant_map(64, 32, test_rotation());
    const EnvironmentMap cflat = compensated(flat);
    EXPECT_EQ(cflat.distribution, flat.distribution) << "a constant map falls back to the plain distribution";
    EXPECT_NEAR(pdf_integral(cflat), 1.0, 1e-4);
    const EnvironmentMap con = constant_environment(glm::vec3(0.5f));
    EXPECT_EQ(compensated(con).distribution, con.distribution);
    EXPECT_EQ(check_consistency(compensated(con), 1u << 12, "constant environment, compensated"), 0.0);
    EXPECT_LT(check_consistency(csky, 1u << 18, "sun-sky, compensated"), 1e-4);

    // the renderer uploads it under MIS only (compensated is the default), plain when asked
    EXPECT_EQ(sky.sampling, EnvironmentSampling::compensated);
    EXPECT_EQ(environment_sampling_distribution(sky, FC_STRATEGY_MIS), csky.distribution);
    EXPECT_EQ(environment_sampling_distribution(sky, FC_STRATEGY_LIGHT), sky.distribution);
    EnvironmentMap asked = sky;
    asked.sampling = EnvironmentSampling::plain;
    EXPECT_EQ(environment_sampling_distribution(asked, FC_STRATEGY_MIS), sky.distribution);
}

// Each row's bound of the density (env_row_pdf_bound, which glass's choice reads before a
// texel's density: kernels/integrator/glass_choice.cl) is never below env_pdf in its row, at
// every texel centre and at directions spread over the sphere, and equals it at the row's most
// likely texel (the same operations on the same probability): so a choice the bound settles is
// the one the density would make. On a sun and sky, plain and compensated, and a smooth map.
TEST(Environment, RowBoundsHoldEveryDensity) {
    ClContext& ctx = test::context();
    SunSkyParams sp;
    EnvironmentMap sky = sun_sky_environment(sp, 256);
    set_environment_rotation(sky, test_rotation());
    for (const EnvironmentMap& e : {sky, compensated(sky), smooth_env(200, 100, test_rotation())}) {
        std::vector<cl_float4> dirs;
        std::vector<double> wts;
        texel_centres(e, dirs, wts);
        const std::size_t centres = dirs.size();
        for (const cl_float4& v : spiral_directions(4096)) dirs.push_back(v);
        const DeviceEnv d(e);
        cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dirs.size() * sizeof(cl_float4),
                      dirs.data());
        cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, dirs.size() * sizeof(cl_float4));
        cl::Kernel k(test::program(kProgram), "env_row_bounds");
        k.setArg(0, d.params), k.setArg(1, d.texels), k.setArg(2, d.dist), k.setArg(3, in), k.setArg(4, out);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(dirs.size()));
        std::vector<cl_float4> r(dirs.size());
        ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, r.size() * sizeof(cl_float4), r.data());
        const int h = e.params.height;
        std::vector<int> attained(h, 0);
        std::size_t finite = 0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            const float pdf = r[i].s[0], bound = r[i].s[1];
            const int row = int(r[i].s[2]);
            ASSERT_TRUE(row >= 0 && row < h) << "direction " << i;
            if (!(std::isfinite(bound))) continue;  // sin(theta) = 0: the density is read
            ++finite;
            ASSERT_GE(bound, pdf) << "direction " << i << ", row " << row;
            if (i < centres && bound == pdf && pdf > 0.0f) attained[row] = 1;
        }
        EXPECT_GT(finite, r.size() * 99 / 100);
        // the rows whose texels are lit: the bound is their most likely texel's density
        int lit = 0, tight = 0;
        for (int y = 0; y < h; ++y)
            if (e.distribution[std::size_t(y) + 1] > e.distribution[std::size_t(y)]) ++lit, tight += attained[y];
        EXPECT_GT(lit, h / 4);  // compensation leaves the rows below the mean black
        EXPECT_EQ(tight, lit);
    }
}

TEST(Environment, RotationAndConvention) {
    // every texel of a map with distinct values is found at the direction the documented
    // convention gives it, after the rotation
    const int w = 64, h = 32;
    std::vector<float> rgb(std::size_t(w) * h * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(i / 3 + 1) + 0.25f * float(i % 3);
    std::vector<std::string> warnings;
    EnvironmentMap e = environment_from_pixels(w, h, rgb, glm::vec3(1.0f), test_rotation(), "ids", warnings);
    std::vector<cl_float4> dirs;
    std::vector<double> wts;
    texel_centres(e, dirs, wts);
    std::vector<cl_float4> r = eval_batch(e, dirs);
    for (std::size_t i = 0; i < r.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(r[i].s[c], rgb[3 * i + c]) << "texel " << i;
    // the image centre looks along +z, up is +y, u grows to the viewer's right (-x)
    EnvironmentMap id = environment_from_pixels(w, h, rgb, glm::vec3(1.0f), glm::mat3(1.0f), "ids", warnings);
    std::vector<cl_float4> probe = {{{0, 0, 1, 0}}, {{0, 1, 0, 0}}, {{-1, 0, 0, 0}}};
    std::vector<cl_float4> v = eval_batch(id, probe);
    EXPECT_EQ(v[0].s[0], float(16 * w + w / 2 + 1));          // row h/2, column w/2 (the texel right of centre)
    EXPECT_TRUE(v[1].s[0] >= 1.0f && v[1].s[0] <= float(w));  // row 0 (any column at the pole)
    EXPECT_EQ(v[2].s[0], float(16 * w + 3 * w / 4 + 1));
    // world -> map -> world and world -> (u, v) -> world
    DeviceEnv d(e);
    ClContext& ctx = test::context();
    std::vector<cl_float4> rand_dirs = spiral_directions(4096);
    cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, rand_dirs.size() * sizeof(cl_float4),
                  rand_dirs.data());
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, rand_dirs.size() * sizeof(float));
    cl::Kernel k(test::program(kProgram), "env_round_trip");
    k.setArg(0, d.params);
    k.setArg(1, in);
    k.setArg(2, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(rand_dirs.size()));
    std::vector<float> err(rand_dirs.size());
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, err.size() * sizeof(float), err.data());
    for (std::size_t i = 0; i < err.size(); ++i) ASSERT_LT(err[i], 2e-5f) << "direction " << i;
}

// Sampling searches a cdf from its guide table (Chen & Asau 1974): the interval is the
// one bisecting the whole cdf gives, for every u tried (uniform, every guide boundary k / g
// and the floats next to it, and the cdf's own values), on a map with a sharp lobe, black
// texels and rows; and the kernels' env_guide_size (count leading zeros) is the host's.
TEST(Environment, GuidedSearchFindsTheBisectedInterval) {
    ClContext& ctx = test::context();
    constexpr int w = 200, h = 100;  // not powers of two
    std::vector<float> rgb = smooth_map(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (y < 10 || (x > 50 && x < 90))  // black rows and columns: zero-width intervals
                for (int c = 0; c < 3; ++c) rgb[3 * (std::size_t(y) * w + x) + c] = 0.0f;
    std::vector<std::string> warnings;
    const EnvironmentMap e = environment_from_pixels(w, h, rgb, glm::vec3(1.0f), glm::mat3(1.0f), "guided", warnings);
    std::vector<float> us;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < 20000; ++i) us.push_back(std::min(uniform(rng), 0x1.fffffep-1f));
    for (std::uint32_t g : {env_guide_size(w), env_guide_size(h)})
        for (std::uint32_t k = 0; k < g; ++k) {
            const float t = float(k) / float(g);
            us.push_back(t);
            if (k > 0) us.push_back(std::nextafter(t, 0.0f));
            us.push_back(std::nextafter(t, 1.0f));
        }
    for (int i = 0; i <= h; ++i) us.push_back(std::min(e.distribution[std::size_t(i)], 0x1.fffffep-1f));
    const DeviceEnv d(e);
    cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, us.size() * sizeof(float), us.data());
    cl::Buffer found(ctx.context(), CL_MEM_WRITE_ONLY, us.size() * sizeof(cl_int4));
    cl::Buffer sizes(ctx.context(), CL_MEM_WRITE_ONLY, us.size() * sizeof(cl_uint));
    cl::Kernel k(test::program(kProgram), "env_guided_search");
    k.setArg(0, d.params), k.setArg(1, d.dist), k.setArg(2, in), k.setArg(3, found), k.setArg(4, sizes);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(us.size()));
    std::vector<cl_int4> f(us.size());
    std::vector<cl_uint> g(us.size());
    ctx.queue().enqueueReadBuffer(found, CL_TRUE, 0, f.size() * sizeof(cl_int4), f.data());
    ctx.queue().enqueueReadBuffer(sizes, CL_TRUE, 0, g.size() * sizeof(cl_uint), g.data());
    for (std::size_t i = 0; i < us.size(); ++i) {
        ASSERT_EQ(f[i].s[0], f[i].s[1]) << "row, u = " << us[i];
        ASSERT_EQ(f[i].s[2], f[i].s[3]) << "column, u = " << us[i];
        ASSERT_EQ(g[i], env_guide_size(std::uint32_t(i + 1))) << "n = " << i + 1;
    }
}

// env_sample_texel's lane forms at the packets' widths, 8 and 16 (the environment's samples in
// the packets, by gathers where the CPU has them), find the same texel and the same point
// across it, to the bit, as its W = 1 form (env_sample_uv's, whose intervals the test above
// checks), for points at random and on every guide boundary and cdf entry, on a map with
// black rows and columns (intervals of zero width).
TEST(Environment, SampleTexelLanesAgreeWithW1) {
    ClContext& ctx = test::context();
    constexpr int w = 200, h = 100;
    std::vector<float> rgb = smooth_map(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (y < 10 || (x > 50 && x < 90))
                for (int c = 0; c < 3; ++c) rgb[3 * (std::size_t(y) * w + x) + c] = 0.0f;
    std::vector<std::string> warnings;
    const EnvironmentMap e = environment_from_pixels(w, h, rgb, glm::vec3(1.0f), glm::mat3(1.0f), "lanes", warnings);
    std::vector<float> ux, uy;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < 8000; ++i) {
        ux.push_back(std::min(uniform(rng), 0x1.fffffep-1f));
        uy.push_back(std::min(uniform(rng), 0x1.fffffep-1f));
    }
    // every guide boundary and the floats beside it, and the cdfs' own entries, each paired
    // with a point at random in the other coordinate
    std::vector<float> edges;
    for (std::uint32_t g : {env_guide_size(w), env_guide_size(h)})
        for (std::uint32_t k = 0; k <= g; ++k) {
            const float t = float(k) / float(g);
            edges.push_back(t);
            edges.push_back(std::nextafter(t, 0.0f));
            edges.push_back(std::nextafter(t, 1.0f));
        }
    for (std::size_t i = 0; i < e.distribution.size() && i < std::size_t(h + 1) + std::size_t(w + 1) * 20; ++i)
        edges.push_back(e.distribution[i]);
    for (float t : edges) {
        const float c = std::clamp(t, 0.0f, 0x1.fffffep-1f);
        ux.push_back(c), uy.push_back(uniform(rng));
        ux.push_back(uniform(rng)), uy.push_back(c);
    }
    ux.push_back(1.0f), uy.push_back(1.0f);  // clamped as env_sample_uv clamps
    while (ux.size() % 16 != 0) ux.push_back(0.5f), uy.push_back(0.5f);
    const DeviceEnv d(e);
    cl::Buffer bx(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, ux.size() * sizeof(float), ux.data());
    cl::Buffer by(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, uy.size() * sizeof(float), uy.data());
    cl::Buffer texels(ctx.context(), CL_MEM_WRITE_ONLY, 3 * ux.size() * sizeof(cl_int2));
    cl::Buffer across(ctx.context(), CL_MEM_WRITE_ONLY, 3 * ux.size() * sizeof(cl_float2));
    cl::Kernel k(test::program(kProgram), "env_sample_texel_lanes");
    k.setArg(0, d.params), k.setArg(1, d.dist), k.setArg(2, bx), k.setArg(3, by), k.setArg(4, texels),
        k.setArg(5, across);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(ux.size() / 16));
    std::vector<cl_int2> t(3 * ux.size());
    std::vector<cl_float2> a(3 * ux.size());
    ctx.queue().enqueueReadBuffer(texels, CL_TRUE, 0, t.size() * sizeof(cl_int2), t.data());
    ctx.queue().enqueueReadBuffer(across, CL_TRUE, 0, a.size() * sizeof(cl_float2), a.data());
    for (std::size_t i = 0; i < ux.size(); ++i) {
        const cl_int2 t1 = t[3 * i];
        ASSERT_TRUE(t1.s[0] >= 0 && t1.s[0] < w && t1.s[1] >= 0 && t1.s[1] < h) << "u " << ux[i] << ", " << uy[i];
        for (int m = 1; m <= 2; ++m) {
            const char* width = m == 1 ? "W = 8" : "W = 16";
            ASSERT_EQ(t[3 * i + m].s[0], t1.s[0]) << width << ", u " << ux[i] << ", " << uy[i];
            ASSERT_EQ(t[3 * i + m].s[1], t1.s[1]) << width << ", u " << ux[i] << ", " << uy[i];
            ASSERT_EQ(std::bit_cast<std::uint32_t>(a[3 * i + m].s[0]), std::bit_cast<std::uint32_t>(a[3 * i].s[0]))
                << width << ", u " << ux[i] << ", " << uy[i];
            ASSERT_EQ(std::bit_cast<std::uint32_t>(a[3 * i + m].s[1]), std::bit_cast<std::uint32_t>(a[3 * i].s[1]))
                << width << ", u " << ux[i] << ", " << uy[i];
        }
    }
}

// The bilinear lookup (opt-in, docs/environment.md): a texel's value at
// its centre, the mean of two neighbours half-way between their centres, the last and
// first columns mixed across u = 0, the first row alone between its centre and the pole.
// Texel (x, y) of this map holds 1 + x + 100 y (+ 0.25 per channel), linear in x and y,
// so every interpolated value is known.
TEST(Environment, BilinearLookup) {
    const int w = 16, h = 8;
    std::vector<float> rgb(std::size_t(w) * h * 3);
    auto value = [&](int x, int y) { return 1.0 + x + 100.0 * y; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) rgb[3 * (std::size_t(y) * w + x) + c] = float(value(x, y) + 0.25 * c);
    std::vector<std::string> warnings;
    EnvironmentMap e = environment_from_pixels(w, h, rgb, glm::vec3(1.0f), glm::mat3(1.0f), "ids", warnings);
    EXPECT_EQ(e.params.filter, FC_ENV_FILTER_NEAREST) << "maps start with the nearest lookup";
    set_environment_filter(e, FC_ENV_FILTER_BILINEAR);
    struct Probe {
        double u, v, want;
        const char* what;
    };
    const std::vector<Probe> probes = {
        {5.5 / w, 3.5 / h, value(5, 3), "a texel's centre"},
        {6.0 / w, 3.5 / h, 0.5 * (value(5, 3) + value(6, 3)), "half-way along a row"},
        {5.5 / w, 4.0 / h, 0.5 * (value(5, 3) + value(5, 4)), "half-way down a column"},
        {5.75 / w, 3.75 / h,
         0.75 * 0.75 * value(5, 3) + 0.25 * 0.75 * (value(6, 3) + value(5, 4)) + 0.25 * 0.25 * value(6, 4),
         "a quarter of the way diagonally"},
        {0.25 / w, 3.5 / h, 0.25 * value(w - 1, 3) + 0.75 * value(0, 3), "across u = 0 (wrapping around)"},
        {(w - 0.25) / w, 3.5 / h, 0.75 * value(w - 1, 3) + 0.25 * value(0, 3), "across u = 1"},
        {5.5 / w, 0.2 / h, value(5, 0), "between the first row's centre and the pole"},
        {5.5 / w, (h - 0.2) / h, value(5, h - 1), "between the last row's centre and the pole"},
    };
    std::vector<cl_float4> dirs;
    for (const Probe& p : probes) dirs.push_back(to_world(e.params, map_direction(kPi * p.v, 2.0 * kPi * p.u)));
    const std::vector<cl_float4> got = eval_batch(e, dirs);
    for (std::size_t i = 0; i < probes.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(double(got[i].s[c]), probes[i].want + 0.25 * c, 2e-4 * probes[i].want)
                << probes[i].what << ", channel " << c;
    // the nearest lookup of the same point between two centres is one texel
    set_environment_filter(e, FC_ENV_FILTER_NEAREST);
    EXPECT_EQ(double(eval_batch(e, {dirs[1]})[0].s[0]), value(6, 3));
    EXPECT_THROW(set_environment_filter(e, 7), Error);
}

// The bilinear lookup's sampling follows the interpolation inside a texel
// (env_bilinear_in_texel): the luminance of a light sample's radiance over its pdf, the
// environment-only estimate of the integral of the luminance over the sphere, is then
// nearly constant, as it is for the nearest lookup, where radiance and density are both
// constant over a texel. With a uniform point inside the picked texel (the sampling before 4
// December 2026) its spread on the sun and sky was several times the nearest lookup's.
struct RatioSpread {
    double mean = 0.0, rel_sd = 0.0;
};
RatioSpread luminance_over_pdf(const EnvironmentMap& e, std::size_t n) {
    SampleBatch b = sample_batch(e, n, 21u);
    double s = 0.0, s2 = 0.0;
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double pdf = b.dir_pdf[i].s[3];
        if (!(pdf > 0.0)) continue;
        const double r = luminance(b.radiance[i].s[0], b.radiance[i].s[1], b.radiance[i].s[2]) / pdf;
        s += r;
        s2 += r * r;
        ++k;
    }
    RatioSpread out;
    out.mean = s / double(k);
    out.rel_sd = std::sqrt(std::max(s2 / double(k) - out.mean * out.mean, 0.0)) / out.mean;
    return out;
}

TEST(Environment, BilinearSamplingFollowsTheInterpolation) {
    SunSkyParams p;
    EnvironmentMap nearest = sun_sky_environment(p, 256);
    set_environment_rotation(nearest, test_rotation());
    EnvironmentMap bilinear = nearest;
    set_environment_filter(bilinear, FC_ENV_FILTER_BILINEAR);
    const RatioSpread a = luminance_over_pdf(nearest, 1u << 18), b = luminance_over_pdf(bilinear, 1u << 18);
    std::printf(
        "[ env      ] sun and sky 256x128, luminance / pdf: nearest %.5g (relative sd %.4f), bilinear %.5g "
        "(relative sd %.4f)\n",
        a.mean, a.rel_sd, b.mean, b.rel_sd);
    // both estimate 4 pi times the mean luminance
    EXPECT_NEAR(a.mean / (4.0 * kPi * nearest.mean_luminance), 1.0, 1e-3);
    EXPECT_NEAR(b.mean / (4.0 * kPi * bilinear.mean_luminance), 1.0, 1e-3);
    EXPECT_LT(b.rel_sd, 2.0 * a.rel_sd + 1e-3) << "the density does not follow the interpolated luminance";
    // the same on a smooth map, and with MIS compensation's texel choice
    const RatioSpread c = luminance_over_pdf(smooth_env(256, 128, test_rotation()), 1u << 16);
    EnvironmentMap smooth = smooth_env(256, 128, test_rotation());
    set_environment_filter(smooth, FC_ENV_FILTER_BILINEAR);
    const RatioSpread d = luminance_over_pdf(smooth, 1u << 16);
    std::printf("[ env      ] smooth 256x128, luminance / pdf relative sd: nearest %.4f, bilinear %.4f\n", c.rel_sd,
                d.rel_sd);
    EXPECT_LT(d.rel_sd, 2.0 * c.rel_sd + 1e-3);
}

TEST(Environment, SanitisesBadTexels) {
    const test::TempDir dir;
    const std::string path = dir.path("bad.exr");
    const int w = 16, h = 8;
    std::vector<float> rgb(std::size_t(w) * h * 3, 1.0f);
    rgb[0] = std::nanf("");
    rgb[3 * 5 + 1] = INFINITY;
    rgb[3 * 20 + 2] = -INFINITY;
    rgb[3 * 40] = -2.0f;
    rgb[3 * 41 + 1] = -0.5f;
    rgb[3 * 41 + 2] = -0.5f;  // same texel: counted once
    write_exr(path, w, h, rgb);
    std::vector<std::string> warnings;
    EnvironmentMap e = load_environment_map(path, glm::vec3(1.0f), glm::mat3(1.0f), warnings);
    ASSERT_EQ(warnings.size(), 1u);
    std::printf("[ warning  ] %s\n", warnings[0].c_str());
    EXPECT_NE(warnings[0].find(path + ": 5 texels were negative, NaN or infinite and were set to 0 ("),
              std::string::npos);
    EXPECT_NE(warnings[0].find("% of the map's energy changed"), std::string::npos);
    for (float v : e.texels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    EXPECT_EQ(e.texels[4 * 40], 0.0f);
    EXPECT_EQ(e.texels[4 * 40 + 1], 1.0f);  // only the bad channels change
    check_consistency(e, 1u << 14, "sanitised");
}

TEST(Environment, OneByOneIsConstant) {
    std::vector<std::string> warnings;
    EnvironmentMap one =
        environment_from_pixels(1, 1, {0.5f, 1.0f, 2.0f}, glm::vec3(2.0f), glm::mat3(1.0f), "1x1", warnings);
    EnvironmentMap con = constant_environment(glm::vec3(1.0f, 2.0f, 4.0f));
    EXPECT_TRUE(warnings.empty());
    std::vector<cl_float4> dirs = {{{0, 0, 1, 0}}, {{0, -1, 0, 0}}, {{0.6f, 0.0f, 0.8f, 0}}};
    std::vector<cl_float4> a = eval_batch(one, dirs), b = eval_batch(con, dirs);
    for (std::size_t i = 0; i < dirs.size(); ++i)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(a[i].s[c], b[i].s[c]);
    EXPECT_FLOAT_EQ(a[0].s[3], float(1.0 / (4.0 * kPi)));
    EXPECT_DOUBLE_EQ(one.mean_luminance, con.mean_luminance);
}

TEST(Environment, NonTwoToOneMaps) {
    std::vector<std::string> warnings;
    EnvironmentMap e =
        environment_from_pixels(40, 40, smooth_map(40, 40), glm::vec3(1.0f), test_rotation(), "square", warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("square: the map is 40x40, not 2:1: it is stretched onto the sphere"),
              std::string::npos);
    EXPECT_LT(check_consistency(e, 1u << 16, "square"), 1e-3);
    EXPECT_NEAR(pdf_integral(e), 1.0, 1e-4);
    EnvironmentMap tall =
        environment_from_pixels(3, 7, smooth_map(3, 7), glm::vec3(1.0f), glm::mat3(1.0f), "tall", warnings);
    EXPECT_NEAR(pdf_integral(tall), 1.0, 1e-4);
}

TEST(Environment, BlackMapLightsNothing) {
    std::vector<std::string> warnings;
    EnvironmentMap e = environment_from_pixels(32, 16, std::vector<float>(32 * 16 * 3, 0.0f), glm::vec3(1.0f),
                                               glm::mat3(1.0f), "black", warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "black: the map is black: it lights nothing");
    EXPECT_EQ(e.params.total, 0.0f);
    EXPECT_EQ(e.mean_luminance, 0.0);
    SampleBatch b = sample_batch(e, 4096, 3u);
    for (std::size_t i = 0; i < b.dir_pdf.size(); ++i) {
        ASSERT_EQ(b.dir_pdf[i].s[3], 0.0f);
        ASSERT_EQ(b.eval[i].s[3], 0.0f);
        for (int c = 0; c < 3; ++c) ASSERT_EQ(b.radiance[i].s[c], 0.0f);
    }
    // a black 1x1 map and a zero scale are black too
    environment_from_pixels(1, 1, {0.0f, 0.0f, 0.0f}, glm::vec3(1.0f), glm::mat3(1.0f), "black1", warnings);
    EXPECT_EQ(warnings.back(), "black1: the map is black: it lights nothing");
    EnvironmentMap zero =
        environment_from_pixels(8, 4, smooth_map(8, 4), glm::vec3(0.0f), glm::mat3(1.0f), "zero", warnings);
    EXPECT_EQ(sample_batch(zero, 64, 1u).dir_pdf[0].s[3], 0.0f);
    EXPECT_EQ(sample_batch(constant_environment(glm::vec3(0.0f)), 64, 1u).dir_pdf[0].s[3], 0.0f);
    EXPECT_THROW(environment_from_pixels(8, 4, smooth_map(8, 4), glm::vec3(-1.0f), glm::mat3(1.0f), "neg", warnings),
                 Error);
}

TEST(Environment, NoEnvironment) {
    EnvironmentMap e = no_environment();
    SampleBatch b = sample_batch(e, 64, 1u);
    EXPECT_EQ(b.dir_pdf[0].s[3], 0.0f);
    EXPECT_EQ(b.eval[0].s[0], 0.0f);
    EXPECT_EQ(b.eval[0].s[3], 0.0f);
    EXPECT_FALSE(e.distribution.empty());
    EXPECT_FALSE(e.texels.empty());
}

TEST(Environment, MissingFileNamesIt) {
    std::vector<std::string> warnings;
    try {
        load_environment_map("/nonexistent/sky.exr", glm::vec3(1.0f), glm::mat3(1.0f), warnings);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/sky.exr"), std::string::npos) << e.what();
    }
}

// Lossy DWAB-compressed maps with large negative texels around the sun.
TEST(Environment, PmndrsMapsAreSanitised) {
    const fs::path dir = fs::path(test::assets_dir()) / "env_pmndrs";
    if (!fs::exists(dir / "sky.exr")) GTEST_SKIP() << dir << " not found";
    for (const char* name : {"sky.exr", "esplanade.exr", "park.exr", "studio.exr"}) {
        std::vector<std::string> warnings;
        EnvironmentMap e = load_environment_map((dir / name).string(), glm::vec3(1.0f), glm::mat3(1.0f), warnings);
        ASSERT_FALSE(warnings.empty()) << name;
        std::printf("[ warning  ] %s\n", warnings[0].c_str());
        for (float v : e.texels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << name;
        EXPECT_NEAR(pdf_integral(e), 1.0, 1e-4) << name;
        EXPECT_LT(check_consistency(e, 1u << 14, name), 1e-3);
    }
}

TEST(Environment, RadianceHdrFile) {
    const fs::path file = fs::path(test::assets_dir()) / "env_polyhaven_hdr" / "kloppenheim_06_1k.hdr";
    if (!fs::exists(file)) GTEST_SKIP() << file << " not found";
    std::vector<std::string> warnings;
    EnvironmentMap e = load_environment_map(file.string(), glm::vec3(1.0f), glm::mat3(1.0f), warnings);
    EXPECT_EQ(e.params.width, 2 * e.params.height);
    EXPECT_GT(e.mean_luminance, 0.0);
    EXPECT_LT(check_consistency(e, 1u << 14, "hdr"), 1e-3);
}

}  // namespace
}  // namespace facet
