#include "host/scene/material.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/util/math.hpp"
#include "host/util/strings.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {
namespace {

constexpr float kExponentMax = FC_PHONG_EXPONENT_MAX;
constexpr float kDefaultAlpha = 0.3f;

struct Preset {
    std::string_view name;
    int diffuse, specular, ndf, geometry;
    int fresnel = FC_FRESNEL_SCHLICK;
    bool energy_compensation = false;  // on for the GGX-based presets, off for the classic models
};
// The named models, once (docs/brdf.md describes them); microfacet is ggx's lobes with any
// D, G, F.
constexpr Preset kPresets[] = {
    {"lambert", FC_DIFFUSE_LAMBERT, FC_SPECULAR_NONE, FC_NDF_GGX, FC_G_SMITH_CORRELATED},
    {"oren_nayar", FC_DIFFUSE_OREN_NAYAR, FC_SPECULAR_NONE, FC_NDF_GGX, FC_G_SMITH_CORRELATED},
    {"cook_torrance", FC_DIFFUSE_LAMBERT, FC_SPECULAR_MICROFACET, FC_NDF_BECKMANN, FC_G_COOK_TORRANCE},
    {"blinn_phong", FC_DIFFUSE_LAMBERT, FC_SPECULAR_BLINN_PHONG, FC_NDF_GGX, FC_G_SMITH_CORRELATED},
    {"blinn_phong_normalized", FC_DIFFUSE_LAMBERT, FC_SPECULAR_BLINN_PHONG_NORMALIZED, FC_NDF_GGX,
     FC_G_SMITH_CORRELATED},
    {"ashikhmin_shirley", FC_DIFFUSE_ASHIKHMIN_SHIRLEY, FC_SPECULAR_ASHIKHMIN_SHIRLEY, FC_NDF_GGX,
     FC_G_SMITH_CORRELATED},
    {"ggx", FC_DIFFUSE_LAMBERT_1MF0, FC_SPECULAR_MICROFACET, FC_NDF_GGX, FC_G_SMITH_CORRELATED, FC_FRESNEL_SCHLICK,
     true},
    {"microfacet", FC_DIFFUSE_LAMBERT_1MF0, FC_SPECULAR_MICROFACET, FC_NDF_GGX, FC_G_SMITH_CORRELATED,
     FC_FRESNEL_SCHLICK, true},
    {"conductor", FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET, FC_NDF_GGX, FC_G_SMITH_CORRELATED, FC_FRESNEL_CONDUCTOR,
     true},
    // the dielectric's compensation (Turquin's albedo scaling) is not reciprocal: opt-in
    {"dielectric", FC_DIFFUSE_NONE, FC_SPECULAR_DIELECTRIC, FC_NDF_GGX, FC_G_SMITH_CORRELATED, FC_FRESNEL_DIELECTRIC},
    {"eon", FC_DIFFUSE_EON, FC_SPECULAR_NONE, FC_NDF_GGX, FC_G_SMITH_CORRELATED},
};

// The name tables, generated from material_layout.h's lists (value order).
#define FC_ENUM_NAME(value, name) {name, value},
const std::vector<EnumName> kDiffuse = {FC_DIFFUSE_LIST(FC_ENUM_NAME)};
const std::vector<EnumName> kSpecular = {FC_SPECULAR_LIST(FC_ENUM_NAME)};
const std::vector<EnumName> kNdf = {FC_NDF_LIST(FC_ENUM_NAME)};
const std::vector<EnumName> kGeometry = {FC_G_LIST(FC_ENUM_NAME)};
const std::vector<EnumName> kFresnel = {FC_FRESNEL_LIST(FC_ENUM_NAME)};
const std::vector<EnumName> kSampling = {FC_SAMPLE_LIST(FC_ENUM_NAME)};
#undef FC_ENUM_NAME

struct ConductorRow {
    std::string_view name;
    std::array<float, 3> eta, k;
};

struct F0Row {
    std::string_view name;
    std::array<float, 3> f0;
};
// Linear column of the table (Hoffman 2013, from Real-Time Rendering 3rd ed.;
// the lecture prints it too): its sRGB column decodes to these within 0.015.
constexpr F0Row kF0[] = {
    {"water", {0.02f, 0.02f, 0.02f}},      {"plastic_low", {0.03f, 0.03f, 0.03f}},
    {"plastic", {0.03f, 0.03f, 0.03f}},    {"glass_low", {0.03f, 0.03f, 0.03f}},
    {"glass", {0.03f, 0.03f, 0.03f}},      {"plastic_high", {0.05f, 0.05f, 0.05f}},
    {"glass_high", {0.08f, 0.08f, 0.08f}}, {"ruby", {0.08f, 0.08f, 0.08f}},
    {"diamond", {0.17f, 0.17f, 0.17f}},    {"iron", {0.56f, 0.57f, 0.58f}},
    {"copper", {0.95f, 0.64f, 0.54f}},     {"gold", {1.00f, 0.71f, 0.29f}},
    {"aluminium", {0.91f, 0.92f, 0.92f}},  {"aluminum", {0.91f, 0.92f, 0.92f}},
    {"silver", {0.95f, 0.93f, 0.88f}},
};

// Complex indices n + i k of metals at R = 630 nm, G = 532 nm, B = 465 nm, linearly
// interpolated in photon energy between the tabulated points (and rounded to 2-3
// digits) of:
//   gold, silver, copper  P. B. Johnson and R. W. Christy, "Optical constants of the
//                         noble metals", Phys. Rev. B 6, 4370 (1972), table 1;
//   aluminium             A. D. Rakic, "Algorithm for the determination of intrinsic
//                         optical constants of metal films: application to aluminum",
//                         Appl. Opt. 34, 4755 (1995);
//   iron                  P. B. Johnson and R. W. Christy, "Optical constants of
//                         transition metals", Phys. Rev. B 9, 5056 (1974).
// The values were transcribed as the refractiveindex.info tables print them; they are
// point samples, not spectral integrals over the RGB primaries, so the normal-incidence
// reflectance differs from the F0 table above by up to ~0.12 (gold's blue).
constexpr ConductorRow kConductors[] = {
    {"gold", {0.188f, 0.543f, 1.33f}, {3.40f, 2.23f, 1.87f}},
    {"silver", {0.056f, 0.054f, 0.047f}, {4.28f, 3.43f, 2.81f}},
    {"copper", {0.271f, 1.10f, 1.24f}, {3.41f, 2.59f, 2.40f}},
    {"aluminium", {1.37f, 0.958f, 0.665f}, {7.62f, 6.69f, 5.66f}},
    {"aluminum", {1.37f, 0.958f, 0.665f}, {7.62f, 6.69f, 5.66f}},
    {"iron", {2.88f, 2.80f, 2.55f}, {3.05f, 2.95f, 2.80f}},
};

std::string rgb(const glm::vec3& c) { return fmt::format("({:g}, {:g}, {:g})", c[0], c[1], c[2]); }

}  // namespace

