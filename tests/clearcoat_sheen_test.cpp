// ClearcoatSheen.*: glTF's clearcoat and sheen layers (kernels/bsdf/clearcoat.cl,
// kernels/bsdf/sheen.cl, layered in kernels/bsdf/bsdf.cl): white furnaces at metallic 0,
// 0.25, 0.5, 0.75, 1 with and without a clearcoat (alpha 0.1, 0.5) and a white sheen
// (roughness 0.3, 1) reflect 1 within 1% and never more; bsdf_sample draws the layered
// mixture with bsdf_pdf's density (chi-square) and its weights are f cos / pdf; with the
// layers at 0 the generic program gives what a program without them gives, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "tests/chi2_test_util.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/microfacet_test_util.hpp"

namespace facet {
namespace {

using namespace test::mf;

// A layer configuration: clearcoat weight and alpha, sheen colour (grey) and roughness.
struct Layers {
    const char* name;
    float clearcoat, clearcoat_alpha, sheen, sheen_roughness;
};

constexpr Layers kLayers[] = {
    {"none", 0.0f, 0.0f, 0.0f, 0.0f},
    {"coat a 0.1", 1.0f, 0.1f, 0.0f, 0.0f},
    {"coat a 0.5", 1.0f, 0.5f, 0.0f, 0.0f},
    {"sheen r 0.3", 0.0f, 0.0f, 1.0f, 0.3f},
    {"sheen r 1", 0.0f, 0.0f, 1.0f, 1.0f},
    {"coat 0.1 + sheen 0.3", 1.0f, 0.1f, 1.0f, 0.3f},
    {"coat 0.5 + sheen 1", 1.0f, 0.5f, 1.0f, 1.0f},
};
constexpr float kMetallic[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
constexpr float kBaseAlphas[] = {0.3f};
constexpr double kThetas[] = {0.0, 60.0, 85.0};

// glTF's material of base colour `base`, metallic M and GGX alpha, as the glTF reader makes
// it, with the layers of `l`.
FcMaterial layered_material(glm::vec3 base, float metallic, float alpha, const Layers& l) {
    Material m = make_material("ggx");
    set_metallic_roughness(m, base, metallic, 0.04f);
    m.alpha_x = m.alpha_y = alpha;
    m.clearcoat = l.clearcoat;
    m.clearcoat_alpha = l.clearcoat_alpha;
    m.sheen = glm::vec3(l.sheen);
    m.sheen_roughness = l.sheen_roughness;
    return device_material(m);
}

// A white base under every layer configuration reflects 1 within 1% (plus 4 standard
// errors) at every metallic, base alpha and angle, and never more than 1 (beyond 0.3% of
// table interpolation and 4 standard errors). Prints the table of docs/brdf.md
// (FACET_FURNACE_SAMPLES sets the samples per direction, 2^15 by default).
TEST(ClearcoatSheen, WhiteFurnaceAtEveryMetallic) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (const Layers& l : kLayers)
        for (float metal : kMetallic)
            for (float a : kBaseAlphas)
                for (double t : kThetas) {
                    mats.push_back(layered_material(glm::vec3(1.0f), metal, a, l));
                    wo.push_back(direction(t, 0.3));
                }
    const unsigned samples =
        std::getenv("FACET_FURNACE_SAMPLES") ? unsigned(std::atoi(std::getenv("FACET_FURNACE_SAMPLES"))) : 1u << 15;
    const std::vector<Albedo> r = albedos(mats, wo, samples);
    std::printf("\nwhite base, albedo (theta_o 0 / 60 / 85 deg)\n| layers | metallic | alpha |");
    std::printf(" albedo |\n");
    double worst = 0.0, highest = 0.0;
    std::size_t i = 0;
    for (const Layers& l : kLayers)
        for (float metal : kMetallic)
            for (float a : kBaseAlphas) {
                std::printf("| %s | %.2f | %.1f |", l.name, double(metal), double(a));
                for (double t : kThetas) {
                    const Albedo& e = r[i++];
                    std::printf(" %.4f", e.mean[0]);
                    EXPECT_EQ(e.bad, 0);
                    for (int c = 0; c < 3; ++c) {
                        worst = std::max(worst, std::fabs(e.mean[c] - 1.0));
                        highest = std::max(highest, e.mean[c]);
                        EXPECT_NEAR(e.mean[c], 1.0, 0.01 + 4.0 * e.error[c])
                            << l.name << " metallic " << metal << " alpha " << a << " theta_o " << t;
                        EXPECT_LE(e.mean[c], 1.003 + 4.0 * e.error[c])
                            << l.name << " metallic " << metal << " alpha " << a << " theta_o " << t;
                    }
                }
                std::printf(" |\n");
            }
    std::printf("worst |albedo - 1|: %.4f, highest albedo %.4f\n", worst, highest);
}

// bsdf_sample draws the layered mixture with the density bsdf_pdf gives (coloured base and
// sheen), for coat alphas 0.1 and 0.5 and two sheens, at two angles.
TEST(ClearcoatSheen, ChiSquareOfTheLayers) {
    const Layers cases[] = {
        {"coat 0.1", 1.0f, 0.1f, 0.0f, 0.0f},
        {"coat 0.5 + sheen 0.3", 0.7f, 0.5f, 0.8f, 0.3f},
        {"sheen 1", 0.0f, 0.0f, 0.6f, 1.0f},
    };
    const double level = test::chi2::sidak(0.01, 3 * 2);
    unsigned seed = 8100u;
    for (const Layers& l : cases) {
        FcMaterial m = layered_material(glm::vec3(0.9f, 0.5f, 0.2f), 0.4f, 0.3f, l);
        m.sheen[1] *= 0.5f;
        const double width = 2.0 * double(std::max(l.clearcoat_alpha, 0.3f));
        for (double deg : {10.0, 75.0}) {
            const Vec3 w = direction(deg, 0.7);
            const auto r = chi_square(m, w, kModeBsdf, mirror(w), width, level, seed++);
            EXPECT_TRUE(r.ok) << l.name << " theta_o " << deg << ": " << r.message;
        }
    }
}

// Every non-delta sample's weight is its f cos / pdf (bsdf_eval and bsdf_pdf at its wi), and
// a mirror coat's delta samples carry c F(mu_o) / p_coat.
TEST(ClearcoatSheen, SamplesAgreeWithEvalAndPdf) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, u;
    const Layers cases[] = {
        {"coat 0.2", 0.8f, 0.2f, 0.0f, 0.0f},
        {"mirror coat + sheen", 1.0f, 0.0f, 0.5f, 0.5f},
        {"sheen", 0.0f, 0.0f, 0.9f, 0.2f},
    };
    for (const Layers& l : cases)
        for (float a : {0.0f, 0.2f})
            for (int k = 0; k < 64; ++k) {
                mats.push_back(layered_material(glm::vec3(0.9f, 0.5f, 0.2f), 0.5f, a, l));
                wo.push_back(f4(direction(5.0 + 1.2 * k, 0.3 * k)));
                u.push_back(
                    {{float(k % 8) / 8.0f + 0.05f, float(k / 8) / 8.0f + 0.05f, float((k * 37) % 64) / 64.0f, 0.0f}});
            }
    const std::vector<cl_float4> out = consistency(mats, wo, u);
    int checked = 0;
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const cl_float4 got = out[4 * i + 2], expect = out[4 * i + 3];
        if (got.s[3] == 0.0f || expect.s[3] != 0.0f) continue;  // refused, or a delta
        ++checked;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got.s[c], expect.s[c], 1e-3f * std::max(1.0f, expect.s[c])) << "sample " << i;
    }
    EXPECT_GT(checked, int(mats.size()) / 2);
}

