// Energy compensation (kernels/bsdf/energy_compensation.cl) and EON (kernels/bsdf/eon.cl):
// white furnaces (the directional albedo of a white lobe, F = 1, is 1 within 1%) at
// alpha in {0.05, 0.1, 0.25, 0.5, 0.75, 1} and theta_o up to 80 degrees for conductors
// (GGX, Beckmann), rough plastic (Lambert under a compensated Schlick layer), rough
// dielectrics (reflection + transmission, from both sides, also off the table's grid) and
// EON; reciprocity of every reciprocal compensated lobe (the dielectric's albedo scaling
// is not). The furnace tables print what docs/brdf.md shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "tests/cl_test_env.hpp"
#include "tests/dielectric_test_util.hpp"
#include "tests/microfacet_test_util.hpp"
#include "kernels/shared/material_layout.h"

namespace facet {
namespace {

using test::mf::Albedo;
using test::mf::albedos;
using test::mf::direction;
using test::mf::f4;
using test::mf::lobe_material;
using test::mf::Vec3;

const char* kKernels = "kernels/test/albedo_kernels.cl";
constexpr float kAlphas[] = {0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
constexpr double kThetas[] = {0.0, 20.0, 40.0, 60.0, 70.0, 80.0};
constexpr unsigned kSamples = 1u << 16;

FcMaterial white_conductor(int ndf, float alpha) {
    FcMaterial m = lobe_material(FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET);
    m.ndf = ndf;
    m.fresnel = FC_FRESNEL_ONE;
    m.alpha_x = m.alpha_y = alpha;
    m.flags = FC_MAT_ENERGY_COMPENSATION;
    return m;
}

FcMaterial white_plastic(int ndf, float alpha) {
    FcMaterial m = white_conductor(ndf, alpha);
    m.diffuse_model = FC_DIFFUSE_LAMBERT_1MF0;
    m.fresnel = FC_FRESNEL_SCHLICK;
    for (int c = 0; c < 3; ++c) m.diffuse[c] = 1.0f, m.specular[c] = 0.04f;
    return m;
}

// A clear rough dielectric of index 1.5 (GGX or Beckmann), exact Fresnel.
FcMaterial clear_dielectric(int ndf, float alpha) {
    FcMaterial m = white_conductor(ndf, alpha);
    m.specular_model = FC_SPECULAR_DIELECTRIC;
    m.fresnel = FC_FRESNEL_DIELECTRIC;
    m.ior = 1.5f;
    for (int c = 0; c < 3; ++c) m.specular[c] = 1.0f;
    return m;
}

FcMaterial white_eon(float r) {
    FcMaterial m = lobe_material(FC_DIFFUSE_EON, FC_SPECULAR_NONE);
    for (int c = 0; c < 3; ++c) m.diffuse[c] = 1.0f;
    m.sigma = r;
    return m;
}

// Runs the furnace over the alpha x theta grid for `make(alpha)`, with and without the
// compensation, prints the table (single scattering / compensated) and its largest
// deviation of a compensated cell from 1, and checks the compensated albedo is 1 within 1%
// (and 4 standard errors).
// The extreme-index furnaces run a coarser grid (`coarse`) to keep their run time short.
constexpr float kCoarseAlphas[] = {0.1f, 0.5f, 1.0f};
constexpr double kCoarseThetas[] = {0.0, 40.0, 70.0, 80.0};

void furnace(const char* title, const std::function<FcMaterial(int, float)>& make, int ndf, bool from_below = false,
             bool coarse = false) {
    const std::vector<float> alphas = coarse ? std::vector<float>(std::begin(kCoarseAlphas), std::end(kCoarseAlphas))
                                             : std::vector<float>(std::begin(kAlphas), std::end(kAlphas));
    const std::vector<double> thetas = coarse ? std::vector<double>(std::begin(kCoarseThetas), std::end(kCoarseThetas))
                                              : std::vector<double>(std::begin(kThetas), std::end(kThetas));
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float a : alphas)
        for (double t : thetas)
            for (bool on : {false, true}) {
                FcMaterial m = make(ndf, a);
                if (!on) m.flags &= ~FC_MAT_ENERGY_COMPENSATION;
                mats.push_back(m);
                Vec3 w = direction(t, 0.3);
                if (from_below) w.z = -w.z;
                wo.push_back(w);
            }
    std::vector<Albedo> r = albedos(mats, wo, kSamples);
    double worst = 0.0;
    std::printf("\n%s: albedo, single scattering / compensated\n| alpha |", title);
    for (double t : thetas) std::printf(" %g deg |", t);
    std::printf("\n|---|");
    for (std::size_t t = 0; t < thetas.size(); ++t) std::printf("---|");
    std::printf("\n");
    std::size_t i = 0;
    for (float a : alphas) {
        std::printf("| %.2f |", double(a));
        for (double t : thetas) {
            const Albedo &ss = r[i], &ec = r[i + 1];
            i += 2;
            std::printf(" %.3f / %.3f |", ss.mean[0], ec.mean[0]);
            EXPECT_EQ(ec.bad, 0);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(ec.mean[c] - 1.0));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(ec.mean[c], 1.0, 0.01 + 4.0 * ec.error[c])
                    << title << " alpha " << a << " theta_o " << t << " channel " << c;
        }
        std::printf("\n");
    }
    std::printf("worst |albedo - 1| of a compensated cell: %.4f\n", worst);
}

TEST(EnergyCompensation, FurnaceConductorGgx) { furnace("GGX conductor, F = 1", white_conductor, FC_NDF_GGX); }

TEST(EnergyCompensation, FurnaceConductorBeckmann) {
    furnace("Beckmann conductor, F = 1", white_conductor, FC_NDF_BECKMANN);
}

TEST(EnergyCompensation, FurnacePlasticGgx) {
    furnace("GGX rough plastic, white base, F0 = 0.04", white_plastic, FC_NDF_GGX);
}

TEST(EnergyCompensation, FurnacePlasticBeckmann) {
    furnace("Beckmann rough plastic, white base, F0 = 0.04", white_plastic, FC_NDF_BECKMANN);
}

// Rough dielectrics: the energy albedo (reflection + transmission times etap^2), from
// outside and from inside (total internal reflection), Turquin's albedo scaling, within 1%
// (plus 4 standard errors per cell) both ways. From inside the table holds E / E_c
// (energy_compensation.cl): with E alone on its 16 x 12 nodes the worst cell was 1.1% off
// (Beckmann, alpha 0.05, 80 degrees, where E_c falls steeply).
TEST(EnergyCompensation, FurnaceDielectricGgx) {
    furnace("GGX rough dielectric, ior 1.5, from outside", clear_dielectric, FC_NDF_GGX);
    furnace("GGX rough dielectric, ior 1.5, from inside", clear_dielectric, FC_NDF_GGX, true);
}

TEST(EnergyCompensation, FurnaceDielectricBeckmann) {
    furnace("Beckmann rough dielectric, ior 1.5, from outside", clear_dielectric, FC_NDF_BECKMANN);
    furnace("Beckmann rough dielectric, ior 1.5, from inside", clear_dielectric, FC_NDF_BECKMANN, true);
}

// A rough dielectric's white furnace in `cells` random cells (alpha 0.05..1, both NDFs,
// half seen from inside), the index drawn by `ior_of(u)` from a uniform u; each within 1 %
// (plus 4 standard errors). Returns the worst |albedo - 1|.
template <class IorOf>
double off_grid_dielectric_furnace(unsigned seed, int cells, IorOf ior_of) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (int i = 0; i < cells; ++i) {
        FcMaterial m = clear_dielectric(i % 2 ? FC_NDF_GGX : FC_NDF_BECKMANN, float(0.05 + 0.95 * u(rng)));
        m.ior = float(ior_of(u(rng)));
        Vec3 w = direction(80.0 * u(rng), 6.283185307179586 * u(rng));
        if (i % 4 >= 2) w.z = -w.z;
        mats.push_back(m);
        wo.push_back(w);
    }
    std::vector<Albedo> r = albedos(mats, wo, kSamples);
    double worst = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        EXPECT_EQ(r[i].bad, 0);
        worst = std::max(worst, std::fabs(r[i].mean[0] - 1.0));
        EXPECT_NEAR(r[i].mean[0], 1.0, 0.01 + 4.0 * r[i].error[0])
            << (mats[i].ndf == FC_NDF_GGX ? "GGX" : "Beckmann") << " alpha " << mats[i].alpha_x << " ior "
            << mats[i].ior << " wo.z " << wo[i].z;
    }
    return worst;
}

