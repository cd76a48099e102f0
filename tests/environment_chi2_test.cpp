// Chi-square goodness of fit of env_sample against env_pdf (kernels/lights/environment.cl),
// >= 1e6 samples per map: the generated sun and sky (the sun carries > 50% of the power,
// in a few texels), a smooth map, and Blender's sunrise.exr when the assets are present.
//
// Cells are blocks of bu x bv texels of the map, found on the device from each sampled
// direction by the documented convention (after the rotation). A cell's expected share is
// the integral of env_pdf over it by the midpoint rule at the texel centres with the
// sin(theta) dtheta dphi weight, which is exact for the piecewise-constant p(u, v) /
// sin(theta) density. Pooling, the statistic and the Sidak-corrected level are those of
// tests/chi2_test_util.hpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "tests/chi2_test_util.hpp"
#include "tests/environment_test_util.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/sky.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace test::env;

const double kLevel = test::chi2::sidak(0.01, 10);

// Cells of bu x bv texels, or with sub > 1 of bu x bv cells of a grid sub times finer than
// the texels (sub = 2: quarters of a texel, inside which the bilinear lookup's density
// varies).
test::chi2::Result chi_square(const EnvironmentMap& e, int bu, int bv, std::uint32_t seed,
                              std::uint64_t n_target = 2000000, int sub = 1) {
    const int w = e.params.width * sub, h = e.params.height * sub;
    EXPECT_TRUE(w % bu == 0 && h % bv == 0) << "cells must tile the map";
    const int nu = w / bu, nv = h / bv;
    // expected shares from env_pdf at the texel (or sub-texel) centres
    std::vector<cl_float4> dirs;
    std::vector<double> wts;
    texel_centres(e, dirs, wts, sub);
    std::vector<cl_float4> ev = eval_batch(e, dirs);
    std::vector<double> mass(std::size_t(nu) * nv, 0.0);
    for (int y = 0; y < nv * bv; ++y)
        for (int x = 0; x < nu * bu; ++x) {
            const std::size_t t = std::size_t(y) * w + x;
            mass[std::size_t(y / bv) * nu + x / bu] += double(ev[t].s[3]) * wts[t];
        }
    // samples, binned on the device
    const cl_uint per_item = 64;
    const std::size_t items = std::size_t((n_target + per_item - 1) / per_item);
    const std::uint64_t n = std::uint64_t(items) * per_item;
    DeviceEnv d(e);
    ClContext& ctx = test::context();
    cl::Buffer bins(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
    cl::Kernel k(test::program(kProgram), "env_sample_bins");
    k.setArg(0, d.params);
    k.setArg(1, d.texels);
    k.setArg(2, d.dist);
    k.setArg(3, cl_uint(seed));
    k.setArg(4, per_item);
    k.setArg(5, cl_int(bu));
    k.setArg(6, cl_int(bv));
    k.setArg(7, bins);
    k.setArg(8, cl_int(sub));
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(items));
    std::vector<cl_uint> b(n);
    ctx.queue().enqueueReadBuffer(bins, CL_TRUE, 0, n * sizeof(cl_uint), b.data());
    std::vector<std::uint32_t> hist(mass.size() + 2, 0u);
    for (cl_uint v : b) ++hist[std::min<std::size_t>(v, mass.size() + 1)];
    return test::chi2::test(hist, mass, n, kLevel);
}