// With clearcoat and sheen at 0 the generic program (layers compiled in) samples, evaluates
// and weighs every material exactly as a program built without the layers does.
TEST(ClearcoatSheen, LayersOffAreTheOldMaterialBitForBit) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, u;
    for (float metal : kMetallic)
        for (float a : {0.0f, 0.05f, 0.4f})
            for (int k = 0; k < 32; ++k) {
                mats.push_back(layered_material(glm::vec3(0.8f, 0.6f, 0.3f), metal, a, kLayers[0]));
                wo.push_back(f4(direction(3.0 + 2.7 * k, 0.4 * k)));
                u.push_back(
                    {{float(k % 4) / 4.0f + 0.1f, float(k / 4) / 8.0f + 0.03f, float((k * 13) % 32) / 32.0f, 0.0f}});
            }
    auto run = [&](const char* entry) {
        cl::Buffer mb = upload(mats), a = upload(wo), b = upload(u);
        cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, 4 * mats.size() * sizeof(cl_float4));
        cl::Kernel k(test::program(entry), "mf_consistency");
        k.setArg(0, mb), k.setArg(1, a), k.setArg(2, b), k.setArg(3, out);
        test::context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
        return download<cl_float4>(out, 4 * mats.size());
    };
    const std::vector<cl_float4> generic = run("kernels/test/microfacet_kernels.cl");
    const std::vector<cl_float4> off = run("kernels/test/layers_off_kernels.cl");
    ASSERT_EQ(generic.size(), off.size());
    int live = 0;
    for (std::size_t i = 0; i < mats.size(); ++i) {
        // bsdf_sample's weight and success, then f cos / pdf at its wi (a refused sample's
        // weight is undefined: only the refusal is compared)
        const cl_float4 *g = &generic[4 * i + 2], *o = &off[4 * i + 2];
        ASSERT_EQ(g[0].s[3], o[0].s[3]) << "sample " << i;
        if (g[0].s[3] == 0.0f) continue;
        ++live;
        EXPECT_EQ(std::memcmp(g, o, 2 * sizeof(cl_float4)), 0) << "sample " << i;
    }
    EXPECT_GT(live, int(mats.size()) / 2);
}

