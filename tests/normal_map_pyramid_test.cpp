// Normal maps seen from afar (host/scene/normal_map_pyramid.hpp and add_normal_spread in
// kernels/texture/material_textures.cl): the smaller levels keep the bumps' spread as the
// mean normal's length, and the kernels turn it into roughness.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "host/scene/normal_map_pyramid.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "host/scene/texture_validate.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/texture_test_util.hpp"

namespace facet {
namespace {

// An 8 x 8 normal map of stripes tilted by +-theta about the bitangent in alternate columns.
TextureImage striped_normal_map(float theta) {
    std::vector<float> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float s = (x % 2 == 0 ? 1.0f : -1.0f) * std::sin(theta);
            rgba.insert(rgba.end(), {0.5f * s + 0.5f, 0.5f, 0.5f * std::cos(theta) + 0.5f, 1.0f});
        }
    return make_texture(8, 8, std::move(rgba));
}

// Level 0 as stored; every smaller level straight up with the length cos(theta) in alpha.
// The plain colour pyramid had the same direction at length 1: the stripes flattened into
// a mirror.
TEST(NormalMapPyramid, SmallerLevelsKeepTheSpreadInAlpha) {
    const float theta = 0.4f;
    TextureImage t = striped_normal_map(theta);
    const std::vector<float> level0(t.texels.begin(), t.texels.begin() + 4 * 64);
    build_normal_map_pyramid(t);
    EXPECT_EQ(t.levels, 4);
    for (std::size_t i = 0; i < level0.size(); ++i) EXPECT_FLOAT_EQ(t.texels[i], level0[i]);
    for (std::size_t i = 64; i < t.texels.size() / 4; ++i) {
        EXPECT_NEAR(t.texels[4 * i + 0], 0.5f, 1e-6f);
        EXPECT_NEAR(t.texels[4 * i + 1], 0.5f, 1e-6f);
        EXPECT_NEAR(t.texels[4 * i + 2], 1.0f, 1e-6f);
        EXPECT_NEAR(t.texels[4 * i + 3], std::cos(theta), 1e-6f) << "texel " << i;
    }
    // The kernels read it back through the trilinear lookup: alpha 1 at level 0, cos(theta) at 1.
    const std::vector<cl_float4> got =
        test::texture_lookup(t, {{{0.5f / 8, 0.5f / 8, 0.0f, 0.0f}}, {{0.5f / 4, 0.5f / 4, 1.0f, 0.0f}}});
    EXPECT_NEAR(got[0].s[3], 1.0f, 1e-6f);
    EXPECT_NEAR(got[1].s[3], std::cos(theta), 1e-3f);
}

// A normal map bound to a material gets this pyramid when the scene's textures are
// sanitised (load_scene does it for every file); a base-colour texture does not.
TEST(NormalMapPyramid, BuiltForNormalMapsOnly) {
    Scene scene;
    scene.textures = {striped_normal_map(0.4f), striped_normal_map(0.4f)};
    Material m = default_material();
    m.textures.normal = 0;
    m.textures.base_color = 1;
    scene.materials.push_back(m);
    sanitise_textures(scene);
    EXPECT_NEAR(scene.textures[0].texels[4 * 64 + 3], std::cos(0.4f), 1e-6f);
    EXPECT_EQ(scene.textures[1].texels[4 * 64 + 3], 1.0f);
}

// add_normal_spread: alpha^2 grows by 2 (1 - r^2) / (3 r - r^3) scale^2 (a vMF lobe of mean
// length r, Han et al. 2007), and not at all for r = 1 or scale 0; capped at alpha 1.
TEST(NormalMapPyramid, SpreadBecomesRoughness) {
    ClContext& ctx = test::context();
    const std::vector<cl_float4> in = {{{0.1f, 0.2f, 1.0f, 1.0f}},
                                       {{0.1f, 0.2f, std::cos(0.3f), 1.0f}},
                                       {{0.1f, 0.2f, std::cos(0.3f), 0.5f}},
                                       {{0.1f, 0.2f, 0.5f, 0.0f}},
                                       {{0.1f, 0.2f, 0.0f, 1.0f}}};
    cl::Kernel k(test::program("kernels/test/texture_kernels.cl"), "normal_spread_batch");
    cl::Buffer ib(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(cl_float4),
                  const_cast<cl_float4*>(in.data()));
    cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, in.size() * sizeof(cl_float4));
    k.setArg(0, ib);
    k.setArg(1, ob);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(in.size()));
    std::vector<cl_float4> out(in.size());
    ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, out.size() * sizeof(cl_float4), out.data());
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double r = std::max(double(in[i].s[2]), 1e-3), scale = in[i].s[3];
        const double spread = r < 1.0 ? 2.0 * (1.0 - r * r) / (3.0 * r - r * r * r) * scale * scale : 0.0;
        for (int a = 0; a < 2; ++a) {
            const double alpha = in[i].s[a];
            const double want = std::sqrt(std::min(alpha * alpha + spread, 1.0));
            EXPECT_NEAR(out[i].s[a], want, 1e-5 * want) << "case " << i << " axis " << a;
            EXPECT_NEAR(out[i].s[2 + a], std::min(2.0 / (want * want) - 2.0, double(FC_PHONG_EXPONENT_MAX)),
                        1e-3 * double(out[i].s[2 + a]) + 1e-3);
        }
    }
    EXPECT_NEAR(double(out[1].s[0] * out[1].s[0]) - 0.01, 0.3 * 0.3, 0.01);  // small tilts: alpha^2 grows by ~theta^2
}

}  // namespace
}  // namespace facet
