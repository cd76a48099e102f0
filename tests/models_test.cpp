// The named reflection models: each matches an independent double-precision
// transcription of its source formula, is reciprocal, conserves energy (or is listed
// in docs/brdf.md as not doing so), stays finite at extreme parameters; plus the host
// presets, name tables and conversions (host/scene/material.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "tests/cl_test_env.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"

namespace facet {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* kKernels = "kernels/test/model_kernels.cl";

struct V3 {
    double x, y, z;
};
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 scale(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
V3 norm(V3 a) { return scale(a, 1.0 / std::sqrt(dot(a, a))); }

// A direction on the upper hemisphere with cos(theta) >= zmin, rounded to float.
V3 random_dir(std::mt19937& rng, double zmin) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double z = zmin + (1.0 - zmin) * u(rng), phi = 2.0 * kPi * u(rng), r = std::sqrt(1.0 - z * z);
    return {double(float(r * std::cos(phi))), double(float(r * std::sin(phi))), double(float(z))};
}
V3 dir_at(double theta_deg) {
    double t = theta_deg * kPi / 180.0;
    return {double(float(std::sin(t))), 0.0, double(float(std::cos(t)))};
}

// Runs models_eval: 4 floats (f rgb, pdf) per (material, wo, wi).
std::vector<float> eval_on_device(const std::vector<FcMaterial>& mats, const std::vector<V3>& wo,
                                  const std::vector<V3>& wi, const char* kernel = "models_eval") {
    ClContext& ctx = test::context();
    std::vector<float> dirs;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (V3 v : {wo[i], wi[i]}) dirs.insert(dirs.end(), {float(v.x), float(v.y), float(v.z)});
    cl::Buffer bm(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, mats.size() * sizeof(FcMaterial),
                  const_cast<FcMaterial*>(mats.data()));
    cl::Buffer bd(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dirs.size() * sizeof(float), dirs.data());
    cl::Buffer bo(ctx.context(), CL_MEM_WRITE_ONLY, mats.size() * 4 * sizeof(float));
    cl::Kernel k(test::program(kKernels), kernel);
    k.setArg(0, bm), k.setArg(1, bd), k.setArg(2, bo), k.setArg(3, int(mats.size()));
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<float> out(mats.size() * 4);
    ctx.queue().enqueueReadBuffer(bo, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    return out;
}

// Runs models_albedo or models_sample_consistency: `per` outputs of type T per item.
template <typename T>
std::vector<T> run_per_wo(const char* kernel, const std::vector<FcMaterial>& mats, const std::vector<V3>& wo,
                          int samples, int per) {
    ClContext& ctx = test::context();
    std::vector<float> dirs;
    for (V3 v : wo) dirs.insert(dirs.end(), {float(v.x), float(v.y), float(v.z)});
    cl::Buffer bm(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, mats.size() * sizeof(FcMaterial),
                  const_cast<FcMaterial*>(mats.data()));
    cl::Buffer bd(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dirs.size() * sizeof(float), dirs.data());
    cl::Buffer bo(ctx.context(), CL_MEM_WRITE_ONLY, mats.size() * per * sizeof(T));
    cl::Kernel k(test::program(kKernels), kernel);
    k.setArg(0, bm), k.setArg(1, bd), k.setArg(2, bo), k.setArg(3, int(mats.size())), k.setArg(4, samples);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<T> out(mats.size() * per);
    ctx.queue().enqueueReadBuffer(bo, CL_TRUE, 0, out.size() * sizeof(T), out.data());
    return out;
}

void set3(float* d, float a, float b, float c) { d[0] = a, d[1] = b, d[2] = c; }

// --- the source formulas in double precision --------------------------------------------
// Chmelík & Čejka's lecture (docs/brdf.md) I_diff + I_spe per channel, mapped to f = I / (pi N.L);
// ggx from Hoffman's D_tr and Heitz 2014's height-correlated Smith G.
double schlick(double f0, double vh) { return f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0); }

double reference_f(const std::string& model, const FcMaterial& m, int c, V3 v, V3 l) {
    V3 h = norm(add(v, l));
    double nl = l.z, nv = v.z, nh = h.z, vh = dot(v, h), cd = m.diffuse[c], cs = m.specular[c];
    double i_diff = 0.0, i_spe = 0.0;
    if (model == "lambert" || model == "cook_torrance" || model == "blinn_phong" || model == "blinn_phong_normalized")
        i_diff = cd * nl;
    if (model == "oren_nayar") {
        double ti = std::acos(nl), to = std::acos(nv), alpha = std::max(ti, to), beta = std::min(ti, to);
        V3 pv = add(v, scale({0, 0, 1}, -nv)), pl = add(l, scale({0, 0, 1}, -nl));
        double lv = std::sqrt(dot(pv, pv)), ll = std::sqrt(dot(pl, pl));
        double cos_phi = (lv > 0 && ll > 0) ? dot(pv, pl) / (lv * ll) : 0.0;
        double s2 = double(m.sigma) * double(m.sigma), a = 1.0 - 0.5 * s2 / (s2 + 0.57), b = 0.45 * s2 / (s2 + 0.09);
        // the lecture writes (A + B max(0, cos phi)) C; the model is A + B max(0, cos phi) C
        i_diff = cd * nl * (a + b * std::max(0.0, cos_phi) * std::sin(alpha) * std::tan(beta));
    }
    if (model == "cook_torrance") {
        double mm = m.alpha_x, f = schlick(cs, vh);
        double g = std::min({1.0, 2.0 * nh * nv / vh, 2.0 * nh * nl / vh});
        double d = std::exp((nh * nh - 1.0) / (mm * mm * nh * nh)) / (mm * mm * std::pow(nh, 4.0));
        i_spe = f * g * d / (4.0 * nv);
    }
    if (model == "blinn_phong") i_spe = nl * cs * std::pow(nh, double(m.exponent_x));
    if (model == "blinn_phong_normalized")
        i_spe = nl * cs * (double(m.exponent_x) + 8.0) / 8.0 * std::pow(nh, double(m.exponent_x));
    if (model == "ashikhmin_shirley") {
        double st = m.exponent_x, sb = m.exponent_y, th = h.x, bh = h.y;
        i_diff = cd * nl * 28.0 / 23.0 * (1.0 - cs) * (1.0 - std::pow(1.0 - nl / 2.0, 5.0)) *
                 (1.0 - std::pow(1.0 - nv / 2.0, 5.0));
        // the lecture's second shin_T is shin_B (Ashikhmin & Shirley 2000, eq. 4)
        i_spe = schlick(cs, vh) * nl * std::sqrt((st + 1.0) * (sb + 1.0)) / 8.0 *
                std::pow(nh, (st * th * th + sb * bh * bh) / (1.0 - nh * nh)) / (vh * std::max(nl, nv));
    }
    if (model == "ggx") {
        double a2 = double(m.alpha_x) * double(m.alpha_x);
        double d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
        auto lambda = [&](double cz) { return (-1.0 + std::sqrt(1.0 + a2 * (1.0 - cz * cz) / (cz * cz))) / 2.0; };
        double g = 1.0 / (1.0 + lambda(nv) + lambda(nl));
        return d * g * schlick(cs, vh) / (4.0 * nl * nv) + (1.0 - cs) * cd / kPi;
    }
    return (i_diff + i_spe) / (kPi * nl);
}

FcMaterial random_preset(const std::string& model, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    FcMaterial m = device_material(make_material(model));
    set3(m.diffuse, 0.1f + 0.8f * u(rng), 0.1f + 0.8f * u(rng), 0.1f + 0.8f * u(rng));
    set3(m.specular, 0.02f + 0.9f * u(rng), 0.02f + 0.9f * u(rng), 0.02f + 0.9f * u(rng));
    m.alpha_x = m.alpha_y = 0.1f + 0.7f * u(rng);
    m.exponent_x = 1.0f + 199.0f * u(rng);
    m.exponent_y = 1.0f + 299.0f * u(rng);
    m.sigma = 1.2f * u(rng);
    return m;
}

TEST(Models, PresetsMatchSourceFormulas) {
    std::mt19937 rng(7);
    const char* models[] = {"lambert",           "oren_nayar", "cook_torrance", "blinn_phong", "blinn_phong_normalized",
                            "ashikhmin_shirley", "ggx"};
    const int per_model = 400;
    // the sources' single-scattering lobes: ggx without its energy compensation
    auto source_preset = [&](const char* model) {
        FcMaterial m = random_preset(model, rng);
        m.flags &= ~FC_MAT_ENERGY_COMPENSATION;
        return m;
    };
    std::vector<FcMaterial> mats;
    std::vector<V3> wo, wi;
    for (const char* model : models)
        for (int i = 0; i < per_model; ++i) {
            mats.push_back(source_preset(model));
            wo.push_back(random_dir(rng, 0.02));
            wi.push_back(random_dir(rng, 0.02));
        }
    // a few exact configurations: normal incidence, retro-reflection, mirror geometry
    std::vector<std::pair<V3, V3>> special = {
        {{0, 0, 1}, {0, 0, 1}}, {dir_at(60), dir_at(60)}, {dir_at(-40), dir_at(40)}};
    for (std::size_t k = 0; k < std::size(models); ++k)
        for (auto [a, b] : special) mats.push_back(source_preset(models[k])), wo.push_back(a), wi.push_back(b);
    std::vector<float> out = eval_on_device(mats, wo, wi);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        std::size_t k = i < std::size(models) * per_model ? i / per_model : (i - std::size(models) * per_model) / 3;
        for (int c = 0; c < 3; ++c) {
            double ref = reference_f(models[k], mats[i], c, wo[i], wi[i]);
            EXPECT_NEAR(out[4 * i + c], ref, 1e-4 * std::abs(ref) + 1e-7)
                << models[k] << " channel " << c << " wo=(" << wo[i].x << "," << wo[i].y << "," << wo[i].z << ") wi=("
                << wi[i].x << "," << wi[i].y << "," << wi[i].z << ")";
        }
    }
}