// The dielectric's albedo scaling between the table's nodes and index slices: random
// alpha in [0.05, 1], theta_o in [0, 80] degrees and ior in [1.2, 2.5], both NDFs and
// both sides, compensated albedo 1 within 1% (plus 4 standard errors).
TEST(EnergyCompensation, FurnaceDielectricOffGrid) {
    const double worst = off_grid_dielectric_furnace(18, 128, [](double u) { return 1.2 + 1.3 * u; });
    std::printf("[ furnace ] rough dielectric off the grid: 128 cells, worst |albedo - 1| = %.4f\n", worst);
}

// The same over the whole accepted index range off the grid: ior log-uniform in
// [1.001, 100], half of them seen from inside.
TEST(EnergyCompensation, FurnaceDielectricOffGridWideIor) {
    const double worst = off_grid_dielectric_furnace(
        27, 64, [](double u) { return std::exp(std::log(1.001) + (std::log(100.0) - std::log(1.001)) * u); });
    std::printf("[ furnace ] rough dielectric off the grid, ior 1.001..100: 64 cells, worst |albedo - 1| = %.4f\n",
                worst);
}

// Rough dielectrics at the ends of the accepted index range (1e-3..100): the near-matched
// ior 1.015, where the single-scattering albedo drops to its limit E(eta -> 1) < 1 (light
// refracted straight on is still masked below) and does not approach the exact E = 1 of
// eta = 1, and ior 4 and 10, beyond the table's old end at eta 3 (docs/brdf.md: 0.88 at
// 1.015, 0.84 to 4.9 beyond 2.5 before the table covered them). Both sides, both NDFs.
void furnace_at_ior(float ior, int ndf) {
    auto make = [ior](int n, float a) {
        FcMaterial m = clear_dielectric(n, a);
        m.ior = ior;
        return m;
    };
    const std::string name = std::string(ndf == FC_NDF_GGX ? "GGX" : "Beckmann") + " rough dielectric, ior " +
                             std::to_string(ior).substr(0, 5);
    furnace((name + ", from outside").c_str(), make, ndf, false, true);
    furnace((name + ", from inside").c_str(), make, ndf, true, true);
}

