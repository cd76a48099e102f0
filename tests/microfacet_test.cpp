// The microfacet BRDF (kernels/bsdf/{ggx,beckmann,blinn_phong_ndf,ndf,geometry,microfacet}.cl)
// and the BSDF dispatcher over every model; the chi-square tests of the samplers are in
// microfacet_chi2_test.cpp.
//  - Chi2Harness: the harness catches a 3% error in alpha, and its incomplete gamma;
//  - PdfIntegratesToOne: normals' pdf = 1, the lobe's <= 1 (= 1 when it stays above);
//  - WeakWhiteFurnace: int D G1 max(0, wo.m) / cos_o dm = 1 (Heitz 2014, eq. 22);
//  - GeometryMatchesReference: every G against double-precision formulas;
//  - SampleMatchesEvalAndPdf: samplers report eval/pdf of what they sample;
//  - ExtremeSweep: finite, non-negative outputs over extreme parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "tests/microfacet_test_util.hpp"

namespace facet {
namespace {

using namespace test::mf;

// ---- double-precision references ----------------------------------------------------

double ref_lambda(const FcMaterial& m, const double w[3]) {
    double ax = m.alpha_x, ay = m.alpha_y;
    if (m.ndf == FC_NDF_BLINN_PHONG) ax = ay = std::sqrt(2.0 / (double(m.exponent_x) + 2.0));
    double s = std::hypot(ax * w[0], ay * w[1]);
    if (m.ndf == FC_NDF_GGX) return 0.5 * (std::sqrt(1.0 + s * s / (w[2] * w[2])) - 1.0);  // Heitz 2014, eq. 86
    double a = w[2] / s;                                                                   // eq. 83
    return 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(std::numbers::pi));
}

void reference_geometry(const FcMaterial& m, const cl_float4& o, const cl_float4& i, double g[FC_G_COUNT]) {
    const double wo[3] = {o.s[0], o.s[1], o.s[2]}, wi[3] = {i.s[0], i.s[1], i.s[2]};
    double h[3] = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
    double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (double& c : h) c /= len;
    double vh = wo[0] * h[0] + wo[1] * h[1] + wo[2] * h[2];
    double lo = ref_lambda(m, wo), li = ref_lambda(m, wi);
    double ax = m.alpha_x, ay = m.alpha_y;
    if (m.ndf == FC_NDF_BLINN_PHONG) ax = ay = std::sqrt(2.0 / (double(m.exponent_x) + 2.0));
    auto alpha_w = [&](const double* w) {  // projected roughness
        double r2 = w[0] * w[0] + w[1] * w[1];
        return std::sqrt((ax * ax * w[0] * w[0] + ay * ay * w[1] * w[1]) / r2);
    };
    auto schlick = [&](const double* w) {
        double k = alpha_w(w) * std::sqrt(2.0 / std::numbers::pi);
        return w[2] / (w[2] * (1.0 - k) + k);
    };
    auto walter = [&](const double* w) {
        double a = w[2] / (alpha_w(w) * std::sqrt(1.0 - w[2] * w[2]));
        return a < 1.6 ? (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a) : 1.0;
    };
    g[FC_G_IMPLICIT] = wo[2] * wi[2];
    g[FC_G_COOK_TORRANCE] = std::min({1.0, 2.0 * h[2] * wo[2] / vh, 2.0 * h[2] * wi[2] / vh});
    g[FC_G_SMITH_SEPARABLE] = 1.0 / ((1.0 + lo) * (1.0 + li));
    g[FC_G_SMITH_CORRELATED] = 1.0 / (1.0 + lo + li);
    g[FC_G_SMITH_SCHLICK] = schlick(wo) * schlick(wi);
    g[FC_G_SMITH_WALTER] = walter(wo) * walter(wi);
}

// A material of random models and parameters; alpha log-uniform in [10^lo, 1].
FcMaterial random_material(std::mt19937& rng, double lo) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto pick = [&](int n) { return int(u(rng) * n) % n; };
    FcMaterial m = lobe_material(pick(FC_DIFFUSE_COUNT), pick(FC_SPECULAR_COUNT));
    m.ndf = pick(FC_NDF_COUNT);
    m.geometry = pick(FC_G_COUNT);
    m.fresnel = pick(FC_FRESNEL_COUNT);
    m.sampling = pick(2);
    m.alpha_x = float(std::pow(10.0, lo * u(rng)));
    m.alpha_y = u(rng) < 0.5 ? m.alpha_x : float(std::pow(10.0, lo * u(rng)));
    m.exponent_x = float(std::pow(10.0, 4.0 * u(rng)));
    m.exponent_y = float(std::pow(10.0, 4.0 * u(rng)));
    m.ior = float(1.0 + 3.0 * u(rng));
    m.sigma = float(1.5 * u(rng));
    for (int c = 0; c < 3; ++c) {
        m.diffuse[c] = float(u(rng));
        m.specular[c] = float(u(rng));
        m.eta[c] = float(0.2 + 3.0 * u(rng));
        m.k[c] = float(5.0 * u(rng));
    }
    return m;
}