// Every diffuse model and every specular lobe (microfacet: every D x G x F).
std::vector<FcMaterial> reciprocity_materials(std::mt19937& rng) {
    std::vector<FcMaterial> mats;
    for (std::string_view model : material_model_names()) mats.push_back(random_preset(std::string(model), rng));
    for (int d = 0; d < FC_NDF_COUNT; ++d)
        for (int g = 0; g < FC_G_COUNT; ++g)
            for (int f = 0; f < FC_FRESNEL_COUNT; ++f) {
                FcMaterial m = random_preset("microfacet", rng);
                m.ndf = d, m.geometry = g, m.fresnel = f;
                m.alpha_y = 0.1f + 0.5f * m.alpha_x;  // anisotropic
                set3(m.eta, 0.2f, 0.9f, 1.4f), set3(m.k, 3.0f, 2.5f, 2.0f), m.ior = 1.6f;
                mats.push_back(m);
            }
    return mats;
}

TEST(Models, EvalPdfGivesEvalsAndPdfsBits) {
    // bsdf_eval_pdf (next-event estimation and the samplers' weights) shares each lobe's
    // work between f and its density: it must give bsdf_eval's and bsdf_pdf's bits. Every
    // model and microfacet combination, the samplers' variants, the dielectric rough and
    // smooth, and each with a metal mix, a clearcoat and a sheen; pairs on both sides.
    std::mt19937 rng(29);
    std::vector<FcMaterial> base = reciprocity_materials(rng), mats;
    for (int d = 0; d < FC_NDF_COUNT; ++d)
        for (float alpha : {0.0f, 0.05f, 0.4f}) {
            FcMaterial m = random_preset("dielectric", rng);
            m.ndf = d, m.alpha_x = alpha, m.alpha_y = 0.5f * alpha + 0.1f * float(alpha > 0.0f);
            base.push_back(m);
        }
    const std::size_t n_base = base.size();
    for (std::size_t i = 0; i < n_base; ++i)
        for (int s = 0; s < FC_SAMPLE_COUNT; ++s) {
            FcMaterial m = base[i];
            m.sampling = s;
            base.push_back(m);
        }
    for (const FcMaterial& b : base)
        for (int layer = 0; layer < 4; ++layer) {
            FcMaterial m = b;
            if (layer == 1) m.metallic = 0.4f;
            if (layer == 2) m.clearcoat = 0.8f, m.clearcoat_alpha = 0.1f;
            if (layer == 3) set3(m.sheen, 0.5f, 0.3f, 0.2f), m.sheen_roughness = 0.4f;
            mats.push_back(m);
        }
    std::vector<FcMaterial> pm;
    std::vector<V3> a, b;
    for (const FcMaterial& m : mats)
        for (int k = 0; k < 24; ++k) {
            V3 wo = random_dir(rng, 0.01), wi = random_dir(rng, 0.01);
            if (k % 3 == 1) wi.z = -wi.z;                // transmission (and nothing for the opaque)
            if (k % 6 == 2) wo.z = -wo.z, wi.z = -wi.z;  // from inside a dielectric
            pm.push_back(m), a.push_back(wo), b.push_back(wi);
        }
    ClContext& ctx = test::context();
    std::vector<float> dirs;
    for (std::size_t i = 0; i < pm.size(); ++i)
        for (V3 v : {a[i], b[i]}) dirs.insert(dirs.end(), {float(v.x), float(v.y), float(v.z)});
    cl::Buffer bm(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, pm.size() * sizeof(FcMaterial), pm.data());
    cl::Buffer bd(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dirs.size() * sizeof(float), dirs.data());
    cl::Buffer bo(ctx.context(), CL_MEM_WRITE_ONLY, pm.size() * sizeof(int));
    cl::Kernel k(test::program(kKernels), "models_eval_pdf_bits");
    k.setArg(0, bm), k.setArg(1, bd), k.setArg(2, bo), k.setArg(3, int(pm.size()));
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(pm.size()));
    std::vector<int> out(pm.size());
    ctx.queue().enqueueReadBuffer(bo, CL_TRUE, 0, out.size() * sizeof(int), out.data());
    int differ = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
        if (out[i] != 0 && differ++ < 5) ADD_FAILURE() << "bits differ: " << describe_material(pm[i]);
    EXPECT_EQ(differ, 0) << "of " << out.size() << " pairs";
}

