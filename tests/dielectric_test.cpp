// The dielectric BSDF (kernels/bsdf/dielectric.cl), the conductor presets and the MTL
// glass and mirror mapping. The chi-square and energy tests are in
// dielectric_chi2_test.cpp, the glass sphere in a white environment in glass_render_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "host/bvh/bvh.hpp"
#include "tests/dielectric_test_util.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"
#include "host/scene/material.hpp"
#include "host/readers/mtl_material.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace test::dl;
using test::mf::f4;

Vec3 random_sphere_dir(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double z = 2.0 * u(rng) - 1.0, phi = 2.0 * 3.14159265358979 * u(rng);
    double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    if (std::abs(z) < 1e-3) z = z < 0 ? -1e-3 : 1e-3;
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// Generalised reciprocity of the radiance BTDF (Veach 1997, eq. 5.14; docs/brdf.md):
// f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2, n the index on each direction's side (1 above,
// ior below). The reflection is symmetric. The pdf is not checked (it is not reciprocal).
TEST(Dielectric, ReciprocityWithEtaSquared) {
    std::mt19937 rng(17);
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo, wi;
    for (float eta : {1.33f, 1.5f, 1.0f / 1.5f, 2.4f})
        for (int ndf : {FC_NDF_GGX, FC_NDF_BECKMANN})
            for (int i = 0; i < 2000; ++i) {
                FcMaterial m = glass(ndf, eta, 0.05f + 0.9f * float(i % 10) / 10.0f);
                Vec3 a = random_sphere_dir(rng), b = random_sphere_dir(rng);
                mats.insert(mats.end(), {m, m});
                wo.insert(wo.end(), {f4(a), f4(b)});
                wi.insert(wi.end(), {f4(b), f4(a)});
            }
    std::vector<cl_float4> out = eval(mats, wo, wi);
    int transmissions = 0, reflections = 0, loose = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < mats.size(); i += 2) {
        double eta = mats[i].ior;
        double n_o = wo[i].s[2] > 0 ? 1.0 : eta, n_i = wi[i].s[2] > 0 ? 1.0 : eta;
        double f = out[i].s[0], g = out[i + 1].s[0];
        ASSERT_TRUE(std::isfinite(f) && f >= 0.0 && std::isfinite(g) && g >= 0.0);
        if (f > 0.0) (n_o == n_i ? reflections : transmissions)++;
        double a = f / (n_o * n_o), b = g / (n_i * n_i);
        // 1 - F comes from the pair's two cosines (fresnel_dielectric_transmittance): with
        // cos_t = sqrt(1 - sin^2_t) instead, pairs near the critical angle agreed only to 3%.
        double rel = std::abs(a - b) / std::max({a, b, 1e-30});
        if (std::max(a, b) > 1e-6) worst = std::max(worst, rel), loose += rel > 1e-4 ? 1 : 0;
        EXPECT_NEAR(a, b, 2e-4 * std::max(a, b) + 1e-9)
            << "eta " << eta << " ndf " << mats[i].ndf << " alpha " << mats[i].alpha_x << " wo.z " << wo[i].s[2]
            << " wi.z " << wi[i].s[2] << ": f(wo,wi) " << f << " f(wi,wo) " << g;
    }
    std::printf("[ recip    ] %d transmission and %d reflection pairs; largest relative error %.3g, %d above 1e-4\n",
                transmissions, reflections, worst, loose);
    EXPECT_GT(transmissions, 1000);
    EXPECT_GT(reflections, 2000);
    EXPECT_EQ(loose, 0);
}

// The smooth interface refracts by Snell-Descartes (n_o sin_o = n_i sin_i) and never
// beyond the critical angle; the weight of a refraction is 1 / etap^2.
TEST(Dielectric, SmoothSnellAndTotalInternalReflection) {
    std::vector<FcMaterial> mats;
    std::vector<cl_float4> wo;
    const double etas[] = {1.0001, 1.33, 1.5, 2.4, 20.0, 1.0 / 1.5, 1.0 / 2.4};
    for (double eta : etas)
        for (double deg : {0.0, 20.0, 40.0, 45.0, 70.0, 89.9}) {
            mats.push_back(glass(FC_NDF_GGX, float(eta), 0.0f));
            wo.push_back(f4(test::mf::direction(deg, 0.3)));
        }
    std::vector<Albedo> a = albedo(mats, wo, 20000);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        double eta = mats[i].ior, cos_o = wo[i].s[2];
        double F = fresnel(cos_o, eta);
        SCOPED_TRACE(testing::Message() << "eta " << eta << " cos_o " << cos_o);
        EXPECT_EQ(a[i].bad, 0.0);
        EXPECT_EQ(a[i].refused, 0.0);
        EXPECT_NEAR(a[i].r + a[i].t, 1.0, 1e-5) << "every sample carries energy 1";
        double sigma = std::sqrt(F * (1.0 - F) / 20000.0);
        EXPECT_NEAR(a[i].reflected, F, 5.0 * sigma + 1e-6);
        if (F == 1.0) {
            EXPECT_EQ(a[i].t, 0.0) << "total internal reflection";
        }
    }
    // The refracted direction itself, and the radiance weight 1 / etap^2, via eval of a
    // slightly rough interface: its transmission lobe peaks at Snell's direction.
    for (double eta : {1.5, 1.0 / 1.5}) {
        Vec3 o = test::mf::direction(30.0, 0.0), t{};
        ASSERT_TRUE(refract_down(o, eta, t));
        std::vector<FcMaterial> m;
        std::vector<cl_float4> a_, b_;
        for (double d : {-0.02, 0.0, 0.02}) {
            m.push_back(glass(FC_NDF_GGX, float(eta), 0.002f));
            a_.push_back(f4(o));
            Vec3 w{t.x + d, t.y, t.z};
            double len = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
            b_.push_back(f4({w.x / len, w.y / len, w.z / len}));
        }
        auto f = eval(m, a_, b_);
        EXPECT_GT(f[1].s[0], 100.0f * f[0].s[0]) << "eta " << eta;
        EXPECT_GT(f[1].s[0], 100.0f * f[2].s[0]) << "eta " << eta;
    }
}

