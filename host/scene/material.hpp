// The host side of materials: the host's Material (a model's lobe choices and its
// parameters, which the readers fill and host/scene/device_scene.cpp compiles into the
// kernels' FcMaterial of kernels/shared/material_layout.h), the named models of the
// source documents as presets, the name tables the scene parser and `facet info` use,
// roughness <-> shininess conversions, normal-incidence Fresnel presets, and
// validation. docs/brdf.md describes every model.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "host/scene/texture_binding.hpp"
#include "kernels/shared/material_layout.h"

namespace facet {

// The Phong exponent s of Beckmann roughness alpha, s = 2 / alpha^2 - 2 (Walter et al. 2007,
// eq. 30), and its inverse alpha = sqrt(2 / (s + 2)), unclamped: the one place the relation
// is written (shininess_from_roughness and roughness_from_shininess clamp it).
constexpr float phong_exponent_from_alpha(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }
float alpha_from_phong_exponent(float s);

// A material as the host holds it: the model (a diffuse lobe and a specular lobe, the
// microfacet terms D, G, F and the sampling, each an FC_* value of material_layout.h)
// and its parameters, colours in linear RGB. The defaults are facet's (see
// material_preset) with Lambert's lobes.
struct Material {
    int diffuse_model = FC_DIFFUSE_LAMBERT;
    int specular_model = FC_SPECULAR_NONE;
    int ndf = FC_NDF_GGX;
    int geometry = FC_G_SMITH_CORRELATED;
    int fresnel = FC_FRESNEL_SCHLICK;
    int sampling = FC_SAMPLE_VISIBLE;
    glm::vec3 diffuse{0.5f};
    // The specular lobe's colour, one field per meaning; the lobe reads one of them
    // (specular_colour below). A preset sets all three to its one colour, so that a
    // material switched to another lobe keeps it.
    glm::vec3 f0{0.04f};             // Schlick Fresnel at normal incidence (microfacet,
                                     // Ashikhmin-Shirley; also the (1 - F0) diffuse lobes)
    glm::vec3 ks{0.04f};             // Blinn-Phong's specular colour Ks
    glm::vec3 transmittance{0.04f};  // dielectric: the tint at each refraction
    glm::vec3 emission{0.0f};
    glm::vec3 eta{1.5f};  // conductor: the complex index eta + i k
    glm::vec3 k{0.0f};
    float alpha_x = 0.3f;  // microfacet roughness along the tangent and bitangent
    float alpha_y = 0.3f;
    float exponent_x = phong_exponent_from_alpha(0.3f);  // Phong-style exponents (alpha 0.3)
    float exponent_y = phong_exponent_from_alpha(0.3f);
    float ior = 1.5f;            // relative index (Schlick from ior, dielectric)
    float sigma = 0.3f;          // Oren-Nayar's sigma, radians
    float eon_roughness = 0.3f;  // EON's roughness r in [0, 1] (Portsmouth et al. 2024)
    bool two_sided_emission = false;
    // Multiple-scattering energy compensation of the GGX / Beckmann lobes and the 1 - E_spec
    // coupling of the diffuse base (docs/brdf.md); the presets turn it on for ggx,
    // microfacet and conductor, off for the classic named models and for the dielectric
    // (whose albedo scaling is not reciprocal: opt-in).
    bool energy_compensation = false;
    // glTF's metallic M in [0, 1] (microfacet lobes): f = (1 - M) f + M f_metal, f_metal the
    // microfacet lobe with Schlick F0 = diffuse, the base colour (kernels/bsdf/metallic.cl).
    float metallic = 0.0f;
    // Coverage (glTF's alphaMode, OBJ's d / map_d; kernels/trace/alpha_test.cl): FC_ALPHA_OPAQUE
    // ignores it; MASK cuts the surface away where alpha (x the alpha texture) < alpha_cutoff;
    // BLEND keeps it with probability alpha (stochastic transparency).
    int alpha_mode = FC_ALPHA_OPAQUE;
    float alpha = 1.0f;  // in [0, 1]
    float alpha_cutoff = 0.5f;
    // glTF's KHR_materials_* (FcMaterial's last block; 0: none). attenuation: Beer-Lambert
    // coefficient per unit length inside a transmissive material (KHR_materials_volume);
    // clearcoat weight and GGX alpha (KHR_materials_clearcoat); sheen colour and roughness
    // (KHR_materials_sheen).
    glm::vec3 attenuation{0.0f};
    float clearcoat = 0.0f;
    float clearcoat_alpha = 0.0f;
    glm::vec3 sheen{0.0f};
    float sheen_roughness = 0.0f;
    // KHR_materials_anisotropy (kernels/bsdf/anisotropy.cl): the strength s in [0, 1] stretches
    // the roughness along the anisotropy direction to mix(alpha_x, 1, s^2) in the kernels (after
    // the roughness texture); the direction is the surface's tangent turned by
    // `anisotropy_rotation` (radians) toward the bitangent. Also orients alpha_x != alpha_y.
    float anisotropy = 0.0f;
    float anisotropy_rotation = 0.0f;
    // Schlick's reflectance at grazing incidence (FC_FRESNEL_SCHLICK) in [0, 1]: 1 is Schlick's
    // own; below 1 it is KHR_materials_specular's dielectric F90 = specularFactor
    // (kernels/bsdf/fresnel.cl). The metal lobe of a metallic mix keeps 1.
    float specular_f90 = 1.0f;
    // Image textures bound to the parameters above (docs/textures.md).
    MaterialTextures textures;
};

// The colour field the material's specular lobe reads: ks for the Blinn-Phong lobes,
// transmittance for the dielectric, f0 otherwise (the kernels' FcMaterial.specular).
glm::vec3& specular_colour(Material& m);
const glm::vec3& specular_colour(const Material& m);

// --- named models ---------------------------------------------------------------------
// The presets of material.cpp's kPresets, in its order: "lambert", ..., "ggx" (the
// default), "microfacet", "conductor" (GGX with the exact conductor Fresnel, aluminium's
// eta + i k, no diffuse lobe) and "dielectric" (smooth clear glass, ior 1.5).
const std::vector<std::string_view>& material_model_names();
inline constexpr std::string_view kDefaultMaterialModel = "ggx";

// The preset of a named model with facet's defaults: diffuse 0.5 grey, specular
// colour (F0 / Ks) 0.04, alpha 0.3 (exponents 2/0.3^2 - 2 = 20.2), Oren-Nayar sigma 0.3 rad,
// ior 1.5, no emission, visible-normal sampling. nullopt for an unknown name.
std::optional<Material> material_preset(std::string_view model);
// The same, throwing facet::Error ("unknown material model 'x' (expected one of ...)").
Material make_material(const std::string& model);
// The named model whose lobe choices (diffuse/specular model, and for microfacet
// presets D, G, F) a material has; "microfacet" for other microfacet combinations,
// "custom" otherwise.
std::string material_model_of(const Material& m);

// --- enum name tables (string <-> FC_* value) ------------------------------------------
enum class MaterialEnum { Diffuse, Specular, Ndf, Geometry, Fresnel, Sampling };

struct EnumName {
    std::string_view name;
    int value;
};
// Every name of the enum in value order (each value has exactly one name), as the
// lists of kernels/shared/material_layout.h (FC_DIFFUSE_LIST, ...) give them.
const std::vector<EnumName>& enum_names(MaterialEnum kind);
std::optional<int> enum_from_name(MaterialEnum kind, std::string_view name);
// The name of a value; "invalid(<n>)" when out of range.
std::string enum_to_name(MaterialEnum kind, int value);
// "diffuse model", "specular model", "ndf", "geometry", "fresnel", "sampling".
std::string_view enum_kind_name(MaterialEnum kind);
// "a, b or c": for messages such as "expected one of ...".
std::string enum_name_list(MaterialEnum kind);

// --- roughness <-> shininess ----------------------------------------------------------
// One relation, given three times: the lecture's m = sqrt(2/(2 + s)), the blog's
// s = 2/m^2 - 2 and Walter et al. 2007's alpha_p = 2 alpha_b^-2 - 2 (Phong exponent s
// vs Beckmann roughness m). Shininess is clamped to [0, 1e6] (the kernels' cap),
// roughness to [1e-3, 1] (s = 0 <-> m = 1). NaN gives the respective default 20.2 / 0.3.
float shininess_from_roughness(float m);
float roughness_from_shininess(float s);

// --- Fresnel at normal incidence ------------------------------------------------------
// Linear-RGB F0 of the table in Hoffman's "Physics and Math of Shading" (from Real-Time
// Rendering 3rd ed.; the PV227 lecture prints it with both columns): water, plastic_low
// (= plastic), glass_low (= glass), plastic_high, glass_high, ruby, diamond, iron, copper,
// gold, aluminium (= aluminum), silver. Names are case-insensitive.
std::optional<std::array<float, 3>> f0_preset(std::string_view name);
std::vector<std::string_view> f0_preset_names();

// --- complex indices of metals ----------------------------------------------------------
// eta + i k per linear-RGB channel (R 630 nm, G 532 nm, B 465 nm) of gold, silver, copper,
// aluminium (= aluminum) and iron, from published optical data (material.cpp cites it).
// Names are case-insensitive. The F0 presets of the same names are the Schlick
// alternative ("fresnel": "schlick" in a scene compares the two).
struct ConductorIndex {
    std::array<float, 3> eta, k;
};
std::optional<ConductorIndex> conductor_preset(std::string_view name);
std::vector<std::string_view> conductor_preset_names();
// The sRGB transfer function's inverse (IEC 61966-2-1), for colours given in sRGB.
float srgb_to_linear(float c);

// --- glTF's metallic-roughness -----------------------------------------------------------
// Sets a microfacet material to glTF's mix of a dielectric (Schlick F0 `dielectric_f0` over a
// Lambert base of colour `base`) and a metal (F0 = base) by `metallic` (docs/brdf.md): at 0
// the dielectric alone, at 1 the metal alone (no diffuse lobe), in between the mix.
void set_metallic_roughness(Material& m, glm::vec3 base, float metallic, float dielectric_f0);

// --- volume ------------------------------------------------------------------------------
// The Beer-Lambert coefficient (per unit length, per channel) of a medium through which
// white light keeps `colour` (each in [0, 1]) after `distance` (> 0): -ln(colour) / distance,
// KHR_materials_volume's attenuationColor and attenuationDistance. A channel of 0 absorbs as
// if it kept 1e-6 (finite).
glm::vec3 attenuation_coefficient(glm::vec3 colour, float distance);

// --- anisotropy ---------------------------------------------------------------------------
// Whether the material's specular lobe depends on the direction around the normal (anisotropy
// > 0, or a microfacet / dielectric lobe with alpha_x != alpha_y, or Ashikhmin-Shirley with
// exponent_x != exponent_y): its shading frame then follows the surface's tangent
// (FC_MAT_ANISOTROPIC), and the scene's triangles get tangents.
bool material_is_anisotropic(const Material& m);

// --- validation -----------------------------------------------------------------------
// Empty when every field is usable, else a message naming the first bad field, e.g.
// "alpha_x must be a finite number >= 0 (got nan)". Checks: colours finite and >= 0
// (diffuse, f0, ks and transmittance also <= 1), enums in range, alpha_x/alpha_y/exponents/sigma
// finite and >= 0, ior, eta finite and > 0, k finite and >= 0, anisotropy in [0, 1],
// anisotropy_rotation finite.
std::string validate_material(const Material& m);
// Clamps the diffuse and specular colours (f0, ks, transmittance) to <= 1 (above 1 a surface creates energy);
// the warning to give when it did ("a reflectance <names> above 1 creates energy;
// clamped to 1", `names` e.g. "(Kd, Ks)" for the file's own), else empty.
std::string clamp_reflectance(Material& m, std::string_view names = {});
// Brings finite values into the kernels' working ranges (exponents to [0, 1e6], alpha to
// [0, 10], sigma to [0, pi/2], colours to >= 0): what the kernels would do anyway, made
// visible to `facet info`. Leaves NaN alone (validate_material reports it).
void clamp_material(Material& m);

// One line for `facet info`, e.g. "ggx: diffuse lambert_1mf0 (0.5, 0.5, 0.5), specular
// microfacet D=ggx G=smith_correlated F=schlick F0=(0.04, 0.04, 0.04) alpha=(0.3, 0.3)
// sampling=visible".
std::string describe_material(const Material& m);

}  // namespace facet