TEST(Models, Reciprocity) {
    // None of facet's lobes is non-reciprocal (docs/brdf.md explains the candidates).
    std::mt19937 rng(11);
    std::vector<FcMaterial> base = reciprocity_materials(rng), mats;
    std::vector<V3> wo, wi;
    for (const FcMaterial& m : base)
        for (int i = 0; i < 64; ++i) {
            V3 a = random_dir(rng, 0.02), b = random_dir(rng, 0.02);
            mats.insert(mats.end(), {m, m});
            wo.insert(wo.end(), {a, b});
            wi.insert(wi.end(), {b, a});
        }
    std::vector<float> out = eval_on_device(mats, wo, wi);
    for (std::size_t i = 0; i < mats.size(); i += 2)
        for (int c = 0; c < 3; ++c) {
            float f = out[4 * i + c], g = out[4 * (i + 1) + c];
            ASSERT_TRUE(std::isfinite(f) && f >= 0.0f) << describe_material(mats[i]);
            EXPECT_NEAR(f, g, 1e-4f * std::max(f, g) + 1e-8f) << describe_material(mats[i]);
        }
}

// --- energy -------------------------------------------------------------------------------
const double kThetas[] = {0, 30, 60, 75, 85, 89};
const float kAlphas[] = {0.05f, 0.1f, 0.2f, 0.3f, 0.5f, 0.7f, 1.0f};

struct Config {
    std::string group;  // one row of the summary
    std::string label;  // the parameter value
    double theta;
    FcMaterial m;
};

// A white material with one lobe and F = 1 (Fresnel ONE, or F0 = 1 for Schlick-only lobes).
FcMaterial white(int diffuse_model, int specular_model) {
    FcMaterial m = device_material(make_material("microfacet"));
    m.flags &= ~FC_MAT_ENERGY_COMPENSATION;  // single scattering (energy_compensation_test.cpp has the rest)
    m.diffuse_model = diffuse_model, m.specular_model = specular_model;
    set3(m.diffuse, 1.0f, 1.0f, 1.0f);
    set3(m.specular, 1.0f, 1.0f, 1.0f);
    m.fresnel = FC_FRESNEL_ONE;
    return m;
}