glm::vec3& specular_colour(Material& m) {
    switch (m.specular_model) {
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            return m.ks;
        case FC_SPECULAR_DIELECTRIC:
            return m.transmittance;
        default:
            return m.f0;
    }
}

const glm::vec3& specular_colour(const Material& m) { return specular_colour(const_cast<Material&>(m)); }

const std::vector<std::string_view>& material_model_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> v;
        for (const Preset& p : kPresets) v.push_back(p.name);
        return v;
    }();
    return names;
}

std::optional<Material> material_preset(std::string_view model) {
    for (const Preset& p : kPresets) {
        if (p.name != model) continue;
        Material m;
        m.diffuse_model = p.diffuse;
        m.specular_model = p.specular;
        m.ndf = p.ndf;
        m.geometry = p.geometry;
        m.fresnel = p.fresnel;
        m.energy_compensation = p.energy_compensation;
        if (p.specular == FC_SPECULAR_DIELECTRIC) {
            m.f0 = m.ks = m.transmittance = glm::vec3(1.0f);  // clear: no absorption at the refractions
            m.alpha_x = m.alpha_y = 0.0f;                     // smooth glass
        }
        if (p.fresnel == FC_FRESNEL_CONDUCTOR) {
            ConductorIndex c = *conductor_preset("aluminium");
            std::array<float, 3> f0 = *f0_preset("aluminium");
            for (int i = 0; i < 3; ++i)
                m.eta[i] = c.eta[i], m.k[i] = c.k[i], m.f0[i] = m.ks[i] = m.transmittance[i] = f0[i];
            m.diffuse = glm::vec3(0.0f);
        }
        return m;
    }
    return std::nullopt;
}

