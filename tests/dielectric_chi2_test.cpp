// Statistical tests of the dielectric BSDF: chi-square goodness of fit of its sampling
// (reflection and refraction together, on one chart of the whole sphere) against its
// pdf, and its energy: reflection plus transmission albedo <= 1 at every alpha and
// angle, and the smooth limit's exact Fresnel split.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tests/chi2_test_util.hpp"
#include "tests/dielectric_test_util.hpp"

namespace facet {
namespace {

using namespace test::dl;
using test::mf::direction;
using test::mf::f4;

constexpr double kPi = 3.14159265358979323846;
constexpr float kEtas[] = {1.33f, 1.5f, 1.0f / 1.5f, 2.4f};
constexpr float kAlphas[] = {0.01f, 0.1f, 0.5f};
constexpr int kChi2Tests = 4 * 3 * (3 + 1) + 8;
const double kLevel = test::chi2::sidak(0.01, kChi2Tests);

// Edges uniform in asinh((x - c) / w) over [lo, hi] (as chi2_test_util.cpp's).
std::vector<double> warped(double lo, double hi, double c, double w, int n) {
    double a = std::asinh((lo - c) / w), b = std::asinh((hi - c) / w);
    std::vector<double> e(std::size_t(n) + 1);
    for (int i = 0; i <= n; ++i) e[std::size_t(i)] = c + w * std::sinh(a + (b - a) * i / n);
    e.front() = lo;
    e.back() = hi;
    return e;
}

// A chart with fine cells about both lobes: the upper hemisphere's theta edges about
// the mirror direction, the lower's about Snell's direction (the mirror image of wo
// under total internal reflection), and phi about the plane of incidence (both lobes
// lie at azimuth phi_o + pi). theta = pi/2 is an edge, and so is the cone where the
// density jumps (below). Without that edge, GGX at alpha = 0.5, theta_o = 80 failed:
// the quadrature's total mass moved by 0.5% between orders 8, 12 and 16.
test::chi2::Chart two_lobe_chart(const Vec3& wo, double eta, double alpha) {
    double theta_o = std::acos(std::clamp(wo.z, -1.0, 1.0));
    Vec3 t{};
    bool refracts = refract_down(wo, eta, t);
    double theta_t = refracts ? std::acos(t.z) : kPi - theta_o;
    double cos_t = refracts ? -t.z : 1.0;
    // A tilt d of the normal turns the refracted ray by d |1 - cos_o / (eta cos_t)|.
    double spread = refracts ? std::max(std::abs(1.0 - wo.z / (eta * cos_t)), 0.1) : 4.0;
    double w_r = 2.0 * alpha, w_t = 2.0 * alpha * spread;
    test::chi2::Chart c;
    std::vector<double> up = warped(0.0, kPi / 2, theta_o, w_r, 32);
    std::vector<double> down = warped(kPi / 2, kPi, theta_t, w_t, 32);
    // The density jumps where the generalised half vector wo + eta wi lies in the
    // surface (wi.z = -wo.z / eta): normals stop at the horizon, where GGX's D is still
    // ~alpha^2 / pi. The nearest edge moves onto that cone.
    if (wo.z / eta < 1.0) {
        double theta_h0 = std::acos(-wo.z / eta);
        std::size_t near = 1;
        for (std::size_t i = 1; i + 1 < down.size(); ++i)
            if (std::abs(down[i] - theta_h0) < std::abs(down[near] - theta_h0)) near = i;
        down[near] = theta_h0;
    }
    c.theta_edges = up;
    c.theta_edges.insert(c.theta_edges.end(), down.begin() + 1, down.end());
    // Straight down (theta = pi in float, which exceeds pi) belongs to the last cell.
    c.theta_edges.back() = 3.1416;
    double perp = std::min(w_r * std::max(wo.z, 1e-3), w_t * 0.5);
    double s = std::sin(theta_o);
    double w_phi = s * kPi > perp ? perp / s : kPi;
    double phi_c = std::atan2(-wo.y, -wo.x);
    c.phi0 = phi_c - kPi;
    c.phi_edges = warped(0.0, 2.0 * kPi, kPi, std::min(w_phi, kPi), 128);
    return c;
}

// 4096 x 123 = 503,808 samples per configuration, order-8 Gauss-Legendre per cell.
constexpr unsigned kPerItem = 123;

test::chi2::Result chi_square(const FcMaterial& m, const Vec3& wo, unsigned seed) {
    using namespace test::mf;
    test::chi2::Chart chart = two_lobe_chart(wo, m.ior, std::max(m.alpha_x, 1e-3f));
    test::chi2::Quadrature q = test::chi2::make_quadrature(chart, 8);
    std::vector<double> mass = test::chi2::cell_masses(q, pdfs(m, wo, kModeBsdf, q.dirs));
    auto hist = histogram(m, wo, kModeBsdf, chart, seed, kPerItem);
    return test::chi2::test(hist, mass, std::uint64_t(kItems) * kPerItem, kLevel);
}

void chi_square_ndf(int ndf, const std::vector<double>& angles) {
    int run = 0, failed = 0;
    double p_min = 1.0, p_max = 0.0;
    for (float eta : kEtas)
        for (float alpha : kAlphas)
            for (double deg : angles) {
                FcMaterial m = glass(ndf, eta, alpha);
                Vec3 wo = direction(deg, 0.7);
                auto r = chi_square(m, wo, 7000u + unsigned(run));
                ++run;
                failed += r.ok ? 0 : 1;
                p_min = std::min(p_min, r.p_value);
                p_max = std::max(p_max, r.p_value);
                EXPECT_TRUE(r.ok) << "ndf " << ndf << " eta " << eta << " alpha " << alpha << " theta_o " << deg << ": "
                                  << r.message;
                EXPECT_EQ(r.invalid, 0u);
            }
    std::printf("[ chi2     ] dielectric ndf %d: %d configurations, %d failed, p in [%.3g, %.3g]\n", ndf, run, failed,
                p_min, p_max);
}

// theta_o = 45, 60 and 80 are beyond the critical angle (41.8) for eta = 1/1.5: total
// internal reflection, except through rough facets tilted toward wo.
TEST(DielectricChi2, ChiSquareGgx) { chi_square_ndf(FC_NDF_GGX, {0.0, 45.0, 80.0}); }

TEST(DielectricChi2, ChiSquareBeckmann) { chi_square_ndf(FC_NDF_BECKMANN, {60.0}); }

// The widened choice of reflection or refraction (FC_MAT_WIDE_CHOICE, set in scenes whose
// light is not uniform): the density still the sampling's.
TEST(DielectricChi2, ChiSquareWideChoice) {
    unsigned seed = 7600u;
    for (float eta : {1.5f, 1.0f / 1.5f})
        for (float alpha : {0.1f, 0.5f})
            for (double deg : {0.0, 80.0}) {
                FcMaterial m = glass(FC_NDF_GGX, eta, alpha);
                m.flags |= FC_MAT_WIDE_CHOICE;
                auto r = chi_square(m, test::mf::direction(deg, 0.7), seed++);
                EXPECT_TRUE(r.ok) << "eta " << eta << " alpha " << alpha << " theta_o " << deg << ": " << r.message;
                EXPECT_EQ(r.invalid, 0u);
            }
}

// The widened choice (dielectric_choice): F moved toward [0.25, 0.75], at most 4 times either
// lobe's share, so the smooth interface still reflects F and transmits 1 - F in expectation,
// chooses the reflection with that probability, and no sample weighs more than 4 / 3.
TEST(DielectricChi2, WideChoiceKeepsTheFresnelSplit) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo;
    for (float eta : {1.0001f, 1.33f, 1.5f, 2.4f, 1.0f / 1.5f})
        for (float a : {0.0f, 0.3f})
            for (double deg : {0.0, 45.0, 70.0, 85.0}) {
                FcMaterial m = glass(FC_NDF_GGX, eta, a);
                m.flags |= FC_MAT_WIDE_CHOICE;
                mats.push_back(m);
                wo.push_back(f4(direction(deg, 1.1)));
            }
    const int samples = 40000;
    std::vector<Albedo> r = albedo(mats, wo, samples);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        SCOPED_TRACE(testing::Message() << "eta " << mats[i].ior << " alpha " << mats[i].alpha_x << " cos_o "
                                        << wo[i].s[2]);
        EXPECT_EQ(r[i].bad, 0.0);
        EXPECT_LE(r[i].wmax, 4.0 / 3.0 + 1e-3);
        if (mats[i].alpha_x > 0.0f) {
            EXPECT_LE(r[i].r + r[i].t, 1.0 + 4.0 * std::hypot(r[i].r_err, r[i].t_err) + 1e-5);
            continue;
        }
        const double F = fresnel(wo[i].s[2], mats[i].ior);
        const double q = std::clamp(F, std::min(0.25, 4.0 * F), 1.0 - std::min(0.25, 4.0 * (1.0 - F)));
        EXPECT_NEAR(r[i].r, F, 5.0 * r[i].r_err + 1e-6);
        EXPECT_NEAR(r[i].t, 1.0 - F, 5.0 * r[i].t_err + 1e-6);
        EXPECT_NEAR(r[i].reflected, q, 5.0 * std::sqrt(q * (1.0 - q) / samples) + 1e-6);
    }
}