struct Albedo {
    double mean, error, max_weight;
    int bad;
};

std::vector<Albedo> albedos(const std::vector<Config>& configs, int samples) {
    std::vector<FcMaterial> mats;
    std::vector<V3> wo;
    for (const Config& c : configs) mats.push_back(c.m), wo.push_back(dir_at(c.theta));
    std::vector<float> out = run_per_wo<float>("models_albedo", mats, wo, samples, 4);
    std::vector<Albedo> r;
    for (std::size_t i = 0; i < configs.size(); ++i)
        r.push_back({out[4 * i], out[4 * i + 1], out[4 * i + 3], int(out[4 * i + 2])});
    return r;
}

// Asserts finite samples and, where `conserving(group)`, albedo <= 1 within Monte Carlo
// error; prints each group's largest albedo (docs/brdf.md lists them).
template <typename Pred>
void check_energy(const std::vector<Config>& configs, int samples, Pred conserving) {
    std::vector<Albedo> a = albedos(configs, samples);
    std::vector<std::string> groups;
    for (const Config& c : configs)
        if (std::find(groups.begin(), groups.end(), c.group) == groups.end()) groups.push_back(c.group);
    for (const std::string& g : groups) {
        std::size_t arg = 0;
        double best = -1.0;
        for (std::size_t i = 0; i < configs.size(); ++i) {
            if (configs[i].group != g) continue;
            EXPECT_EQ(a[i].bad, 0) << g << " " << configs[i].label << " theta_o " << configs[i].theta;
            EXPECT_TRUE(std::isfinite(a[i].mean));
            if (conserving(g)) {
                EXPECT_LE(a[i].mean, 1.0 + 4.0 * a[i].error + 2e-3)
                    << g << " " << configs[i].label << " theta_o " << configs[i].theta << " +- " << a[i].error;
            }
            if (a[i].mean > best) best = a[i].mean, arg = i;
        }
        std::printf("  %-40s max albedo %.4f +- %.4f at %s, theta_o %g%s\n", g.c_str(), best, a[arg].error,
                    configs[arg].label.c_str(), configs[arg].theta, conserving(g) ? "" : "  (not asserted)");
    }
}

TEST(Models, EnergyMicrofacet) {
    std::vector<Config> configs;
    for (int d = 0; d < FC_NDF_COUNT; ++d)
        for (int g = 0; g < FC_G_COUNT; ++g)
            for (float alpha : kAlphas)
                for (double t : kThetas) {
                    FcMaterial m = white(FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET);
                    m.ndf = d, m.geometry = g, m.alpha_x = m.alpha_y = alpha;
                    m.exponent_x = m.exponent_y = shininess_from_roughness(alpha);
                    std::string group = "microfacet D=" + enum_to_name(MaterialEnum::Ndf, d) +
                                        " G=" + enum_to_name(MaterialEnum::Geometry, g);
                    // the Blinn-Phong NDF's Smith G borrows Beckmann's Lambda (docs/brdf.md)
                    if (d == FC_NDF_BLINN_PHONG) group += alpha <= 0.3f ? " alpha<=0.3" : " alpha>=0.5";
                    configs.push_back({group, "alpha " + std::to_string(alpha).substr(0, 4), t, m});
                }
    check_energy(configs, 1 << 15, [](const std::string& g) {
        bool smith = g.find("smith_separable") != std::string::npos || g.find("smith_correlated") != std::string::npos;
        return smith && g.find("D=blinn_phong") == std::string::npos;  // exact Lambda only
    });
}

TEST(Models, EnergyPhongLobes) {
    std::vector<Config> configs;
    for (int model : {FC_SPECULAR_BLINN_PHONG, FC_SPECULAR_BLINN_PHONG_NORMALIZED})
        for (float e : {0.0f, 1.0f, 5.0f, 20.0f, 100.0f, 1000.0f, 1e4f})
            for (double t : kThetas) {
                FcMaterial m = white(FC_DIFFUSE_NONE, model);
                m.exponent_x = e;
                configs.push_back({enum_to_name(MaterialEnum::Specular, model), "e " + std::to_string(int(e)), t, m});
            }
    const float as_exp[][2] = {{0, 0}, {1, 1}, {10, 10}, {100, 100}, {10, 1000}, {1000, 10}, {1e4f, 1e4f}};
    for (auto [nu, nv] : as_exp)
        for (double t : kThetas) {
            FcMaterial m = white(FC_DIFFUSE_NONE, FC_SPECULAR_ASHIKHMIN_SHIRLEY);
            m.exponent_x = nu, m.exponent_y = nv;
            configs.push_back({"ashikhmin_shirley specular (F0 = 1)",
                               "nu " + std::to_string(int(nu)) + " nv " + std::to_string(int(nv)), t, m});
        }
    check_energy(configs, 1 << 15, [](const std::string& g) { return g != "blinn_phong_normalized"; });
}

