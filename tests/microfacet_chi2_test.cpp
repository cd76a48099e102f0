// Statistical tests of the samplers (the rest is in microfacet_test.cpp): every sampler
// of kernels/bsdf/ against its pdf by a chi-square test (chi2_test_util.hpp), >= 1e6
// samples per configuration: the microfacet lobe for GGX (Heitz 2018's visible normals,
// D cos, spherical caps, bounded visible normals) and Beckmann (visible / all normals) x
// 7 roughnesses and 2 anisotropic pairs x 6 view angles (F = 1), Blinn-Phong's NDF, the
// normals themselves, and through bsdf_sample the Blinn-Phong lobes, Ashikhmin-Shirley,
// the diffuse lobes (EON's CLTC sampling included), diffuse + specular mixtures and the
// energy-compensated lobes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "tests/chi2_test_util.hpp"
#include "tests/microfacet_test_util.hpp"

namespace facet {
namespace {

using namespace test::mf;

// ---- the chi-square grid ---------------------------------------------------------------

constexpr double kAngles[] = {0.0, 15.0, 30.0, 60.0, 80.0, 89.0};
constexpr float kAlphas[] = {0.002f, 0.01f, 0.05f, 0.1f, 0.3f, 0.5f, 1.0f};
constexpr float kAniso[][2] = {{0.05f, 0.3f}, {0.3f, 0.05f}};

// Every chi-square test of this file, for the Sidak correction.
constexpr int kNdfGrid = (7 + 2) * 6;  // per NDF and sampler: alphas x angles
constexpr int kChi2Tests = 6 * kNdfGrid + 5 * 6 + 54 + 18 * 4;
const double kLevel = test::chi2::sidak(0.01, kChi2Tests);

// GGX has four samplers (Heitz 2018 the oracle, D cos, spherical caps, bounded); Beckmann two.
std::vector<int> samplers(int ndf) {
    if (ndf == FC_NDF_GGX) return {FC_SAMPLE_VISIBLE, FC_SAMPLE_ALL, FC_SAMPLE_SPHERICAL_CAP, FC_SAMPLE_BOUNDED};
    return {FC_SAMPLE_VISIBLE, FC_SAMPLE_ALL};
}

void chi_square_ndf(int ndf) {
    int run = 0, failed = 0;
    for (int sampling : samplers(ndf))
        for (int a = 0; a < 9; ++a)
            for (double deg : kAngles) {
                float ax = a < 7 ? kAlphas[a] : kAniso[a - 7][0];
                float ay = a < 7 ? kAlphas[a] : kAniso[a - 7][1];
                FcMaterial m = microfacet_material(ndf, sampling, ax, ay);
                Vec3 wo = direction(deg, 0.7);
                auto r = chi_square(m, wo, kModeMicrofacet, mirror(wo), 2.0 * double(std::min(ax, ay)), kLevel,
                                    1000u + unsigned(run));
                ++run;
                failed += r.ok ? 0 : 1;
                if (sampling >= FC_SAMPLE_SPHERICAL_CAP && a == 4)
                    std::printf("[ chi2     ] sampler %d alpha %g theta_o %g: refused %.4f\n", sampling, double(ax),
                                deg, double(r.refused) / double(std::uint64_t(kItems) * kPerItem));
                EXPECT_TRUE(r.ok) << "ndf " << ndf << " sampling " << sampling << " alpha (" << ax << ", " << ay
                                  << ") theta_o " << deg << ": " << r.message;
            }
    std::printf("[ chi2     ] ndf %d: %d configurations, %d failed\n", ndf, run, failed);
}

TEST(MicrofacetChi2, ChiSquareGgx) { chi_square_ndf(FC_NDF_GGX); }

TEST(MicrofacetChi2, ChiSquareBeckmann) { chi_square_ndf(FC_NDF_BECKMANN); }

TEST(MicrofacetChi2, ChiSquareBlinnPhongNdf) {
    for (float e : {2.0f, 20.0f, 200.0f, 2000.0f, 20000.0f})
        for (double deg : kAngles) {
            FcMaterial m = microfacet_material(FC_NDF_BLINN_PHONG, FC_SAMPLE_VISIBLE, 0.0f, 0.0f);
            m.exponent_x = e;
            Vec3 wo = direction(deg, 0.7);
            double alpha = std::sqrt(2.0 / (double(e) + 2.0));
            auto r = chi_square(m, wo, kModeMicrofacet, mirror(wo), 2.0 * alpha, kLevel, 2000u);
            EXPECT_TRUE(r.ok) << "exponent " << e << " theta_o " << deg << ": " << r.message;
        }
}

// The normals themselves (h-space), against ndf_pdf.
TEST(MicrofacetChi2, ChiSquareNormals) {
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN})
        for (int sampling : samplers(ndf))
            for (int a = 0; a < 3; ++a)
                for (double deg : {0.0, 60.0, 89.0}) {
                    float ax = a == 0 ? 0.01f : a == 1 ? 0.3f : 0.05f;
                    float ay = a == 2 ? 0.3f : ax;
                    FcMaterial m = microfacet_material(ndf, sampling, ax, ay);
                    Vec3 wo = direction(deg, 0.7);
                    auto r = chi_square(m, wo, kModeNdf, Vec3{0, 0, 1}, double(std::min(ax, ay)), kLevel, 3000u);
                    EXPECT_TRUE(r.ok) << "ndf " << ndf << " sampling " << sampling << " alpha (" << ax << ", " << ay
                                      << ") theta_o " << deg << ": " << r.message;
                }
}