Material make_material(const std::string& model) {
    if (auto m = material_preset(model)) return *m;
    throw Error(unknown_name("material model", model, name_list(material_model_names())));
}

std::string material_model_of(const Material& m) {
    for (const Preset& p : kPresets) {
        if (p.name == "microfacet" || m.diffuse_model != p.diffuse || m.specular_model != p.specular) continue;
        bool microfacet = p.specular == FC_SPECULAR_MICROFACET;
        if (microfacet && (m.ndf != p.ndf || m.geometry != p.geometry || m.fresnel != p.fresnel)) continue;
        return std::string(p.name);
    }
    return m.specular_model == FC_SPECULAR_MICROFACET ? "microfacet" : "custom";
}

const std::vector<EnumName>& enum_names(MaterialEnum kind) {
    switch (kind) {
        case MaterialEnum::Diffuse:
            return kDiffuse;
        case MaterialEnum::Specular:
            return kSpecular;
        case MaterialEnum::Ndf:
            return kNdf;
        case MaterialEnum::Geometry:
            return kGeometry;
        case MaterialEnum::Fresnel:
            return kFresnel;
        case MaterialEnum::Sampling:
            return kSampling;
    }
    return kSampling;
}

std::optional<int> enum_from_name(MaterialEnum kind, std::string_view name) {
    std::string n = lower(name);
    for (const EnumName& e : enum_names(kind))
        if (e.name == n) return e.value;
    return std::nullopt;
}

std::string enum_to_name(MaterialEnum kind, int value) {
    for (const EnumName& e : enum_names(kind))
        if (e.value == value) return std::string(e.name);
    return fmt::format("invalid({})", value);
}

std::string_view enum_kind_name(MaterialEnum kind) {
    switch (kind) {
        case MaterialEnum::Diffuse:
            return "diffuse model";
        case MaterialEnum::Specular:
            return "specular model";
        case MaterialEnum::Ndf:
            return "ndf";
        case MaterialEnum::Geometry:
            return "geometry";
        case MaterialEnum::Fresnel:
            return "fresnel";
        case MaterialEnum::Sampling:
            return "sampling";
    }
    return "?";
}

std::string enum_name_list(MaterialEnum kind) {
    const auto& names = enum_names(kind);
    std::string r;
    for (std::size_t i = 0; i < names.size(); ++i)
        r += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + std::string(names[i].name);
    return r;
}

float alpha_from_phong_exponent(float s) { return std::sqrt(2.0f / (s + 2.0f)); }

float shininess_from_roughness(float m) {
    if (std::isnan(m)) return phong_exponent_from_alpha(kDefaultAlpha);
    return std::clamp(phong_exponent_from_alpha(std::clamp(m, 1e-3f, 1.0f)), 0.0f, kExponentMax);
}

float roughness_from_shininess(float s) {
    if (std::isnan(s)) return kDefaultAlpha;
    return std::clamp(alpha_from_phong_exponent(std::clamp(s, 0.0f, kExponentMax)), 1e-3f, 1.0f);
}