TEST(Models, EnergyDiffuse) {
    std::vector<Config> configs;
    for (double t : kThetas) {
        configs.push_back({"lambert", "rho 1", t, white(FC_DIFFUSE_LAMBERT, FC_SPECULAR_NONE)});
        FcMaterial m = white(FC_DIFFUSE_LAMBERT_1MF0, FC_SPECULAR_NONE);
        m.fresnel = FC_FRESNEL_SCHLICK, set3(m.specular, 0, 0, 0);
        configs.push_back({"lambert_1mf0 (F0 = 0)", "rho 1", t, m});
        m.diffuse_model = FC_DIFFUSE_ASHIKHMIN_SHIRLEY;
        configs.push_back({"ashikhmin_shirley diffuse (F0 = 0)", "rho 1", t, m});
        for (float sigma : {0.0f, 0.1f, 0.25f, 0.5f, 1.0f, 1.5f}) {
            FcMaterial o = white(FC_DIFFUSE_OREN_NAYAR, FC_SPECULAR_NONE);
            o.sigma = sigma;
            configs.push_back({"oren_nayar", "sigma " + std::to_string(sigma).substr(0, 4), t, o});
        }
    }
    check_energy(configs, 1 << 15, [](const std::string& g) { return g != "oren_nayar"; });
}

TEST(Models, EnergyLossTable) {
    // 1 - albedo of GGX and Beckmann with height-correlated Smith and F = 1: the energy
    // single scattering loses (docs/brdf.md).
    for (int d : {FC_NDF_GGX, FC_NDF_BECKMANN}) {
        std::vector<Config> configs;
        for (float alpha : kAlphas)
            for (double t : kThetas) {
                FcMaterial m = white(FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET);
                m.ndf = d, m.geometry = FC_G_SMITH_CORRELATED, m.alpha_x = m.alpha_y = alpha;
                configs.push_back({"", "", t, m});
            }
        std::vector<Albedo> a = albedos(configs, 1 << 17);
        std::printf("\n1 - albedo, %s, height-correlated Smith, F = 1\n| alpha |",
                    enum_to_name(MaterialEnum::Ndf, d).c_str());
        for (double t : kThetas) std::printf(" %g deg |", t);
        std::string rule = "|---|";
        for (std::size_t t = 0; t < std::size(kThetas); ++t) rule += "---|";
        std::printf("\n%s\n", rule.c_str());
        std::size_t i = 0;
        for (float alpha : kAlphas) {
            std::printf("| %.2f |", double(alpha));
            for (std::size_t t = 0; t < std::size(kThetas); ++t, ++i) {
                std::printf(" %.3f |", 1.0 - a[i].mean);
                EXPECT_EQ(a[i].bad, 0);
                EXPECT_GE(1.0 - a[i].mean, -4.0 * a[i].error - 2e-3);
            }
            std::printf("\n");
        }
    }
}

TEST(Models, LambertSampleIsItsEvalOverPdf) {
    // A Lambertian lobe alone is sampled by its own short route (bsdf.cl,
    // lambert_only_sample: weight = albedo): its f, pdf and weight must be those of the
    // general route, bsdf_eval, bsdf_pdf and f cos / pdf, to rounding; so must a Lambert
    // lobe under a specular one, which takes the general route.
    std::vector<FcMaterial> mats;
    std::vector<V3> wo;
    const V3 dirs[] = {{0, 0, 1}, dir_at(45), dir_at(89.9), {1.0, 0.0, 1e-7}};
    for (int specular : {FC_SPECULAR_NONE, FC_SPECULAR_MICROFACET})
        for (float albedo : {0.0f, 0.18f, 1.0f})
            for (V3 v : dirs) {
                FcMaterial m = white(FC_DIFFUSE_LAMBERT, specular);
                set3(m.diffuse, albedo, 0.5f * albedo, 1.0f);
                mats.push_back(m), wo.push_back(v);
            }
    std::vector<int> c = run_per_wo<int>("models_bsdf_sample_consistency", mats, wo, 4096, 2);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        EXPECT_EQ(c[2 * i], 0) << "f, pdf or weight differ: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        EXPECT_EQ(c[2 * i + 1], 0) << "bad sample: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
    }
}

TEST(Models, SampleMatchesEvalAndExtremes) {
    // The Blinn-Phong and Ashikhmin-Shirley samplers report exactly eval/pdf, and every
    // lobe stays finite and non-negative at extreme parameters and grazing directions.
    const float exps[] = {0.0f, 1e-30f, 0.5f, 30.0f, 1e6f, 1e30f, NAN, -5.0f, INFINITY};
    std::vector<FcMaterial> mats;
    std::vector<V3> wo;
    const V3 dirs[] = {{0, 0, 1}, dir_at(45), dir_at(89.9), {1.0, 0.0, 1e-7}, {0.6, 0.8, 1e-30}};
    for (int model : {FC_SPECULAR_BLINN_PHONG, FC_SPECULAR_BLINN_PHONG_NORMALIZED, FC_SPECULAR_ASHIKHMIN_SHIRLEY})
        for (float e : exps)
            for (V3 v : dirs) {
                FcMaterial m = white(FC_DIFFUSE_OREN_NAYAR, model);
                m.exponent_x = e, m.exponent_y = 100.0f, m.sigma = e;
                mats.push_back(m), wo.push_back(v);
            }
    std::vector<int> c = run_per_wo<int>("models_sample_consistency", mats, wo, 4096, 2);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        EXPECT_EQ(c[2 * i], 0) << "f/pdf mismatch: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        EXPECT_EQ(c[2 * i + 1], 0) << "bad sample: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
    }
    // eval and pdf of the whole BSDF (Oren-Nayar with sigma = e, plus the lobe) on pairs
    std::vector<FcMaterial> pm;
    std::vector<V3> a, b;
    for (const FcMaterial& m : mats)
        for (V3 u : dirs)
            for (V3 v : dirs) pm.push_back(m), a.push_back(u), b.push_back(v);
    for (const FcMaterial& m : mats)  // opposite grazing directions: h near n, wo.h near 0
        pm.push_back(m), a.push_back({1.0, 0.0, 1e-6}), b.push_back({-1.0, 0.0, 1e-6});
    std::vector<float> out = eval_on_device(pm, a, b);
    for (std::size_t i = 0; i < out.size(); ++i)
        ASSERT_TRUE(std::isfinite(out[i]) && out[i] >= 0.0f) << describe_material(pm[i / 4]) << " item " << i;
}