// The render tier's furnace: a white sphere (analytic) of glTF's material at metallic 0, 0.25,
// 0.5, 0.75, 1, bare and under a clearcoat (alpha 0.1) and a white sheen (roughness 0.5), in
// a constant environment L = 0.7, renders L within 1 % (the mean over the image, the sphere
// filling most of it), through the integrator's next-event estimation and MIS.
TEST(ClearcoatSheen, FurnaceSphereRender) {
    const Layers cases[] = {kLayers[0], {"coat 0.1 + sheen 0.5", 1.0f, 0.1f, 1.0f, 0.5f}};
    for (const Layers& l : cases)
        for (float metal : kMetallic) {
            Material m = make_material("ggx");
            set_metallic_roughness(m, glm::vec3(1.0f), metal, 0.04f);
            m.alpha_x = m.alpha_y = 0.3f;
            m.clearcoat = l.clearcoat;
            m.clearcoat_alpha = l.clearcoat_alpha;
            m.sheen = glm::vec3(l.sheen);
            m.sheen_roughness = l.sheen_roughness;
            Scene scene;
            add_material(scene, m, "m");
            add_analytic_sphere(scene, glm::vec3(0.0f), 1.0f, 0, false);
            scene.camera.eye = glm::vec3(0.0f, 0.0f, 3.0f);
            scene.camera.target = glm::vec3(0.0f);
            scene.camera.fov_y_degrees = 40.0f;
            scene.settings.width = scene.settings.height = 24;
            scene.settings.max_depth = 8;
            scene.environment = constant_environment(glm::vec3(0.7f));
            build_lights(scene);
            Bvh bvh = build_bvh(scene.vertices);
            Renderer r(test::context(), scene, bvh);
            render_fixed(r, 64, 16);
            double rejected = -1.0;
            const std::vector<float> img = r.image(&rejected);
            double mean = 0.0;
            for (float v : img) mean += double(v) / double(img.size());
            std::printf("[ furnace  ] %s, metallic %.2f: mean %.5f (L = 0.7)\n", l.name, double(metal), mean);
            EXPECT_EQ(rejected, 0.0);
            EXPECT_NEAR(mean, 0.7, 0.007) << l.name << " metallic " << metal;
        }
}