TEST(Microfacet, Chi2Harness) {
    for (double x : {0.1, 1.0, 5.0, 30.0}) {
        EXPECT_NEAR(test::chi2::gamma_q(1.0, x), std::exp(-x), 1e-12);
        EXPECT_NEAR(test::chi2::gamma_q(0.5, x), std::erfc(std::sqrt(x)), 1e-12);
    }
    EXPECT_NEAR(test::chi2::gamma_q(2000.0, 2000.0), 0.49702645155579744, 1e-9);  // scipy gammaincc
    EXPECT_NEAR(test::chi2::gamma_q(4000.5, 4100.0), 0.058728421513105054, 1e-9);
    const double level = test::chi2::sidak(0.01, 400);
    FcMaterial sampled = microfacet_material(FC_NDF_GGX, FC_SAMPLE_VISIBLE, 0.1f, 0.1f);
    FcMaterial wrong = sampled;
    wrong.alpha_x = wrong.alpha_y = 0.103f;
    Vec3 wo = direction(30.0, 0.7);
    auto good = chi_square(sampled, wo, kModeMicrofacet, mirror(wo), 0.2, level, 5u);
    EXPECT_TRUE(good.ok) << good.message;
    auto bad = chi_square_mismatch(sampled, wrong, wo, kModeMicrofacet, mirror(wo), 0.2, level, 5u);
    EXPECT_FALSE(bad.ok) << bad.message;
}

TEST(Microfacet, PdfIntegratesToOne) {
    const float alphas[][2] = {{0.002f, 0.002f}, {0.01f, 0.01f}, {0.1f, 0.1f},
                               {0.5f, 0.5f},     {1.0f, 1.0f},   {0.05f, 0.3f}};
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN, FC_NDF_BLINN_PHONG})
        for (int sampling : {FC_SAMPLE_VISIBLE, FC_SAMPLE_ALL})
            for (auto& a : alphas)
                for (double deg : {0.0, 30.0, 60.0, 89.0}) {
                    if (ndf == FC_NDF_BLINN_PHONG && a[0] != a[1]) continue;
                    FcMaterial m = microfacet_material(ndf, sampling, a[0], a[1]);
                    m.exponent_x = 2.0f / (a[0] * a[0]) - 2.0f;
                    double w = double(std::min(a[0], a[1]));
                    Vec3 wo = direction(deg, 0.7);
                    double normals = pdf_mass(m, wo, kModeNdf, Vec3{0, 0, 1}, w);
                    double lobe = pdf_mass(m, wo, kModeMicrofacet, mirror(wo), 2.0 * w);
                    // Lobes whose reflected directions stay above the horizon (tails < 1e-4).
                    bool above = deg <= 30.0 && (ndf == FC_NDF_GGX ? w <= 0.01 : w <= 0.1);
                    std::string what = "ndf " + std::to_string(ndf) + " sampling " + std::to_string(sampling) +
                                       " alpha " + std::to_string(a[0]) + "," + std::to_string(a[1]) + " theta_o " +
                                       std::to_string(deg);
                    EXPECT_NEAR(normals, 1.0, 1e-3) << what;
                    EXPECT_LE(lobe, 1.0 + 1e-3) << what;
                    if (above) {
                        EXPECT_NEAR(lobe, 1.0, 1e-3) << what;
                    }
                }
    // The cosine lobe of the dispatcher.
    double cosine = pdf_mass(lobe_material(FC_DIFFUSE_LAMBERT, FC_SPECULAR_NONE), direction(40.0, 0.0), kModeBsdf,
                             Vec3{0, 0, 1}, 10.0);
    EXPECT_NEAR(cosine, 1.0, 1e-4);
}

TEST(Microfacet, WeakWhiteFurnace) {
    const float alphas[][2] = {{0.01f, 0.01f}, {0.1f, 0.1f},  {0.3f, 0.3f},  {0.6f, 0.6f},
                               {1.0f, 1.0f},   {0.05f, 0.3f}, {0.3f, 0.05f}, {0.002f, 0.2f}};
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN})
        for (auto& a : alphas)
            for (double deg : {0.0, 30.0, 60.0, 80.0, 85.0, 89.0}) {
                FcMaterial m = microfacet_material(ndf, FC_SAMPLE_ALL, a[0], a[1]);
                Vec3 wo = direction(deg, 0.7);
                const double axis[3] = {0.0, 0.0, 1.0};
                double w = double(std::min(a[0], a[1]));
                // Strongly anisotropic lobes are thin in phi about the pole: more phi cells.
                bool thin = std::max(a[0], a[1]) > 20.0f * std::min(a[0], a[1]);
                auto q = test::chi2::make_quadrature(
                    test::chi2::make_lobe_chart(axis, w, w, thin ? 128 : 64, thin ? 1024 : 128));
                std::vector<cl_float4> dirs = q.dirs;
                dirs.push_back(f4(wo));
                auto t = ndf_terms(m, wo, dirs);
                double sum = 0.0;
                for (std::size_t i = 0; i < q.dirs.size(); ++i) {
                    const cl_float4& d = q.dirs[i];
                    double wm = wo.x * double(d.s[0]) + wo.y * double(d.s[1]) + wo.z * double(d.s[2]);
                    sum += q.weights[i] * double(t[i].s[0]) * std::max(0.0, wm);
                }
                double g1 = 1.0 / (1.0 + double(t.back().s[1]));
                EXPECT_NEAR(sum * g1 / wo.z, 1.0, 1e-3)
                    << "ndf " << ndf << " alpha (" << a[0] << ", " << a[1] << ") theta_o " << deg;
            }
}