// --- the plain two-lobe base (bsdf_plain: kernels/bsdf/plain_base_lanes.cl) ------------------
// f = kd / pi + D G F / (4 cos_o cos_i) in double from the sources: anisotropic GGX and Beckmann D
// and Lambda (Heitz 2014, eqs. 71, 85, 72, 86), Smith's separable or height-correlated G
// (eqs. 98, 99), the unpolarised Fresnel term of a dielectric or, with a complex index, a
// conductor (Born & Wolf's amplitudes r_s, r_p), kd = diffuse (x (1 - F0) for Lambert x (1 - F0),
// 0 without a diffuse lobe); the density (1 - p) cos_i / pi + p G1(wo) D / (4 cos_o) (visible
// normals), p the specular lobe's probability from the lobes' albedo estimates (1 without a
// diffuse lobe).
double fresnel_dielectric_ref(double c, double eta) {
    double s2 = (1.0 - c * c) / (eta * eta);
    if (s2 >= 1.0) return 1.0;
    double ct = std::sqrt(1.0 - s2), rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

double plain_lambda(const FcMaterial& m, V3 w) {
    double ax = double(m.alpha_x), ay = double(m.alpha_y), s2 = ax * ax * w.x * w.x + ay * ay * w.y * w.y;
    if (s2 == 0.0) return 0.0;
    double t2 = s2 / (w.z * w.z);  // alpha_w^2 tan^2 theta
    if (m.ndf == FC_NDF_GGX) return (-1.0 + std::sqrt(1.0 + t2)) / 2.0;
    double a = 1.0 / std::sqrt(t2);
    return (std::erf(a) - 1.0) / 2.0 + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
}

double plain_D(const FcMaterial& m, V3 h) {
    double ax = double(m.alpha_x), ay = double(m.alpha_y),
           e = (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay)) / (h.z * h.z);
    double c4 = std::pow(h.z, 4.0);
    if (m.ndf == FC_NDF_GGX) return 1.0 / (kPi * ax * ay * c4 * (1.0 + e) * (1.0 + e));
    return std::exp(-e) / (kPi * ax * ay * c4);
}