// A coat with a normal of its own (FC_MAT_CLEARCOAT_NORMAL, in the shading frame), tilted 30
// degrees toward +x, over a base that reflects nothing (black, specularFactor 0): seen from 60
// degrees on that side it reflects what an untilted coat does from 30 degrees (its own angle;
// ignoring the normal it would reflect the 60-degree Fresnel, about 0.07 instead of 0.04), and
// bsdf_sample draws it with bsdf_pdf's density, its weights f cos / pdf.
FcMaterial tilted_coat(float alpha, float tilt_deg) {
    Material m = make_material("ggx");
    set_metallic_roughness(m, glm::vec3(0.0f), 0.0f, 0.0f);
    m.specular_f90 = 0.0f;
    m.clearcoat = 1.0f;
    m.clearcoat_alpha = alpha;
    FcMaterial d = device_material(m);
    const Vec3 n = direction(tilt_deg, 0.0);
    if (tilt_deg != 0.0f) {
        d.flags |= FC_MAT_CLEARCOAT_NORMAL;
        d.clearcoat_normal[0] = float(n.x), d.clearcoat_normal[1] = float(n.y), d.clearcoat_normal[2] = float(n.z);
    }
    return d;
}

TEST(ClearcoatSheen, CoatReflectsAboutItsOwnNormal) {
    const std::vector<Albedo> r = albedos({tilted_coat(0.05f, 30.0f), tilted_coat(0.05f, 0.0f)},
                                          {direction(60.0, 0.0), direction(30.0, 0.0)}, 1u << 16);
    EXPECT_GT(r[1].mean[0], 0.02);
    EXPECT_NEAR(r[0].mean[0], r[1].mean[0], 0.02 * r[1].mean[0] + 4.0 * (r[0].error[0] + r[1].error[0]));
}

TEST(ClearcoatSheen, CoatWithItsOwnNormalSamplesItsPdf) {
    FcMaterial m = tilted_coat(0.2f, 20.0f);
    for (int c = 0; c < 3; ++c) m.diffuse[c] = 0.5f;  // a base to share the samples with
    const double level = test::chi2::sidak(0.01, 2);
    unsigned seed = 8300u;
    for (double deg : {15.0, 70.0}) {
        const Vec3 w = direction(deg, 0.5);
        const auto r = chi_square(m, w, kModeBsdf, mirror(w), 0.6, level, seed++);
        EXPECT_TRUE(r.ok) << "theta_o " << deg << ": " << r.message;
    }
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, u;
    for (int k = 0; k < 64; ++k) {
        mats.push_back(m);
        wo.push_back(f4(direction(5.0 + 1.2 * k, 0.3 * k)));
        u.push_back({{float(k % 8) / 8.0f + 0.05f, float(k / 8) / 8.0f + 0.05f, float((k * 37) % 64) / 64.0f, 0.0f}});
    }
    const std::vector<cl_float4> out = consistency(mats, wo, u);
    int checked = 0;
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const cl_float4 got = out[4 * i + 2], expect = out[4 * i + 3];
        if (got.s[3] == 0.0f || expect.s[3] != 0.0f) continue;
        ++checked;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got.s[c], expect.s[c], 1e-3f * std::max(1.0f, expect.s[c])) << "sample " << i;
    }
    EXPECT_GT(checked, int(mats.size()) / 2);
}

}  // namespace
}  // namespace facet