TEST(EnergyCompensation, FurnaceDielectricNearMatched) {
    furnace_at_ior(1.015f, FC_NDF_GGX);
    furnace_at_ior(1.015f, FC_NDF_BECKMANN);
}

TEST(EnergyCompensation, FurnaceDielectricHighIor) {
    for (float ior : {4.0f, 10.0f}) {
        furnace_at_ior(ior, FC_NDF_GGX);
        furnace_at_ior(ior, FC_NDF_BECKMANN);
    }
}

// The smooth limit of the white plastic (roughness 0: a Schlick mirror over the coupled
// white base) reflects 1 within 1% up to the silhouette, as the rough one does (alpha 1e-3
// up to 85 degrees: at 89 its tables' grazing node gives 1.04-1.05, not asserted); before
// the base was coupled at the mirror limit it reflected F(mu) + (1 - F0), 1.37 at 80 degrees.
TEST(EnergyCompensation, FurnacePlasticSmooth) {
    const double thetas[] = {0.0, 40.0, 60.0, 70.0, 80.0, 85.0, 89.0};
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN})
        for (float a : {0.0f, 1e-3f})
            for (double t : thetas) mats.push_back(white_plastic(ndf, a)), wo.push_back(direction(t, 0.3));
    std::vector<Albedo> r = albedos(mats, wo, kSamples);
    std::printf("\nSmooth white plastic (F0 = 0.04), albedo\n| ndf, alpha |");
    for (double t : thetas) std::printf(" %g deg |", t);
    std::printf("\n|---|---|---|---|---|---|---|---|\n");
    for (std::size_t i = 0; i < r.size(); ++i) {
        const std::size_t t = i % std::size(thetas);
        if (t == 0) std::printf("| %s, %g |", mats[i].ndf == FC_NDF_GGX ? "GGX" : "Beckmann", double(mats[i].alpha_x));
        std::printf(" %.4f |", r[i].mean[0]);
        if (t + 1 == std::size(thetas)) std::printf("\n");
        EXPECT_EQ(r[i].bad, 0);
        if (mats[i].alpha_x > 0.0f && thetas[t] > 85.0) continue;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(r[i].mean[c], 1.0, 0.01 + 4.0 * r[i].error[c])
                << "ndf " << mats[i].ndf << " alpha " << mats[i].alpha_x << " theta_o " << thetas[t];
    }
}