// The Fresnel term's channel c at cosine cos_i.
double plain_fresnel(const FcMaterial& m, int c, double cos_i) {
    if (m.fresnel != FC_FRESNEL_CONDUCTOR) return fresnel_dielectric_ref(cos_i, double(m.ior));
    const std::complex<double> n(double(m.eta[c]), double(m.k[c]));
    const std::complex<double> ct = std::sqrt(n * n - (1.0 - cos_i * cos_i));  // n cos_t
    const std::complex<double> rs = (cos_i - ct) / (cos_i + ct), rp = (n * n * cos_i - ct) / (n * n * cos_i + ct);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

double plain_luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

// f's channel c (c = 3: the density).
double plain_reference(const FcMaterial& m, int c, V3 v, V3 l) {
    V3 h = norm(add(v, l));
    double lo = plain_lambda(m, v), li = plain_lambda(m, l);
    double g = m.geometry == FC_G_SMITH_CORRELATED ? 1.0 / (1.0 + lo + li) : 1.0 / ((1.0 + lo) * (1.0 + li));
    double d = plain_D(m, h);
    const bool diffuse = m.diffuse_model != FC_DIFFUSE_NONE, coupled = m.diffuse_model == FC_DIFFUSE_LAMBERT_1MF0;
    if (c < 3) {
        double fs = d * g * plain_fresnel(m, c, dot(v, h)) / (4.0 * v.z * l.z);
        double k = !diffuse ? 0.0 : coupled ? 1.0 - plain_fresnel(m, c, 1.0) : 1.0;
        return double(m.diffuse[c]) * k / kPi + fs;
    }
    double p = 1.0;
    if (diffuse) {
        double w = plain_luminance(double(m.diffuse[0]), double(m.diffuse[1]), double(m.diffuse[2]));
        if (coupled)
            w *= 1.0 - plain_luminance(plain_fresnel(m, 0, 1.0), plain_fresnel(m, 1, 1.0), plain_fresnel(m, 2, 1.0));
        double s = plain_luminance(plain_fresnel(m, 0, v.z), plain_fresnel(m, 1, v.z), plain_fresnel(m, 2, v.z));
        p = std::clamp(s / (s + w), 0.05, 0.95);
    }
    return (1.0 - p) * l.z / kPi + p * d / (4.0 * v.z * (1.0 + lo));
}

// Each of `materials` `per` times, with a random pair of directions above the surface (z at
// least min_z) each time, appended to mats, wo and wi.
void random_pairs(const std::vector<FcMaterial>& materials, int per, double min_z, std::mt19937& rng,
                  std::vector<FcMaterial>& mats, std::vector<V3>& wo, std::vector<V3>& wi) {
    for (const FcMaterial& m : materials)
        for (int k = 0; k < per; ++k)
            mats.push_back(m), wo.push_back(random_dir(rng, min_z)), wi.push_back(random_dir(rng, min_z));
}

std::vector<FcMaterial> plain_materials(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<FcMaterial> mats;
    for (int i = 0; i < n; ++i) {
        FcMaterial m = device_material(make_material("microfacet"));
        m.flags &= ~FC_MAT_ENERGY_COMPENSATION;
        const int diffuse[] = {FC_DIFFUSE_LAMBERT, FC_DIFFUSE_LAMBERT_1MF0, FC_DIFFUSE_NONE};
        m.diffuse_model = diffuse[i % 3];
        m.ndf = (i / 3) % 2 ? FC_NDF_BECKMANN : FC_NDF_GGX;
        m.geometry = (i / 6) % 2 ? FC_G_SMITH_CORRELATED : FC_G_SMITH_SEPARABLE;
        m.fresnel = (i / 12) % 2 ? FC_FRESNEL_CONDUCTOR : FC_FRESNEL_DIELECTRIC;
        set3(m.eta, 0.2f + u(rng), 0.4f + u(rng), 1.0f + u(rng));
        set3(m.k, 0.5f + 3.0f * u(rng), 0.5f + 3.0f * u(rng), 3.0f * u(rng));
        m.sampling = FC_SAMPLE_VISIBLE;
        set3(m.diffuse, 0.05f + 0.9f * u(rng), 0.05f + 0.9f * u(rng), 0.05f + 0.9f * u(rng));
        m.alpha_x = 0.15f + 0.75f * u(rng);
        m.alpha_y = i % 4 ? m.alpha_x : 0.15f + 0.75f * u(rng);  // a quarter anisotropic
        m.ior = 1.1f + 2.0f * u(rng);
        mats.push_back(m);
    }
    return mats;
}

TEST(Models, PlainBaseMatchesSourceFormulas) {
    // f and the density of every plain combination (GGX or Beckmann, separable or correlated,
    // Lambert, Lambert x (1 - F0) or none, dielectric or conductor, isotropic and not) on random
    // pairs
    std::mt19937 rng(41);
    std::vector<FcMaterial> mats;
    std::vector<V3> wo, wi;
    random_pairs(plain_materials(rng, 72), 40, 0.05, rng, mats, wo, wi);
    std::vector<float> out = eval_on_device(mats, wo, wi);
    int bad = 0;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            double ref = plain_reference(mats[i], c, wo[i], wi[i]);
            if (!(std::abs(double(out[4 * i + c]) - ref) <= 2e-4 * std::abs(ref) + 1e-7) && bad++ < 5)
                ADD_FAILURE() << describe_material(mats[i]) << (c < 3 ? " f channel " : " pdf ") << c << ": "
                              << out[4 * i + c] << ", source " << ref;
        }
    EXPECT_EQ(bad, 0) << "of " << mats.size() << " pairs";
}

// Plain bases with Schlick's F (coloured F0, F90), F = 1 or energy compensation (the lobe's
// f_ms, the diffuse base coupled to its albedo), some with glTF's metallic mix: GGX or
// Beckmann, height-correlated, a third anisotropic.
std::vector<FcMaterial> compensated_plain_materials(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<FcMaterial> mats = plain_materials(rng, n);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        FcMaterial& m = mats[i];
        m.geometry = FC_G_SMITH_CORRELATED;
        m.alpha_y = m.alpha_x;
        const int fresnel[] = {FC_FRESNEL_SCHLICK,    FC_FRESNEL_SCHLICK_IOR, FC_FRESNEL_ONE,
                               FC_FRESNEL_DIELECTRIC, FC_FRESNEL_CONDUCTOR,   FC_FRESNEL_SCHLICK};
        m.fresnel = fresnel[(i / 6) % 6];
        set3(m.specular, u(rng), u(rng), 0.04f);
        if (i % 4 == 1) m.flags |= FC_MAT_SPECULAR_F90, m.specular_f90 = u(rng);
        if (i % 5 != 4) m.flags |= FC_MAT_ENERGY_COMPENSATION;  // a fifth uncompensated
        m.alpha_x = m.alpha_y = 0.05f + 0.9f * u(rng);
        if (i % 3 == 1) m.alpha_y = 0.05f + 0.9f * u(rng);  // a third anisotropic
        if (i % 7 == 2) m.metallic = u(rng);                // glTF's metallic mix: fractional, or 1
        if (i % 7 == 5) m.metallic = 1.0f;
    }
    return mats;
}

TEST(Models, CompensatedPlainBaseMatchesTheGeneralRoute) {
    // the plain base's f and density (bsdf_eval, bsdf_pdf: its lanes at W = 1) against the
    // general route's formulas for the same materials (energy_compensation.cl, microfacet.cl,
    // bsdf.cl), on random pairs
    std::mt19937 rng(47);
    std::vector<FcMaterial> mats;
    std::vector<V3> wo, wi;
    random_pairs(compensated_plain_materials(rng, 72), 40, 0.02, rng, mats, wo, wi);
    std::vector<float> lanes = eval_on_device(mats, wo, wi),
                       general = eval_on_device(mats, wo, wi, "models_eval_general");
    int bad = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            const double a = lanes[4 * i + c], b = general[4 * i + c], err = std::abs(a - b) / (std::abs(b) + 1e-3);
            worst = std::max(worst, err);
            if (!(std::abs(a - b) <= 2e-6 * std::abs(b) + 1e-8) && bad++ < 5)
                ADD_FAILURE() << describe_material(mats[i]) << (c < 3 ? " f channel " : " pdf ") << c << ": " << a
                              << ", general route " << b;
        }
    std::printf("[ plain    ] compensated and Schlick bases: largest relative difference %.2g\n", worst);
    EXPECT_EQ(bad, 0) << "of " << mats.size() << " pairs";
}