TEST(Microfacet, GeometryMatchesReference) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int checked = 0;
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN, FC_NDF_BLINN_PHONG}) {
        FcMaterial m = microfacet_material(ndf, FC_SAMPLE_VISIBLE, 0.0f, 0.0f);
        for (int mat = 0; mat < 20; ++mat) {
            m.alpha_x = float(std::pow(10.0, -2.0 * u(rng)));
            m.alpha_y = (ndf == FC_NDF_BLINN_PHONG || mat % 2) ? m.alpha_x : float(std::pow(10.0, -2.0 * u(rng)));
            m.exponent_x = 2.0f / (m.alpha_x * m.alpha_x) - 2.0f;
            std::vector<cl_float4> wo, wi;
            for (int i = 0; i < 256; ++i) {
                wo.push_back(f4(direction(89.5 * u(rng), 6.3 * u(rng))));
                wi.push_back(f4(direction(89.5 * u(rng), 6.3 * u(rng))));
            }
            auto g = geometry_terms(m, wo, wi);
            for (std::size_t i = 0; i < wo.size(); ++i) {
                double ref[FC_G_COUNT];
                reference_geometry(m, wo[i], wi[i], ref);
                for (int k = 0; k < FC_G_COUNT; ++k, ++checked)
                    ASSERT_NEAR(g[i * FC_G_COUNT + std::size_t(k)], ref[k], 2e-4 * ref[k] + 1e-6)
                        << "ndf " << ndf << " G " << k << " alpha " << m.alpha_x << "," << m.alpha_y;
            }
        }
    }
    std::printf("[ geometry ] %d G values checked\n", checked);
}

TEST(Microfacet, SampleMatchesEvalAndPdf) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 40000;
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, us;
    for (int i = 0; i < n; ++i) {
        mats.push_back(random_material(rng, -5.0));
        wo.push_back(f4(direction(std::acos(0.02 + 0.98 * u(rng)) * 180.0 / std::numbers::pi, 6.3 * u(rng))));
        us.push_back(cl_float4{{float(u(rng)), float(u(rng)), float(u(rng)), 0.0f}});
    }
    auto out = consistency(mats, wo, us);
    int lobes = 0, samples = 0;
    auto rel = [](double a, double b) { return std::abs(a - b) <= 1e-4 * std::max(std::abs(a), std::abs(b)) + 1e-30; };
    for (int i = 0; i < n; ++i) {
        const cl_float4* o = &out[4 * std::size_t(i)];
        const FcMaterial& m = mats[std::size_t(i)];
        std::string what = "material " + std::to_string(i) + " diffuse " + std::to_string(m.diffuse_model) +
                           " specular " + std::to_string(m.specular_model) + " ndf " + std::to_string(m.ndf);
        if (o[0].s[3] >= 0.0f) {  // a non-delta sample of the specular lobe
            ++lobes;
            for (int c = 0; c < 4; ++c)
                ASSERT_TRUE(rel(o[0].s[c], o[1].s[c]))
                    << what << " component " << c << ": " << o[0].s[c] << " vs " << o[1].s[c];
        }
        if (o[2].s[3] > 0.0f && o[3].s[3] == 0.0f) {  // a non-delta sample of the BSDF
            ++samples;
            for (int c = 0; c < 3; ++c) ASSERT_TRUE(rel(o[2].s[c], o[3].s[c])) << what << " weight " << c;
        }
    }
    std::printf("[ sample   ] %d lobe samples and %d BSDF samples checked\n", lobes, samples);
    EXPECT_GT(lobes, n / 4);
}

TEST(Microfacet, ExtremeSweep) {
    SweepResult r = extreme_sweep(1u << 20, 17u);
    std::printf("[ sweep    ] %llu cases checked (%u materials), %u failures\n",
                static_cast<unsigned long long>(r.checked), 1u << 20, r.failures);
    EXPECT_GE(r.checked, 1000000u);
    EXPECT_EQ(r.failures, 0u) << r.report;
}

}  // namespace
}  // namespace facet