// The other lobes and mixtures, through bsdf_sample / bsdf_pdf.
TEST(MicrofacetChi2, ChiSquareBsdf) {
    std::vector<std::pair<FcMaterial, double>> cases;  // material, lobe width
    auto add = [&](FcMaterial m, double w) { cases.emplace_back(m, w); };
    for (int model : {FC_SPECULAR_BLINN_PHONG, FC_SPECULAR_BLINN_PHONG_NORMALIZED})
        for (float e : {10.0f, 1000.0f}) {
            FcMaterial m = lobe_material(FC_DIFFUSE_NONE, model);
            m.exponent_x = m.exponent_y = e;
            add(m, 2.0 * std::sqrt(2.0 / (double(e) + 2.0)));
        }
    for (auto [nu, nv] : {std::pair{10.0f, 10.0f}, std::pair{100.0f, 1000.0f}}) {
        FcMaterial m = lobe_material(FC_DIFFUSE_ASHIKHMIN_SHIRLEY, FC_SPECULAR_ASHIKHMIN_SHIRLEY);
        m.exponent_x = nu;
        m.exponent_y = nv;
        add(m, 2.0 * std::sqrt(2.0 / (double(std::min(nu, nv)) + 2.0)));
    }
    add(lobe_material(FC_DIFFUSE_LAMBERT, FC_SPECULAR_NONE), 10.0);
    add(lobe_material(FC_DIFFUSE_OREN_NAYAR, FC_SPECULAR_NONE), 10.0);
    for (auto [ndf, alpha] :
         {std::pair{FC_NDF_GGX, 0.1f}, std::pair{FC_NDF_BECKMANN, 0.02f}, std::pair{FC_NDF_GGX, 0.5f}}) {
        FcMaterial m = microfacet_material(ndf, FC_SAMPLE_VISIBLE, alpha, alpha);
        m.diffuse_model = FC_DIFFUSE_LAMBERT_1MF0;
        m.fresnel = FC_FRESNEL_SCHLICK;
        add(m, 2.0 * double(alpha));
    }
    // energy-compensated lobes (the f_ms mixture) and EON's CLTC sampling
    for (auto [ndf, alpha] : {std::pair{FC_NDF_GGX, 0.5f}, std::pair{FC_NDF_BECKMANN, 0.75f}}) {
        FcMaterial m = microfacet_material(ndf, FC_SAMPLE_VISIBLE, alpha, alpha);
        m.flags = FC_MAT_ENERGY_COMPENSATION;
        add(m, 2.0 * double(alpha));
        m.diffuse_model = FC_DIFFUSE_LAMBERT_1MF0;
        m.fresnel = FC_FRESNEL_SCHLICK;
        add(m, 2.0 * double(alpha));
    }
    for (float r : {0.3f, 1.0f}) {
        FcMaterial m = lobe_material(FC_DIFFUSE_EON, FC_SPECULAR_NONE);
        m.sigma = r;
        add(m, 10.0);
    }
    {
        FcMaterial m = microfacet_material(FC_NDF_GGX, FC_SAMPLE_BOUNDED, 0.3f, 0.3f);
        m.diffuse_model = FC_DIFFUSE_EON;
        m.fresnel = FC_FRESNEL_SCHLICK;
        add(m, 0.6);
    }
    ASSERT_EQ(cases.size(), 18u);
    for (std::size_t c = 0; c < cases.size(); ++c)
        for (double deg : {0.0, 30.0, 60.0, 85.0}) {
            Vec3 wo = direction(deg, 0.7);
            auto r =
                chi_square(cases[c].first, wo, kModeBsdf, mirror(wo), cases[c].second, kLevel, 4000u + unsigned(c));
            EXPECT_TRUE(r.ok) << "case " << c << " (diffuse " << cases[c].first.diffuse_model << ", specular "
                              << cases[c].first.specular_model << ") theta_o " << deg << ": " << r.message;
        }
}

}  // namespace
}  // namespace facet