TEST(Models, CompensatedPlainBaseSamplesItsDensity) {
    // as PlainBaseSamplesItsDensity for the compensated and Schlick bases: the mean sample
    // weight against the directional albedo integrated from the general route's f (midpoint
    // rule in cos and azimuth), and every sample's f and pdf bsdf_eval's and bsdf_pdf's
    std::mt19937 rng(53);
    std::vector<FcMaterial> mats;
    std::vector<V3> wo;
    for (FcMaterial m : compensated_plain_materials(rng, 18)) {
        // the midpoint rule below resolves lobes of alpha 0.15 and more, at 80 degrees too
        m.alpha_x = std::max(m.alpha_x, 0.15f), m.alpha_y = std::max(m.alpha_y, 0.15f);
        for (double theta : {0.0, 50.0, 80.0}) mats.push_back(m), wo.push_back(dir_at(theta));
    }
    std::vector<int> c = run_per_wo<int>("models_bsdf_sample_consistency", mats, wo, 4096, 2);
    std::vector<float> a = run_per_wo<float>("models_albedo", mats, wo, 1 << 17, 4);
    const int nu = 200, nphi = 200;
    std::vector<FcMaterial> gm;
    std::vector<V3> go, gi;
    for (std::size_t i = 0; i < mats.size(); ++i)
        for (int iu = 0; iu < nu; ++iu)
            for (int ip = 0; ip < nphi; ++ip) {
                double z = (iu + 0.5) / nu, phi = 2.0 * kPi * (ip + 0.5) / nphi, r = std::sqrt(1.0 - z * z);
                gm.push_back(mats[i]), go.push_back(wo[i]), gi.push_back({r * std::cos(phi), r * std::sin(phi), z});
            }
    std::vector<float> f = eval_on_device(gm, go, gi, "models_eval_general");
    for (std::size_t i = 0; i < mats.size(); ++i) {
        EXPECT_EQ(c[2 * i], 0) << "f/pdf mismatch: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        EXPECT_EQ(c[2 * i + 1], 0) << "bad sample: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        double sum = 0.0;
        for (int k = 0; k < nu * nphi; ++k) sum += double(f[4 * (i * nu * nphi + k)]) * gi[i * nu * nphi + k].z;
        const double albedo = sum * 2.0 * kPi / (double(nu) * nphi);
        EXPECT_NEAR(double(a[4 * i]), albedo, 4.0 * double(a[4 * i + 1]) + 3e-3)
            << describe_material(mats[i]) << " wo.z " << wo[i].z << " +- " << a[4 * i + 1];
        EXPECT_EQ(a[4 * i + 2], 0.0f);
    }
}

TEST(Models, PlainBaseSamplesItsDensity) {
    // bsdf_sample's weights (f cos / pdf from its own f and pdf, which must be bsdf_eval's and
    // bsdf_pdf's) average to the directional albedo, the integral of f cos over the hemisphere
    // (midpoint rule in cos and azimuth, source formulas): a sampler that does not draw from
    // its density misses it by more than the Monte Carlo error
    std::mt19937 rng(43);
    std::vector<FcMaterial> mats;
    std::vector<V3> wo;
    for (const FcMaterial& m : plain_materials(rng, 24))
        for (double theta : {0.0, 50.0, 80.0}) mats.push_back(m), wo.push_back(dir_at(theta));
    std::vector<int> c = run_per_wo<int>("models_bsdf_sample_consistency", mats, wo, 4096, 2);
    std::vector<float> a = run_per_wo<float>("models_albedo", mats, wo, 1 << 17, 4);
    for (std::size_t i = 0; i < mats.size(); ++i) {
        EXPECT_EQ(c[2 * i], 0) << "f/pdf mismatch: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        EXPECT_EQ(c[2 * i + 1], 0) << "bad sample: " << describe_material(mats[i]) << " wo.z " << wo[i].z;
        const int nu = 600, nphi = 600;
        double sum = 0.0;
        for (int iu = 0; iu < nu; ++iu)
            for (int ip = 0; ip < nphi; ++ip) {
                double z = (iu + 0.5) / nu, phi = 2.0 * kPi * (ip + 0.5) / nphi, r = std::sqrt(1.0 - z * z);
                sum += plain_reference(mats[i], 0, wo[i], {r * std::cos(phi), r * std::sin(phi), z}) * z;
            }
        const double albedo = sum * 2.0 * kPi / (double(nu) * nphi);
        EXPECT_NEAR(double(a[4 * i]), albedo, 4.0 * double(a[4 * i + 1]) + 2e-3)
            << describe_material(mats[i]) << " wo.z " << wo[i].z << " +- " << a[4 * i + 1];
        EXPECT_EQ(a[4 * i + 2], 0.0f);
    }
}

}  // namespace
}  // namespace facet