TEST(EnergyCompensation, FurnaceEon) {
    const float rs[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float r : rs)
        for (double t : kThetas) mats.push_back(white_eon(r)), wo.push_back(direction(t, 0.3));
    std::vector<Albedo> a = albedos(mats, wo, kSamples);
    std::printf("\nEON, rho = 1: albedo\n| r |");
    for (double t : kThetas) std::printf(" %g deg |", t);
    std::printf("\n|---|---|---|---|---|---|---|\n");
    std::size_t i = 0;
    for (float r : rs) {
        std::printf("| %.2f |", double(r));
        for (double t : kThetas) {
            std::printf(" %.4f |", a[i].mean[0]);
            EXPECT_EQ(a[i].bad, 0);
            EXPECT_NEAR(a[i].mean[0], 1.0, 0.01 + 4.0 * a[i].error[0]) << "EON r " << r << " theta_o " << t;
            ++i;
        }
        std::printf("\n");
    }
}

// A coloured conductor (gold's complex index): the compensation adds energy, never
// more than a white furnace allows, and keeps each channel below 1.
TEST(EnergyCompensation, ColouredConductorGainsEnergyBelowOne) {
    std::vector<FcMaterial> mats;
    std::vector<Vec3> wo;
    for (float a : {0.25f, 0.5f, 1.0f})
        for (bool on : {false, true}) {
            FcMaterial m = white_conductor(FC_NDF_GGX, a);
            m.fresnel = FC_FRESNEL_CONDUCTOR;
            const float eta[3] = {0.188f, 0.543f, 1.33f}, k[3] = {3.40f, 2.23f, 1.87f};
            for (int c = 0; c < 3; ++c) m.eta[c] = eta[c], m.k[c] = k[c];
            if (!on) m.flags = 0u;
            mats.push_back(m);
            wo.push_back(direction(30.0, 0.0));
        }
    std::vector<Albedo> r = albedos(mats, wo, kSamples);
    for (std::size_t i = 0; i < r.size(); i += 2)
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(r[i + 1].mean[c], r[i].mean[c] + 2e-3) << "alpha index " << i / 2 << " channel " << c;
            EXPECT_LT(r[i + 1].mean[c], 1.0) << "alpha index " << i / 2 << " channel " << c;
        }
}

// F_avg = 2 int_0^1 F(mu) mu dmu (ec_fresnel_avg, the F_ms and coupled diffuse terms' input):
// Schlick's in closed form, F0 + (F90 - F0) / 21, and the exact dielectric and conductor
// terms by 8-point Gauss-Legendre, against Simpson's rule in double on 4096 intervals.
TEST(EnergyCompensation, FresnelAverageIsTheCosineWeightedMean) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<FcMaterial> mats;
    for (int i = 0; i < 64; ++i) {
        FcMaterial m = white_plastic(FC_NDF_GGX, 0.3f);
        switch (i % 4) {
            case 0:  // Schlick, coloured F0, F90 = 1 or KHR_materials_specular's F90
                for (int c = 0; c < 3; ++c) m.specular[c] = u(rng);
                if (i % 8 == 0) m.flags |= FC_MAT_SPECULAR_F90, m.specular_f90 = u(rng);
                break;
            case 1:
                m.fresnel = FC_FRESNEL_SCHLICK_IOR, m.ior = 1.0f + 2.0f * u(rng);
                break;
            case 2:
                m.fresnel = FC_FRESNEL_DIELECTRIC, m.ior = 1.05f + 2.0f * u(rng);
                break;
            default:
                m.fresnel = FC_FRESNEL_CONDUCTOR;
                for (int c = 0; c < 3; ++c) m.eta[c] = 0.1f + 2.0f * u(rng), m.k[c] = 0.5f + 5.0f * u(rng);
        }
        mats.push_back(m);
    }
    auto fresnel = [](const FcMaterial& m, int c, double mu) {
        if (m.fresnel == FC_FRESNEL_SCHLICK || m.fresnel == FC_FRESNEL_SCHLICK_IOR) {
            const double r = (double(m.ior) - 1.0) / (double(m.ior) + 1.0);
            const double f0 = m.fresnel == FC_FRESNEL_SCHLICK ? double(m.specular[c]) : r * r;
            const double f90 = (m.flags & FC_MAT_SPECULAR_F90) ? double(m.specular_f90) : 1.0;
            return f0 + (f90 - f0) * std::pow(1.0 - mu, 5.0);
        }
        if (m.fresnel == FC_FRESNEL_DIELECTRIC) return test::dl::fresnel(mu, double(m.ior));
        const std::complex<double> n(m.eta[c], m.k[c]);
        const std::complex<double> cos_t = std::sqrt(1.0 - (1.0 - mu * mu) / (n * n));
        const std::complex<double> rs = (mu - n * cos_t) / (mu + n * cos_t), rp = (n * mu - cos_t) / (n * mu + cos_t);
        return 0.5 * (std::norm(rs) + std::norm(rp));
    };
    using namespace test;
    cl::Buffer bm = mf::upload(mats);
    cl::Buffer bo(context().context(), CL_MEM_WRITE_ONLY, mats.size() * sizeof(cl_float4));
    cl::Kernel k(program(kKernels), "albedo_fresnel_avg");
    k.setArg(0, bm), k.setArg(1, bo);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<cl_float4> out = mf::download<cl_float4>(bo, mats.size());
    double worst_schlick = 0.0, worst_exact = 0.0;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const int n = 4096;
            double sum = 0.0;
            for (int j = 0; j <= n; ++j) {
                const double mu = double(j) / n, w = (j == 0 || j == n) ? 1.0 : (j % 2 ? 4.0 : 2.0);
                sum += w * 2.0 * mu * fresnel(mats[i], c, mu);
            }
            const double ref = sum / (3.0 * n), err = std::fabs(double(out[i].s[c]) - ref);
            const bool schlick = mats[i].fresnel == FC_FRESNEL_SCHLICK || mats[i].fresnel == FC_FRESNEL_SCHLICK_IOR;
            (schlick ? worst_schlick : worst_exact) = std::max(schlick ? worst_schlick : worst_exact, err);
            EXPECT_LE(err, schlick ? 5e-7 : 5e-6) << "material " << i << " (Fresnel " << mats[i].fresnel << ") channel "
                                                  << c << ": " << out[i].s[c] << " against " << ref;
        }
    std::printf("[ F_avg    ] max abs error: Schlick %.2g (closed form), exact terms %.2g (Gauss-Legendre)\n",
                worst_schlick, worst_exact);
}