// Normal-incidence reflectance of the complex-index presets against the F0 table (the
// Schlick alternative): both describe the same metals, within the spread of the data.
TEST(Dielectric, ConductorPresetsAgreeWithF0Table) {
    for (const char* metal : {"gold", "silver", "copper", "aluminium", "iron"}) {
        auto c = conductor_preset(metal);
        auto f0 = f0_preset(metal);
        ASSERT_TRUE(c && f0) << metal;
        for (int i = 0; i < 3; ++i) {
            double n = c->eta[i], k = c->k[i];
            double r = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
            EXPECT_NEAR(r, (*f0)[i], 0.13) << metal << " channel " << i;
        }
    }
    EXPECT_FALSE(conductor_preset("unobtainium").has_value());
    EXPECT_TRUE(conductor_preset("Aluminum").has_value());
    Material m = make_material("conductor");
    EXPECT_EQ(m.fresnel, FC_FRESNEL_CONDUCTOR);
    EXPECT_EQ(m.diffuse_model, FC_DIFFUSE_NONE);
    EXPECT_EQ(material_model_of(m), "conductor");
    Material g = make_material("dielectric");
    EXPECT_EQ(g.specular_model, FC_SPECULAR_DIELECTRIC);
    EXPECT_EQ(material_model_of(g), "dielectric");
    EXPECT_EQ(validate_material(g), "");
}

// illum 5 is a mirror of Ks, illum 7 smooth glass of index Ni tinted by Tf.
TEST(Dielectric, MtlGlassAndMirror) {
    std::vector<std::string> warnings;
    auto mats = parse_mtl("t.mtl",
                          "newmtl mirror\nKs 0.9 0.8 0.7\nillum 5\n"
                          "newmtl glass\nKs 0.3 0.3 0.3\nTf 0.25 1 1\nNi 1.33\nillum 7\n"
                          "newmtl grey\nTf 0.1 0.1 0.1\nNi 2.5\nillum 7\n",
                          warnings);
    ASSERT_EQ(mats.size(), 3u);
    const Material& mirror = mats[0].material;
    EXPECT_EQ(mirror.specular_model, FC_SPECULAR_MICROFACET);
    EXPECT_EQ(mirror.diffuse_model, FC_DIFFUSE_NONE);
    EXPECT_LT(std::max(mirror.alpha_x, mirror.alpha_y), FC_ALPHA_MIRROR);
    EXPECT_FLOAT_EQ(mirror.f0[1], 0.8f);
    const Material& glass_m = mats[1].material;
    EXPECT_EQ(glass_m.specular_model, FC_SPECULAR_DIELECTRIC);
    EXPECT_FLOAT_EQ(glass_m.ior, 1.33f);
    EXPECT_FLOAT_EQ(glass_m.transmittance[0], 0.5f) << "sqrt(Tf) per refraction";
    EXPECT_FLOAT_EQ(glass_m.transmittance[1], 1.0f);
    // Only Tf's hue is kept (McGuire's clear glass says Tf 0.1): grey Tf is clear glass.
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(mats[2].material.transmittance[c], 1.0f);
}

// McGuire's Cornell boxes with a mirror sphere and glass (or water) render without a
// single NaN, infinite or negative sample.
TEST(Dielectric, McGuireCornellBoxesRenderClean) {
    for (const char* name : {"CornellBox-Sphere.obj", "CornellBox-Water.obj"}) {
        const std::string file = test::assets_dir() + "/cornell_mcguire/" + name;
        if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
        Scene scene = load_scene(file);
        scene.settings.width = scene.settings.height = 32;
        bool has_glass = false, has_mirror = false;
        for (const Material& m : scene.materials) {
            has_glass |= m.specular_model == FC_SPECULAR_DIELECTRIC;
            has_mirror |= m.specular_model == FC_SPECULAR_MICROFACET && m.alpha_x < FC_ALPHA_MIRROR;
        }
        EXPECT_TRUE(has_glass && has_mirror) << name;
        Bvh bvh = build_bvh(scene.vertices);
        Renderer r(test::context(), scene, bvh);
        render_fixed(r, 16);
        double rejected = -1.0;
        std::vector<float> img = r.image(&rejected);
        EXPECT_EQ(rejected, 0.0) << name;
        double sum = 0.0;
        for (float v : img) sum += double(v);
        EXPECT_GT(sum / double(img.size()), 0.01) << name;
    }
}

}  // namespace
}  // namespace facet