TEST(EnvironmentChi2, ChiSquareSunSky) {
    SunSkyParams p;
    SunSkyImage img = render_sun_sky(p, 2048);
    std::printf("[ chi2     ] sun and sky 2048x1024: the sun carries %.1f%% of the power\n",
                100.0 * img.sun_power_fraction);
    ASSERT_GT(img.sun_power_fraction, 0.5);
    std::vector<std::string> warnings;
    EnvironmentMap e = environment_from_pixels(img.width, img.height, img.rgb, glm::vec3(1.0f), test_rotation(),
                                               "sun and sky", warnings);
    auto r = chi_square(e, 16, 16, 11u);
    std::printf("[ chi2     ] sun and sky, 16x16-texel cells: %s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
    // finer: 1x1-texel cells on a smaller map (the sun covers a texel or two)
    EnvironmentMap small = sun_sky_environment(p, 256);
    auto f = chi_square(small, 1, 1, 12u);
    std::printf("[ chi2     ] sun and sky 256x128, texel cells: %s\n", f.message.c_str());
    EXPECT_TRUE(f.ok) << f.message;
}

TEST(EnvironmentChi2, ChiSquareSmooth) {
    std::vector<std::string> warnings;
    EnvironmentMap e = environment_from_pixels(256, 128, smooth_map(256, 128), glm::vec3(1.0f, 0.5f, 2.0f),
                                               test_rotation(), "smooth", warnings);
    auto r = chi_square(e, 4, 4, 13u);
    std::printf("[ chi2     ] smooth 256x128, 4x4-texel cells: %s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

// MIS compensation's distribution (compensated_environment_distribution): env_sample
// against env_pdf when both read it, on the sun and sky (only the texels brighter than the
// mean keep density: the sun and the sky around it) and on a constant map (the fallback to
// the plain distribution).
TEST(EnvironmentChi2, ChiSquareCompensated) {
    SunSkyParams p;
    EnvironmentMap sky = sun_sky_environment(p, 256);
    set_environment_rotation(sky, test_rotation());
    sky.distribution = compensated_environment_distribution(sky);
    auto f = chi_square(sky, 1, 1, 15u);
    std::printf("[ chi2     ] compensated sun and sky 256x128, texel cells: %s\n", f.message.c_str());
    EXPECT_TRUE(f.ok) << f.message;
    std::vector<std::string> warnings;
    EnvironmentMap smooth = environment_from_pixels(256, 128, smooth_map(256, 128), glm::vec3(1.0f, 0.5f, 2.0f),
                                                    test_rotation(), "smooth", warnings);
    smooth.distribution = compensated_environment_distribution(smooth);
    auto s = chi_square(smooth, 4, 4, 16u);
    std::printf("[ chi2     ] compensated smooth 256x128, 4x4-texel cells: %s\n", s.message.c_str());
    EXPECT_TRUE(s.ok) << s.message;
    std::vector<float> rgb(64 * 32 * 3, 0.7f);
    EnvironmentMap flat = environment_from_pixels(64, 32, rgb, glm::vec3(1.0f), test_rotation(), "flat", warnings);
    flat.distribution = compensated_environment_distribution(flat);
    auto c = chi_square(flat, 2, 2, 17u);
    std::printf("[ chi2     ] compensated constant map 64x32 (plain fallback), 2x2-texel cells: %s\n",
                c.message.c_str());
    EXPECT_TRUE(c.ok) << c.message;
}

// The bilinear lookup's sampling inside a texel (env_bilinear_in_texel): cells of a quarter
// texel, where the density is bilinear between the values at the quarter's corners, on the
// sun and sky (the sun's few texels hold most of the power, with steep gradients between
// them), plain and with MIS compensation's texel choice, and on a smooth map.
TEST(EnvironmentChi2, ChiSquareBilinearInsideTexels) {
    SunSkyParams p;
    EnvironmentMap sky = sun_sky_environment(p, 128);
    set_environment_rotation(sky, test_rotation());
    set_environment_filter(sky, FC_ENV_FILTER_BILINEAR);
    auto a = chi_square(sky, 1, 1, 18u, 4000000, 2);
    std::printf("[ chi2     ] bilinear sun and sky 128x64, quarter-texel cells: %s\n", a.message.c_str());
    EXPECT_TRUE(a.ok) << a.message;
    EnvironmentMap comp = sky;
    comp.distribution = compensated_environment_distribution(sky);
    auto b = chi_square(comp, 1, 1, 19u, 4000000, 2);
    std::printf("[ chi2     ] bilinear compensated sun and sky 128x64, quarter-texel cells: %s\n", b.message.c_str());
    EXPECT_TRUE(b.ok) << b.message;
    std::vector<std::string> warnings;
    EnvironmentMap smooth = environment_from_pixels(64, 32, smooth_map(64, 32), glm::vec3(1.0f, 0.5f, 2.0f),
                                                    test_rotation(), "smooth", warnings);
    set_environment_filter(smooth, FC_ENV_FILTER_BILINEAR);
    auto c = chi_square(smooth, 1, 1, 20u, 2000000, 2);
    std::printf("[ chi2     ] bilinear smooth 64x32, quarter-texel cells: %s\n", c.message.c_str());
    EXPECT_TRUE(c.ok) << c.message;
}

TEST(EnvironmentChi2, ChiSquareSunrise) {
    const std::filesystem::path file = std::filesystem::path(test::assets_dir()) / "env_blender" / "sunrise.exr";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    std::vector<std::string> warnings;
    EnvironmentMap e = load_environment_map(file.string(), glm::vec3(1.0f), test_rotation(), warnings);
    for (const std::string& w : warnings) std::printf("[ warning  ] %s\n", w.c_str());
    int block = 1;  // the largest power of 2 that tiles the map in cells of >= 1/128 of its width
    while (2 * block <= e.params.width / 128 && e.params.width % (2 * block) == 0 && e.params.height % (2 * block) == 0)
        block *= 2;
    auto r = chi_square(e, block, block, 14u);
    std::printf("[ chi2     ] sunrise.exr %dx%d, %dx%d-texel cells: %s\n", e.params.width, e.params.height, block,
                block, r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

}  // namespace
}  // namespace facet