// f(wo, wi) = f(wi, wo) to float precision for every compensated lobe, anisotropic too.
TEST(EnergyCompensation, Reciprocity) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, wi;
    auto dir = [&] {
        double z = 0.02 + 0.98 * double(u(rng)), phi = 6.283185307179586 * double(u(rng));
        double s = std::sqrt(1.0 - z * z);
        return f4(Vec3{s * std::cos(phi), s * std::sin(phi), z});
    };
    for (int i = 0; i < 3000; ++i) {
        int ndf = i % 2 ? FC_NDF_GGX : FC_NDF_BECKMANN;
        FcMaterial m = i % 3 == 0 ? white_conductor(ndf, 0.02f + u(rng)) : white_plastic(ndf, 0.02f + u(rng));
        if (i % 5 == 0) m.alpha_y = 0.02f + u(rng);
        if (i % 7 == 0) m = white_eon(u(rng));
        if (i % 11 == 0) {
            m.fresnel = FC_FRESNEL_CONDUCTOR;
            for (int c = 0; c < 3; ++c) m.eta[c] = 0.2f + 2.0f * u(rng), m.k[c] = 4.0f * u(rng);
        }
        for (int c = 0; c < 3; ++c) m.diffuse[c] = u(rng), m.specular[c] = u(rng);
        mats.push_back(m);
        wo.push_back(dir());
        wi.push_back(dir());
    }
    using namespace test;
    cl::Buffer bm = mf::upload(mats), a = mf::upload(wo), b = mf::upload(wi);
    cl::Buffer bo(context().context(), CL_MEM_WRITE_ONLY, 2 * mats.size() * sizeof(cl_float4));
    cl::Kernel k(program(kKernels), "albedo_reciprocity");
    k.setArg(0, bm), k.setArg(1, a), k.setArg(2, b), k.setArg(3, bo);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<cl_float4> out = mf::download<cl_float4>(bo, 2 * mats.size());
    int failures = 0;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            float f = out[2 * i].s[c], g = out[2 * i + 1].s[c];
            bool ok = std::isfinite(f) && f >= 0.0f && std::fabs(f - g) <= 1e-5f * std::fmax(std::fabs(f), 1e-3f);
            if (!ok && ++failures <= 10)
                ADD_FAILURE() << "material " << i << " (diffuse " << mats[i].diffuse_model << ", ndf " << mats[i].ndf
                              << ") channel " << c << ": f(wo, wi) = " << f << ", f(wi, wo) = " << g;
        }
    EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace facet
