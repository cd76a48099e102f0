// SpecularF90.*: Schlick's Fresnel with a reflectance F90 at grazing incidence
// (FC_MAT_SPECULAR_F90, kernels/bsdf/fresnel.cl), KHR_materials_specular's dielectric F90 =
// specularFactor, on glTF's dielectric-metal mix with its energy compensation
// (energy_compensation.cl). A black base shows the specular lobe alone: specularFactor 0
// reflects nothing, 0.5 half of what 1 reflects even at grazing angles (with F90 fixed at 1
// the grazing reflectance hardly changes with the factor); a base under specularFactor 0 is
// the Lambert lobe alone; a white base reflects 1 at every F90 and metallic.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"
#include "tests/microfacet_test_util.hpp"

namespace facet {
namespace {

using namespace test::mf;

// glTF's material of base colour `base`, metallic M and GGX alpha under KHR_materials_specular's
// specularFactor s (F0 = 0.04 s, F90 = s), as the glTF reader makes it.
FcMaterial specular_material(glm::vec3 base, float metallic, float alpha, float s) {
    Material m = make_material("ggx");
    set_metallic_roughness(m, base, metallic, 0.04f * s);
    m.alpha_x = m.alpha_y = alpha;
    m.specular_f90 = s;
    return device_material(m);
}

constexpr double kThetas[] = {0.0, 60.0, 85.0};

// A black base shows the dielectric's specular lobe alone: at specularFactor 0 it reflects
// nothing at any angle, and at 0.5 half of what 1 reflects (F = s (0.04 + 0.96 (1 - c)^5)
// scales with s; the multiple-scattering term nearly so), at 85 degrees too.
TEST(SpecularF90, SpecularFactorScalesTheGrazingReflectance) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float alpha : {0.0f, 0.3f})
        for (float s : {1.0f, 0.5f, 0.0f})
            for (double t : kThetas) {
                mats.push_back(specular_material(glm::vec3(0.0f), 0.0f, alpha, s));
                wo.push_back(direction(t, 0.4));
            }
    const std::vector<Albedo> r = albedos(mats, wo, 1u << 14);
    std::size_t i = 0;
    for (float alpha : {0.0f, 0.3f}) {
        const Albedo* one = &r[i];
        const Albedo* half = &r[i + 3];
        const Albedo* zero = &r[i + 6];
        for (int k = 0; k < 3; ++k) {
            SCOPED_TRACE(testing::Message() << "alpha " << alpha << " theta_o " << kThetas[k]);
            EXPECT_EQ(zero[k].bad, 0);
            EXPECT_EQ(zero[k].mean[0], 0.0) << "specularFactor 0 reflects";
            EXPECT_NEAR(half[k].mean[0], 0.5 * one[k].mean[0],
                        0.03 * one[k].mean[0] + 4.0 * (half[k].error[0] + one[k].error[0]));
        }
        EXPECT_GT(one[2].mean[0], 0.1) << "the grazing reflectance at specularFactor 1";
        i += 9;
    }
}

// Under specularFactor 0 the material is its Lambert base alone: albedo = the base colour at
// every angle (the coupled diffuse takes all the energy the absent specular lobe leaves).
TEST(SpecularF90, SpecularFactorZeroLeavesTheDiffuseBase) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float alpha : {0.0f, 0.3f})
        for (double t : kThetas) {
            mats.push_back(specular_material(glm::vec3(0.6f, 0.4f, 0.2f), 0.0f, alpha, 0.0f));
            wo.push_back(direction(t, 1.1));
        }
    const std::vector<Albedo> r = albedos(mats, wo, 1u << 14);
    const double base[3] = {0.6, 0.4, 0.2};
    for (std::size_t i = 0; i < r.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(r[i].mean[c], base[c], 1e-3 + 4.0 * r[i].error[c]) << "material " << i << " channel " << c;
}

// A white base reflects 1 within 1% at specularFactor 0, 0.3 and 0.7 (F90 < 1), metallic 0 and
// 0.5, rough and mirror lobes, and never more than 1 beyond the tables' 0.3%.
TEST(SpecularF90, WhiteFurnaceHoldsBelowOne) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    const float factors[] = {0.0f, 0.3f, 0.7f}, metals[] = {0.0f, 0.5f}, alphas[] = {0.0f, 0.1f, 0.5f};
    for (float s : factors)
        for (float metal : metals)
            for (float a : alphas)
                for (double t : kThetas) {
                    mats.push_back(specular_material(glm::vec3(1.0f), metal, a, s));
                    wo.push_back(direction(t, 0.3));
                }
    const std::vector<Albedo> r = albedos(mats, wo, 1u << 15);
    std::size_t i = 0;
    for (float s : factors)
        for (float metal : metals)
            for (float a : alphas)
                for (double t : kThetas) {
                    const Albedo& e = r[i++];
                    EXPECT_EQ(e.bad, 0);
                    for (int c = 0; c < 3; ++c) {
                        EXPECT_NEAR(e.mean[c], 1.0, 0.01 + 4.0 * e.error[c])
                            << "specularFactor " << s << " metallic " << metal << " alpha " << a << " theta_o " << t;
                        EXPECT_LE(e.mean[c], 1.003 + 4.0 * e.error[c])
                            << "specularFactor " << s << " metallic " << metal << " alpha " << a << " theta_o " << t;
                    }
                }
}

}  // namespace
}  // namespace facet
