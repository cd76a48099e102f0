// glTF materials onto facet's models (glTF 2.0 specification, appendix B; the KHR
// extensions' own documents for ior, transmission and emissive strength).
#include "host/readers/gltf_material.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "host/error.hpp"
#include "kernels/shared/render_layout.h"

namespace facet::gltf {
namespace {

// A number of an extension object, or `fallback` when absent.
double extension_number(const tinygltf::Material& g, const char* extension, const char* key, double fallback) {
    const auto it = g.extensions.find(extension);
    if (it == g.extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
}

float in_range(double v, double lo, double hi, const std::string& file, const std::string& place, const char* what) {
    if (!(v >= lo && v <= hi))
        throw Error(fmt::format("{}: {}: {} must be in [{:g}, {:g}], got {:g}", file, place, what, lo, hi, v));
    return static_cast<float>(v);
}

void note_texture(const tinygltf::TextureInfo& t, const char* name, const std::string& where, Ignored& ignored) {
    if (t.index >= 0) ignored.add(fmt::format("{} (textures are not read yet; the factor alone is used)", name), where);
}

}  // namespace

void Ignored::warn(const std::string& file, std::vector<std::string>& warnings) const {
    for (const auto& [feature, places] : places_) {
        std::string list;
        for (std::size_t i = 0; i < places.size() && i < 4; ++i) list += (i ? ", " : "") + places[i];
        if (places.size() > 4) list += fmt::format(" and {} more", places.size() - 4);
        warnings.push_back(fmt::format("{}: {} is not supported and is ignored ({})", file, feature, list));
    }
}

bool supported_extension(const std::string& name) {
    return name == "KHR_lights_punctual" || name == "KHR_materials_ior" || name == "KHR_materials_transmission" ||
           name == "KHR_materials_emissive_strength";
}

Material default_gltf_material() {
    Material m = make_material("ggx");
    m.diffuse_model = FC_DIFFUSE_NONE;
    m.diffuse = glm::vec3(0.0f);
    m.f0 = m.ks = m.transmittance = glm::vec3(1.0f);
    m.alpha_x = m.alpha_y = 1.0f;
    return m;
}

Material convert_material(const tinygltf::Material& g, const std::string& file, const std::string& place,
                          Ignored& ignored) {
    const std::string where = g.name.empty() ? place : fmt::format("{} '{}'", place, g.name);
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() != 4)
        throw Error(fmt::format("{}: {}: baseColorFactor must have 4 numbers", file, place));
    glm::vec3 base;
    for (int c = 0; c < 3; ++c)
        base[c] = in_range(pbr.baseColorFactor[std::size_t(c)], 0, 1, file, place, "baseColorFactor");
    const float metallic = in_range(pbr.metallicFactor, 0, 1, file, place, "metallicFactor");
    const float roughness = in_range(pbr.roughnessFactor, 0, 1, file, place, "roughnessFactor");
    const float ior =
        in_range(extension_number(g, "KHR_materials_ior", "ior", 1.5), 1, 10, file, place, "KHR_materials_ior.ior");
    const float transmission = in_range(extension_number(g, "KHR_materials_transmission", "transmissionFactor", 0), 0,
                                        1, file, place, "KHR_materials_transmission.transmissionFactor");
    const float strength = in_range(extension_number(g, "KHR_materials_emissive_strength", "emissiveStrength", 1), 0,
                                    1e30, file, place, "KHR_materials_emissive_strength.emissiveStrength");
    glm::vec3 emissive(0.0f);
    if (!g.emissiveFactor.empty() && g.emissiveFactor.size() != 3)
        throw Error(fmt::format("{}: {}: emissiveFactor must have 3 numbers", file, place));
    for (std::size_t c = 0; c < g.emissiveFactor.size(); ++c)
        emissive[int(c)] = in_range(g.emissiveFactor[c], 0, 1, file, place, "emissiveFactor");

    Material m;
    const float alpha = roughness * roughness;
    if (transmission >= 0.5f && metallic < 0.5f) {
        m = make_material("dielectric");
        m.transmittance = m.f0 = m.ks = base;
        m.ior = ior;
    } else {
        m = make_material("ggx");
        const float f0 = ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f));
        m.f0 = m.ks = m.transmittance = glm::mix(glm::vec3(f0), base, metallic);
        m.diffuse = base * (1.0f - metallic);
        if (metallic >= 1.0f) m.diffuse_model = FC_DIFFUSE_NONE;
        m.ior = ior;
    }
    m.alpha_x = m.alpha_y = alpha;
    m.exponent_x = m.exponent_y = shininess_from_roughness(std::max(roughness, 1e-3f));
    m.emission = emissive * strength;
    for (int c = 0; c < 3; ++c)
        if (!(m.emission[c] <= FC_MAX_RADIANCE))
            throw Error(
                fmt::format("{}: {}: emissiveFactor x emissiveStrength must be at most {:g} (got {:g}): the "
                            "image would overflow",
                            file, place, FC_MAX_RADIANCE, m.emission[c]));
    m.two_sided_emission = g.doubleSided;
    if (transmission > 0.0f && transmission < 1.0f)
        ignored.add(fmt::format("a partial transmissionFactor (rounded to {})", transmission >= 0.5f ? 1 : 0), where);

    note_texture(pbr.baseColorTexture, "baseColorTexture", where, ignored);
    note_texture(pbr.metallicRoughnessTexture, "metallicRoughnessTexture", where, ignored);
    note_texture(g.emissiveTexture, "emissiveTexture", where, ignored);
    if (g.normalTexture.index >= 0) ignored.add("normalTexture (no normal maps yet)", where);
    if (g.occlusionTexture.index >= 0) ignored.add("occlusionTexture (a path tracer computes occlusion itself)", where);
    if (g.alphaMode != "OPAQUE") ignored.add(fmt::format("alphaMode {} (rendered opaque)", g.alphaMode), where);
    for (const auto& [name, value] : g.extensions) {
        if (name == "KHR_materials_transmission" && value.IsObject() && value.Has("transmissionTexture"))
            ignored.add("transmissionTexture", where);
        if (!supported_extension(name)) ignored.add("material extension " + name, where);
    }
    if (std::string problem = validate_material(m); !problem.empty())
        throw Error(fmt::format("{}: {}: {}", file, place, problem));
    return m;
}

}  // namespace facet::gltf
