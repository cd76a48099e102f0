// Metallic.*: glTF's metallic-roughness BRDF (kernels/bsdf/metallic.cl), a dielectric and a
// metal mixed linearly by metallic M: white furnaces at M = 0, 0.25, 0.5, 0.75, 1 (the
// directional albedo of a white base is 1 within 1%), the same furnace of the mix as facet
// built it before (the metal's F0 in the diffuse's coupling) for comparison, and a
// chi-square test of bsdf_sample's mixture against bsdf_pdf.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"
#include "tests/chi2_test_util.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/microfacet_test_util.hpp"

namespace facet {
namespace {

using namespace test::mf;

constexpr float kMetallic[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
constexpr float kAlphas[] = {0.05f, 0.25f, 0.5f, 1.0f};
constexpr double kThetas[] = {0.0, 40.0, 70.0, 85.0};

// glTF's material of base colour `base`, metallic M and GGX alpha, as the glTF reader makes it.
FcMaterial gltf_material(glm::vec3 base, float metallic, float alpha) {
    Material m = make_material("ggx");
    set_metallic_roughness(m, base, metallic, 0.04f);
    m.alpha_x = m.alpha_y = alpha;
    return device_material(m);
}

// The same as facet built it before: diffuse B (1 - M) coupled to F0 = mix(0.04, B, M).
FcMaterial premixed_material(glm::vec3 base, float metallic, float alpha) {
    Material m = make_material("ggx");
    m.diffuse = base * (1.0f - metallic);
    m.f0 = m.ks = m.transmittance = glm::mix(glm::vec3(0.04f), base, metallic);
    if (metallic >= 1.0f) m.diffuse_model = FC_DIFFUSE_NONE;
    m.alpha_x = m.alpha_y = alpha;
    return device_material(m);
}

// A white base in a white furnace reflects everything at every metallic, alpha and angle
// (within 1% plus 4 standard errors); printed beside the premixed model's albedo.
TEST(Metallic, WhiteFurnaceAtEveryMetallic) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float metal : kMetallic)
        for (float a : kAlphas)
            for (double t : kThetas) {
                mats.push_back(gltf_material(glm::vec3(1.0f), metal, a));
                mats.push_back(premixed_material(glm::vec3(1.0f), metal, a));
                wo.push_back(direction(t, 0.3));
                wo.push_back(direction(t, 0.3));
            }
    const std::vector<Albedo> r = albedos(mats, wo, 1u << 16);
    std::printf("\nwhite base, albedo glTF mix / premixed (before)\n| metallic | alpha |");
    for (double t : kThetas) std::printf(" %g deg |", t);
    std::printf("\n");
    double worst = 0.0;
    std::size_t i = 0;
    for (float metal : kMetallic)
        for (float a : kAlphas) {
            std::printf("| %.2f | %.2f |", double(metal), double(a));
            for (double t : kThetas) {
                const Albedo &mix = r[i], &old = r[i + 1];
                i += 2;
                std::printf(" %.3f / %.3f |", mix.mean[0], old.mean[0]);
                EXPECT_EQ(mix.bad, 0);
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::fabs(mix.mean[c] - 1.0));
                    EXPECT_NEAR(mix.mean[c], 1.0, 0.01 + 4.0 * mix.error[c])
                        << "metallic " << metal << " alpha " << a << " theta_o " << t << " channel " << c;
                }
            }
            std::printf("\n");
        }
    std::printf("worst |albedo - 1|: %.4f\n", worst);
}

// bsdf_sample draws the mixture with the density bsdf_pdf gives (coloured base, so the
// dielectric's and the metal's Fresnel differ), for M in {0.3, 0.7} x alpha x theta_o.
TEST(Metallic, ChiSquareOfTheMixture) {
    const double level = test::chi2::sidak(0.01, 2 * 2 * 3);
    unsigned seed = 7000u;
    for (float metal : {0.3f, 0.7f})
        for (float a : {0.1f, 0.5f}) {
            const FcMaterial m = gltf_material(glm::vec3(0.9f, 0.5f, 0.2f), metal, a);
            for (double deg : {0.0, 45.0, 80.0}) {
                const Vec3 w = direction(deg, 0.7);
                const auto r = chi_square(m, w, kModeBsdf, mirror(w), 2.0 * double(a), level, seed++);
                EXPECT_TRUE(r.ok) << "metallic " << metal << " alpha " << a << " theta_o " << deg << ": " << r.message;
            }
        }
}

// Every non-delta sample's weight is its f cos / pdf (bsdf_eval and bsdf_pdf at its wi).
TEST(Metallic, SamplesAgreeWithEvalAndPdf) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, u;
    for (float metal : {0.25f, 0.5f, 0.75f})
        for (float a : {0.0f, 0.2f})
            for (int k = 0; k < 64; ++k) {
                mats.push_back(gltf_material(glm::vec3(0.9f, 0.5f, 0.2f), metal, a));
                wo.push_back(f4(direction(5.0 + 1.2 * k, 0.3 * k)));
                u.push_back(
                    {{float(k % 8) / 8.0f + 0.05f, float(k / 8) / 8.0f + 0.05f, float((k * 37) % 64) / 64.0f, 0.0f}});
            }
    const std::vector<cl_float4> out = consistency(mats, wo, u);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const cl_float4 got = out[4 * i + 2], expect = out[4 * i + 3];
        if (got.s[3] == 0.0f || expect.s[3] != 0.0f) continue;  // refused, or a delta
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got.s[c], expect.s[c], 1e-3f * std::max(1.0f, expect.s[c])) << "sample " << i;
    }
}

}  // namespace
}  // namespace facet