// Reflection plus transmission albedo (energy, i.e. with the radiance scaling 1/etap^2
// undone) <= 1 for every eta, alpha and angle, from both sides. With visible-normal
// sampling and the exact Smith G each sample's energy weight is G2 / G1(wo) <= 1.
TEST(DielectricChi2, EnergyDielectric) {
    const float alphas[] = {2e-4f, 0.01f, 0.1f, 0.3f, 0.5f, 1.0f};
    const double thetas[] = {0.0, 30.0, 60.0, 75.0, 85.0, 89.0};
    const float etas[] = {1.0001f, 1.33f, 1.5f, 1.0f / 1.5f, 2.4f, 20.0f, 0.05f};
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo;
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN})
        for (float eta : etas)
            for (float a : alphas)
                for (double deg : thetas) {
                    mats.push_back(glass(ndf, eta, a));
                    wo.push_back(f4(direction(deg, 0.4)));
                }
    const int samples = 10000;
    std::vector<Albedo> r = albedo(mats, wo, samples);
    std::printf("[ energy   ] R+T (GGX) by alpha (rows) and theta_o 0 30 60 75 85 89, eta 1.5:\n");
    for (std::size_t i = 0; i < mats.size(); ++i) {
        SCOPED_TRACE(testing::Message() << "ndf " << mats[i].ndf << " eta " << mats[i].ior << " alpha "
                                        << mats[i].alpha_x << " cos_o " << wo[i].s[2]);
        double rt = r[i].r + r[i].t;
        EXPECT_EQ(r[i].bad, 0.0);
        EXPECT_LE(rt, 1.0 + 4.0 * std::hypot(r[i].r_err, r[i].t_err) + 1e-5);
        EXPECT_LE(r[i].wmax, 1.0 + 1e-3);
        if (mats[i].ndf == FC_NDF_GGX && mats[i].ior == 1.5f) {
            std::printf("%s%.4f", i % 6 == 0 ? "[ energy   ]   " : "  ", rt);
            if (i % 6 == 5) std::printf("   alpha %g\n", double(mats[i].alpha_x));
        }
    }
}