std::optional<std::array<float, 3>> f0_preset(std::string_view name) {
    std::string n = lower(name);
    for (const F0Row& r : kF0)
        if (r.name == n) return r.f0;
    return std::nullopt;
}

std::optional<ConductorIndex> conductor_preset(std::string_view name) {
    std::string n = lower(name);
    for (const ConductorRow& r : kConductors)
        if (r.name == n) return ConductorIndex{r.eta, r.k};
    return std::nullopt;
}

std::vector<std::string_view> conductor_preset_names() {
    std::vector<std::string_view> v;
    for (const ConductorRow& r : kConductors) v.push_back(r.name);
    return v;
}

std::vector<std::string_view> f0_preset_names() {
    std::vector<std::string_view> v;
    for (const F0Row& r : kF0) v.push_back(r.name);
    return v;
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

void set_metallic_roughness(Material& m, glm::vec3 base, float metallic, float dielectric_f0) {
    m.metallic = 0.0f;
    if (metallic >= 1.0f) {  // the metal alone
        m.diffuse_model = FC_DIFFUSE_NONE;
        m.diffuse = glm::vec3(0.0f);
        m.f0 = m.ks = m.transmittance = base;
        return;
    }
    m.diffuse_model = FC_DIFFUSE_LAMBERT_1MF0;
    m.diffuse = base;
    m.f0 = m.ks = m.transmittance = glm::vec3(dielectric_f0);
    m.metallic = std::max(metallic, 0.0f);
}

bool material_is_anisotropic(const Material& m) {
    if (m.anisotropy > 0.0f) return true;
    if (m.specular_model == FC_SPECULAR_MICROFACET || m.specular_model == FC_SPECULAR_DIELECTRIC)
        return m.alpha_x != m.alpha_y;
    return m.specular_model == FC_SPECULAR_ASHIKHMIN_SHIRLEY && m.exponent_x != m.exponent_y;
}

std::string validate_material(const Material& m) {
    auto bad = [](float v, bool ok) { return !std::isfinite(v) || !ok; };
    const struct {
        const char* name;
        const glm::vec3& v;
        float hi;
    } colours[] = {{"diffuse", m.diffuse, 1.0f},
                   {"specular f0", m.f0, 1.0f},
                   {"specular ks", m.ks, 1.0f},
                   {"specular transmittance", m.transmittance, 1.0f},
                   {"emission", m.emission, FC_MAX_RADIANCE},
                   {"k", m.k, INFINITY}};
    for (const auto& c : colours)
        for (int i = 0; i < 3; ++i)
            if (bad(c.v[i], c.v[i] >= 0.0f && c.v[i] <= c.hi))
                return fmt::format("{} must be finite numbers >= 0{} (got {})", c.name,
                                   std::isinf(c.hi) ? "" : fmt::format(" and <= {:g}", c.hi), rgb(c.v));
    for (int i = 0; i < 3; ++i)
        if (bad(m.eta[i], m.eta[i] > 0.0f)) return fmt::format("eta must be finite numbers > 0 (got {})", rgb(m.eta));
    const struct {
        const char* name;
        float v;
    } scalars[] = {{"alpha_x", m.alpha_x},       {"alpha_y", m.alpha_y}, {"exponent_x", m.exponent_x},
                   {"exponent_y", m.exponent_y}, {"sigma", m.sigma},     {"eon_roughness", m.eon_roughness}};
    for (const auto& s : scalars)
        if (bad(s.v, s.v >= 0.0f)) return fmt::format("{} must be a finite number >= 0 (got {:g})", s.name, s.v);
    if (bad(m.metallic, m.metallic >= 0.0f && m.metallic <= 1.0f))
        return fmt::format("metallic must be a finite number in [0, 1] (got {:g})", m.metallic);
    if (bad(m.specular_f90, m.specular_f90 >= 0.0f && m.specular_f90 <= 1.0f))
        return fmt::format("specular_f90 must be a finite number in [0, 1] (got {:g})", m.specular_f90);
    if (bad(m.alpha, m.alpha >= 0.0f && m.alpha <= 1.0f))
        return fmt::format("alpha must be a finite number in [0, 1] (got {:g})", m.alpha);
    if (bad(m.alpha_cutoff, true))
        return fmt::format("alpha_cutoff must be a finite number (got {:g})", m.alpha_cutoff);
    if (m.alpha_mode < 0 || m.alpha_mode >= FC_ALPHA_MODE_COUNT)
        return fmt::format("alpha mode {} is out of range", m.alpha_mode);
    if (bad(m.ior, m.ior > 0.0f)) return fmt::format("ior must be a finite number > 0 (got {:g})", m.ior);
    if (bad(m.anisotropy, m.anisotropy >= 0.0f && m.anisotropy <= 1.0f))
        return fmt::format("anisotropy must be a finite number in [0, 1] (got {:g})", m.anisotropy);
    if (bad(m.anisotropy_rotation, true))
        return fmt::format("anisotropy_rotation must be a finite number (got {:g})", m.anisotropy_rotation);
    const struct {
        MaterialEnum kind;
        int v;
    } enums[] = {{MaterialEnum::Diffuse, m.diffuse_model},
                 {MaterialEnum::Specular, m.specular_model},
                 {MaterialEnum::Ndf, m.ndf},
                 {MaterialEnum::Geometry, m.geometry},
                 {MaterialEnum::Fresnel, m.fresnel},
                 {MaterialEnum::Sampling, m.sampling}};
    for (const auto& e : enums)
        if (e.v < 0 || e.v >= int(enum_names(e.kind).size()))
            return fmt::format("{} {} is out of range (expected {})", enum_kind_name(e.kind), e.v,
                               enum_name_list(e.kind));
    return {};
}

std::string clamp_reflectance(Material& m, std::string_view names) {
    bool clamped = false;
    for (int c = 0; c < 3; ++c) {
        for (glm::vec3* colour : {&m.diffuse, &m.f0, &m.ks, &m.transmittance}) {
            clamped = clamped || (*colour)[c] > 1.0f;
            (*colour)[c] = std::min((*colour)[c], 1.0f);
        }
    }
    return clamped
               ? fmt::format("a reflectance{}{} above 1 creates energy; clamped to 1", names.empty() ? "" : " ", names)
               : "";
}

void clamp_material(Material& m) {
    auto clampf = [](float& v, float lo, float hi) {
        if (!std::isnan(v)) v = std::clamp(v, lo, hi);
    };
    for (int i = 0; i < 3; ++i) {
        clampf(m.diffuse[i], 0.0f, INFINITY);
        clampf(m.f0[i], 0.0f, INFINITY);
        clampf(m.ks[i], 0.0f, INFINITY);
        clampf(m.transmittance[i], 0.0f, INFINITY);
        clampf(m.emission[i], 0.0f, INFINITY);
        clampf(m.k[i], 0.0f, INFINITY);
    }
    clampf(m.exponent_x, 0.0f, kExponentMax);
    clampf(m.exponent_y, 0.0f, kExponentMax);
    clampf(m.alpha_x, 0.0f, 10.0f);
    clampf(m.alpha_y, 0.0f, 10.0f);
    clampf(m.sigma, 0.0f, kPiF / 2.0f);
    clampf(m.eon_roughness, 0.0f, 1.0f);
}

std::string describe_material(const Material& m) {
    std::string s = material_model_of(m) + ":";
    if (m.diffuse_model != FC_DIFFUSE_NONE) {
        s += fmt::format(" diffuse {} {}", enum_to_name(MaterialEnum::Diffuse, m.diffuse_model), rgb(m.diffuse));
        if (m.diffuse_model == FC_DIFFUSE_OREN_NAYAR) s += fmt::format(" sigma={:g}", m.sigma);
        if (m.diffuse_model == FC_DIFFUSE_EON) s += fmt::format(" roughness={:g}", m.eon_roughness);
    }
    switch (m.specular_model) {
        case FC_SPECULAR_MICROFACET:
            s += fmt::format(" specular microfacet D={} G={} F={}", enum_to_name(MaterialEnum::Ndf, m.ndf),
                             enum_to_name(MaterialEnum::Geometry, m.geometry),
                             enum_to_name(MaterialEnum::Fresnel, m.fresnel));
            if (m.fresnel == FC_FRESNEL_SCHLICK) s += " F0=" + rgb(m.f0);
            if (m.fresnel == FC_FRESNEL_SCHLICK && m.specular_f90 != 1.0f)
                s += fmt::format(" F90={:g}", m.specular_f90);
            if (m.fresnel == FC_FRESNEL_SCHLICK_IOR || m.fresnel == FC_FRESNEL_DIELECTRIC)
                s += fmt::format(" ior={:g}", m.ior);
            if (m.fresnel == FC_FRESNEL_CONDUCTOR) s += " eta=" + rgb(m.eta) + " k=" + rgb(m.k);
            if (m.ndf == FC_NDF_BLINN_PHONG) s += fmt::format(" exponent={:g}", m.exponent_x);
            else s += fmt::format(" alpha=({:g}, {:g})", m.alpha_x, m.alpha_y);
            s += " sampling=" + enum_to_name(MaterialEnum::Sampling, m.sampling);
            if (m.metallic > 0.0f) s += fmt::format(" metallic={:g} (F0 of the metal: the diffuse colour)", m.metallic);
            if (m.energy_compensation) s += " energy_compensation";
            break;
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            s += fmt::format(" specular {} Ks={} exponent={:g}", enum_to_name(MaterialEnum::Specular, m.specular_model),
                             rgb(m.ks), m.exponent_x);
            break;
        case FC_SPECULAR_ASHIKHMIN_SHIRLEY:
            s +=
                fmt::format(" specular ashikhmin_shirley F0={} nu={:g} nv={:g}", rgb(m.f0), m.exponent_x, m.exponent_y);
            break;
        case FC_SPECULAR_DIELECTRIC:
            s += fmt::format(" specular dielectric ior={:g} D={} transmittance={}", m.ior,
                             enum_to_name(MaterialEnum::Ndf, m.ndf), rgb(m.transmittance));
            if (std::max(m.alpha_x, m.alpha_y) < FC_ALPHA_MIRROR) s += " smooth";
            else s += fmt::format(" alpha=({:g}, {:g})", m.alpha_x, m.alpha_y);
            break;
        default:
            if (m.specular_model != FC_SPECULAR_NONE) s += fmt::format(" specular invalid({})", m.specular_model);
    }
    if (m.anisotropy > 0.0f)
        s += fmt::format(" anisotropy={:g} rotation={:g} rad", m.anisotropy, m.anisotropy_rotation);
    if (m.emission[0] > 0.0f || m.emission[1] > 0.0f || m.emission[2] > 0.0f) s += " emission=" + rgb(m.emission);
    if (m.alpha_mode == FC_ALPHA_MASK)
        s += fmt::format(" alpha_mode=mask alpha={:g} cutoff={:g}", m.alpha, m.alpha_cutoff);
    else if (m.alpha_mode == FC_ALPHA_BLEND) s += fmt::format(" alpha_mode=blend alpha={:g}", m.alpha);
    if (m.alpha_mode != FC_ALPHA_OPAQUE && m.textures.alpha >= 0)
        s += m.textures.alpha_channel == 0 ? " x texture R" : " x texture A";
    return s;
}

glm::vec3 attenuation_coefficient(glm::vec3 colour, float distance) {
    glm::vec3 sigma;
    for (int c = 0; c < 3; ++c) sigma[c] = -std::log(std::max(colour[c], 1e-6f)) / distance;
    return sigma;
}

}  // namespace facet