// An index-matched interface (ior 1), smooth or rough, from either side: no reflection,
// all the energy straight through (a rough one lost ~80% as a degenerate half vector).
TEST(DielectricChi2, EnergyDielectricIndexMatched) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo;
    for (float a : {0.0f, 0.1f, 0.5f, 1.0f})
        for (double deg : {0.0, 45.0, 85.0, 120.0, 170.0}) {
            mats.push_back(glass(FC_NDF_GGX, 1.0f, a));
            wo.push_back(f4(direction(deg, 0.7)));
        }
    std::vector<Albedo> r = albedo(mats, wo, 10000);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        SCOPED_TRACE(testing::Message() << "alpha " << mats[i].alpha_x << " cos_o " << wo[i].s[2]);
        EXPECT_EQ(r[i].bad, 0.0);
        EXPECT_EQ(r[i].r, 0.0);
        EXPECT_NEAR(r[i].t, 1.0, 1e-5);
    }
}

// The smooth limit: a nearly smooth rough interface splits energy as the exact Fresnel
// equations do, R = F(theta_o), T = 1 - F, as the delta BSDF does exactly.
TEST(DielectricChi2, EnergyDielectricSmoothLimit) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo;
    for (float eta : kEtas)
        for (float a : {0.0f, 1e-3f})
            for (double deg : {0.0, 30.0, 45.0, 60.0, 70.0}) {
                mats.push_back(glass(FC_NDF_GGX, eta, a));
                wo.push_back(f4(direction(deg, 1.1)));
            }
    std::vector<Albedo> r = albedo(mats, wo, 40000);
    double worst = 0.0;
    for (std::size_t i = 0; i < mats.size(); ++i) {
        double F = fresnel(wo[i].s[2], mats[i].ior);
        SCOPED_TRACE(testing::Message() << "eta " << mats[i].ior << " alpha " << mats[i].alpha_x << " cos_o "
                                        << wo[i].s[2] << " F " << F);
        EXPECT_NEAR(r[i].r, F, 0.01);
        EXPECT_NEAR(r[i].t, 1.0 - F, 0.01);
        worst = std::max({worst, std::abs(r[i].r - F), std::abs(r[i].t - (1.0 - F))});
    }
    std::printf("[ energy   ] smooth limit: largest |R - F|, |T - (1 - F)| = %.4f\n", worst);
}

}  // namespace
}  // namespace facet
