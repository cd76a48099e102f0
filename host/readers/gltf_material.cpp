// glTF materials onto facet's models (glTF 2.0 specification, appendix B; the KHR
// extensions' own documents for ior, transmission, emissive strength, clearcoat, sheen and
// anisotropy).
#include "host/readers/gltf_material.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "host/error.hpp"
#include "host/readers/text_parse.hpp"
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

// KHR_materials_volume on a transmissive material: Beer-Lambert absorption inside, from
// attenuationColor (default white: none) and attenuationDistance (default infinite: none);
// thicknessFactor is for rasterisers (a path tracer follows the ray through the mesh).
void read_volume(const tinygltf::Material& g, Material& m, const std::string& file, const std::string& place,
                 const std::string& where, Ignored& ignored) {
    const auto it = g.extensions.find("KHR_materials_volume");
    if (it == g.extensions.end() || !it->second.IsObject()) return;
    const tinygltf::Value& v = it->second;
    if (m.specular_model != FC_SPECULAR_DIELECTRIC) {
        ignored.add("KHR_materials_volume on a material that does not transmit", where);
        return;
    }
    glm::vec3 colour(1.0f);
    if (v.Has("attenuationColor")) {
        const tinygltf::Value& c = v.Get("attenuationColor");
        if (!c.IsArray() || c.ArrayLen() != 3)
            throw Error(fmt::format("{}: {}: KHR_materials_volume.attenuationColor must have 3 numbers", file, place));
        for (int i = 0; i < 3; ++i)
            colour[i] = in_range(c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : std::nan(""), 0, 1, file, place,
                                 "KHR_materials_volume.attenuationColor");
    }
    const double distance = extension_number(g, "KHR_materials_volume", "attenuationDistance", HUGE_VAL);
    if (!(distance > 0.0))
        throw Error(fmt::format("{}: {}: KHR_materials_volume.attenuationDistance must be > 0, got {:g}", file, place,
                                distance));
    if (std::isfinite(distance)) m.attenuation = attenuation_coefficient(colour, float(distance));
}

// --- textures ----------------------------------------------------------------------------

int wrap_mode(int gl) {
    if (gl == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return FC_WRAP_CLAMP;
    if (gl == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return FC_WRAP_MIRROR;
    return FC_WRAP_REPEAT;
}

// "%20" and friends of a relative URI decoded.
std::string uri_decode(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uri[i + 1]) && std::isxdigit(uri[i + 2])) {
            out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else out += uri[i];
    }
    return out;
}

// An image held in the file (a data URI or a buffer view).
TextureImage embedded_texture(const tinygltf::Image& image, TextureSpace space, const std::string& owner) {
    const std::string ext = image.mimeType == "image/jpeg" ? ".jpg" : ".png";
    return load_texture_bytes(image.image.data(), image.image.size(), ext, space, owner);
}

// What the glTF texture `index` of a material slot is bound from.
struct TextureSlot {
    int index;
    int tex_coord;
    const tinygltf::ExtensionMap* extensions;
    const char* name;
    TextureSpace space;
};

// Loads the slot's texture into scene.textures (once per image, space and wrap modes)
// and returns its index, or -1 without one.
int bind_texture(const TextureSlot& slot, const tinygltf::Model& model, const std::string& file,
                 const std::string& where, Ignored& ignored, Scene& scene) {
    if (slot.index < 0) return -1;
    if (std::size_t(slot.index) >= model.textures.size())
        throw Error(fmt::format("{}: {}: {} names texture {}, which does not exist ({} textures)", file, where,
                                slot.name, slot.index, model.textures.size()));
    if (slot.tex_coord != 0)
        ignored.add(fmt::format("{} on TEXCOORD_{} (TEXCOORD_0 is used)", slot.name, slot.tex_coord), where);
    const tinygltf::Texture& tex = model.textures[std::size_t(slot.index)];
    if (tex.source < 0 || std::size_t(tex.source) >= model.images.size())
        throw Error(fmt::format("{}: textures[{}]: no image (source {}; {} images)", file, slot.index, tex.source,
                                model.images.size()));
    int wrap_u = FC_WRAP_REPEAT, wrap_v = FC_WRAP_REPEAT;
    if (tex.sampler >= 0 && std::size_t(tex.sampler) < model.samplers.size()) {
        wrap_u = wrap_mode(model.samplers[std::size_t(tex.sampler)].wrapS);
        wrap_v = wrap_mode(model.samplers[std::size_t(tex.sampler)].wrapT);
    }
    const tinygltf::Image& image = model.images[std::size_t(tex.source)];
    const std::string owner = fmt::format("{} of {} in {} (images[{}])", slot.name, where, file, tex.source);
    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0)
        return add_texture(scene, text::join_asset_path(text::directory_of(file), uri_decode(image.uri)), slot.space,
                           owner, wrap_u, wrap_v);
    // Embedded images: one key per image of this file.
    const std::string key = fmt::format("{}#images[{}]", file, tex.source);
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const TextureImage& t = scene.textures[i];
        if (t.path == key && t.space == slot.space && t.wrap_u == wrap_u && t.wrap_v == wrap_v) return int(i);
    }
    TextureImage t = embedded_texture(image, slot.space, owner);
    t.path = key;
    t.wrap_u = wrap_u;
    t.wrap_v = wrap_v;
    scene.textures.push_back(std::move(t));
    return int(scene.textures.size() - 1);
}

// KHR_texture_transform of a texture slot as two rows of an affine map (identity without it).
std::array<float, 6> texture_transform(const tinygltf::ExtensionMap& ext, Ignored& ignored, const std::string& where) {
    std::array<float, 6> m{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f};
    const auto it = ext.find("KHR_texture_transform");
    if (it == ext.end() || !it->second.IsObject()) return m;
    const tinygltf::Value& v = it->second;
    auto number = [&](const char* key, int i, double fallback) {
        if (!v.Has(key)) return fallback;
        const tinygltf::Value& x = v.Get(key);
        if (i >= 0) {
            if (!x.IsArray() || x.ArrayLen() <= std::size_t(i) || !x.Get(i).IsNumber()) return fallback;
            return x.Get(i).GetNumberAsDouble();
        }
        return x.IsNumber() ? x.GetNumberAsDouble() : fallback;
    };
    const double ox = number("offset", 0, 0), oy = number("offset", 1, 0), r = number("rotation", -1, 0);
    const double sx = number("scale", 0, 1), sy = number("scale", 1, 1);
    if (v.Has("texCoord")) ignored.add("KHR_texture_transform.texCoord (TEXCOORD_0 is used)", where);
    // translation x rotation x scale (the extension's own definition)
    m = {float(std::cos(r) * sx),  float(std::sin(r) * sy), float(ox),
         float(-std::sin(r) * sx), float(std::cos(r) * sy), float(oy)};
    return m;
}

// A textureInfo of an extension object `v` at `key` (index, texCoord, its KHR_texture_transform
// and, for normal maps, `scale`), bound as the material's own textures are: TEXCOORD_0 and one
// KHR_texture_transform per material (warned otherwise). -1 without one.
int bind_extension_texture(const tinygltf::Value& v, const char* extension, const char* key, TextureSpace space,
                           Material& m, const std::string& file, const std::string& place, const std::string& where,
                           Ignored& ignored, const tinygltf::Model& model, Scene& scene, float* scale = nullptr) {
    if (!v.Has(key)) return -1;
    const tinygltf::Value& info = v.Get(key);
    const std::string name = fmt::format("extensions.{}.{}", extension, key);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt() || info.Get("index").GetNumberAsInt() < 0)
        throw Error(fmt::format("{}: {}.{}: must be an object with an \"index\" >= 0", file, place, name));
    tinygltf::ExtensionMap ext;
    if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const std::string& k : info.Get("extensions").Keys()) ext[k] = info.Get("extensions").Get(k);
    const int tex_coord =
        info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
    const bool had_texture = m.textures.any();
    const TextureSlot slot{info.Get("index").GetNumberAsInt(), tex_coord, &ext, name.c_str(), space};
    const int bound = bind_texture(slot, model, file, where, ignored, scene);
    const std::array<float, 6> t = texture_transform(ext, ignored, where);
    if (!had_texture) m.textures.uv_transform = t;
    else if (t != m.textures.uv_transform)
        ignored.add("different KHR_texture_transforms in one material (the first is used)", where);
    if (scale && info.Has("scale")) {
        const tinygltf::Value& x = info.Get("scale");
        const double d = x.IsNumber() ? x.GetNumberAsDouble() : std::nan("");
        if (!std::isfinite(d)) throw Error(fmt::format("{}: {}.{}.scale: must be a finite number", file, place, name));
        *scale = float(d);
    }
    return bound;
}

// Binds the material's textures (base colour, metallic-roughness, normal, emission).
void bind_textures(const tinygltf::Material& g, Material& m, glm::vec3 base, float metallic, float f0,
                   const std::string& file, const std::string& where, Ignored& ignored, const tinygltf::Model& model,
                   Scene& scene) {
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    const TextureSlot slots[] = {
        {pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, &pbr.baseColorTexture.extensions,
         "baseColorTexture", TextureSpace::Color},
        {pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
         &pbr.metallicRoughnessTexture.extensions, "metallicRoughnessTexture", TextureSpace::Data},
        {g.normalTexture.index, g.normalTexture.texCoord, &g.normalTexture.extensions, "normalTexture",
         TextureSpace::Data},
        {g.emissiveTexture.index, g.emissiveTexture.texCoord, &g.emissiveTexture.extensions, "emissiveTexture",
         TextureSpace::Color}};
    int bound[4];
    bool have_transform = false;
    for (int i = 0; i < 4; ++i) {
        bound[i] = bind_texture(slots[i], model, file, where, ignored, scene);
        if (bound[i] < 0) continue;
        const std::array<float, 6> t = texture_transform(*slots[i].extensions, ignored, where);
        if (!have_transform) m.textures.uv_transform = t;
        else if (t != m.textures.uv_transform)
            ignored.add("different KHR_texture_transforms in one material (the first is used)", where);
        have_transform = true;
    }
    MaterialTextures& t = m.textures;
    if (m.specular_model == FC_SPECULAR_DIELECTRIC) {
        t.specular = bound[0];  // the base colour tints the glass
    } else if (bound[0] >= 0 || bound[1] >= 0) {
        t.metallic_workflow = true;
        t.base_color = bound[0];
        t.base_factor = base;
        t.metallic_factor = metallic;
        t.dielectric_f0 = f0;
        t.metalness = bound[1];
        t.metal_channel = 2;
        if (bound[1] >= 0 && m.diffuse_model == FC_DIFFUSE_NONE) m.diffuse_model = FC_DIFFUSE_LAMBERT_1MF0;
    }
    t.roughness = bound[1];
    t.roughness_channel = 1;
    t.normal = bound[2];
    t.normal_scale = float(g.normalTexture.scale);
    t.emission = bound[3];
}

// KHR_materials_specular on glTF's dielectric-metal mix: the dielectric's F0 becomes
// min(F0(ior) specularColorFactor specularColorTexture, 1) specularFactor specularTexture.a and
// its F90 specularFactor specularTexture.a (the extension's fresnel_mix; Material::specular_f90,
// kernels/bsdf/fresnel.cl). With either texture, or a colour on a textured material (whose
// texels set the dielectric's F0), the kernels compute both per hit
// (MaterialTextures::specular_extension, kernels/texture/extension_textures.cl).
void read_specular(const tinygltf::Material& g, Material& m, float ior, const std::string& file,
                   const std::string& place, const std::string& where, Ignored& ignored, const tinygltf::Model& model,
                   Scene& scene) {
    const auto it = g.extensions.find("KHR_materials_specular");
    if (it == g.extensions.end() || !it->second.IsObject()) return;
    const tinygltf::Value& v = it->second;
    if (m.specular_model != FC_SPECULAR_MICROFACET) {
        ignored.add("KHR_materials_specular on a transmissive material", where);
        return;
    }
    const float factor = in_range(extension_number(g, "KHR_materials_specular", "specularFactor", 1.0), 0, 1, file,
                                  place, "KHR_materials_specular.specularFactor");
    glm::vec3 colour(1.0f);
    if (v.Has("specularColorFactor")) {
        const tinygltf::Value& c = v.Get("specularColorFactor");
        if (!c.IsArray() || c.ArrayLen() != 3)
            throw Error(
                fmt::format("{}: {}: KHR_materials_specular.specularColorFactor must have 3 numbers", file, place));
        for (int i = 0; i < 3; ++i)
            colour[i] = in_range(c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : std::nan(""), 0, 1e3, file, place,
                                 "KHR_materials_specular.specularColorFactor");
    }
    if (m.metallic <= 0.0f && m.diffuse_model == FC_DIFFUSE_NONE) return;  // the metal alone: no dielectric
    const float f0_ior = ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f));
    const glm::vec3 f0 = glm::min(f0_ior * colour, glm::vec3(1.0f)) * factor;
    m.f0 = m.ks = m.transmittance = f0;
    m.specular_f90 = factor;
    MaterialTextures& t = m.textures;
    const char* ext = "KHR_materials_specular";
    t.specular_strength = bind_extension_texture(v, ext, "specularTexture", TextureSpace::Data, m, file, place, where,
                                                 ignored, model, scene);
    t.specular_color = bind_extension_texture(v, ext, "specularColorTexture", TextureSpace::Color, m, file, place,
                                              where, ignored, model, scene);
    const bool coloured = f0.x != f0.y || f0.y != f0.z;
    t.dielectric_f0 = (f0.x + f0.y + f0.z) / 3.0f;
    if (t.specular_strength >= 0 || t.specular_color >= 0 || (t.metallic_workflow && coloured)) {
        t.specular_extension = true;
        t.specular_color_f0 = f0_ior * colour;
        t.specular_weight = factor;
    }
}

// --- clearcoat and sheen -------------------------------------------------------------------

// The layers' extensions (kernels/bsdf/clearcoat.cl, sheen.cl), each number checked with its
// JSON path in the message; their textures multiply the factors (extension_textures.cl).
bool layer_extension(const std::string& name) {
    return name == "KHR_materials_clearcoat" || name == "KHR_materials_sheen";
}

// A number of a layer extension's object `v` at `key` (its JSON path extensions.EXT.key after
// `place`), `fallback` when absent, which must lie in [0, 1].
float layer_factor(const tinygltf::Value& v, const char* extension, const char* key, double fallback,
                   const std::string& file, const std::string& place) {
    if (!v.Has(key)) return float(fallback);
    const tinygltf::Value& x = v.Get(key);
    const double d = x.IsNumber() ? x.GetNumberAsDouble() : std::nan("");
    const std::string what = fmt::format("extensions.{}.{}", extension, key);
    if (!(d >= 0.0 && d <= 1.0))
        throw Error(fmt::format("{}: {}.{}: must be a number in [0, 1], got {}", file, place, what,
                                x.IsNumber() ? fmt::format("{:g}", d) : std::string("no number")));
    return float(d);
}

// KHR_materials_clearcoat (clearcoatFactor, clearcoatRoughnessFactor: alpha = roughness^2)
// and KHR_materials_sheen (sheenColorFactor, sheenRoughnessFactor) onto the material's
// layers. The layers go over non-transmissive materials only.
void read_layers(const tinygltf::Material& g, Material& m, const std::string& file, const std::string& place,
                 const std::string& where, Ignored& ignored, const tinygltf::Model& model, Scene& scene) {
    for (const char* extension : {"KHR_materials_clearcoat", "KHR_materials_sheen"}) {
        const auto it = g.extensions.find(extension);
        if (it == g.extensions.end()) continue;
        const tinygltf::Value& v = it->second;
        if (!v.IsObject()) throw Error(fmt::format("{}: {}.extensions.{}: must be an object", file, place, extension));
        if (m.specular_model == FC_SPECULAR_DIELECTRIC) {
            ignored.add(fmt::format("{} on a transmissive material", extension), where);
            continue;
        }
        if (std::string(extension) == "KHR_materials_clearcoat") {
            m.clearcoat = layer_factor(v, extension, "clearcoatFactor", 0.0, file, place);
            const float r = layer_factor(v, extension, "clearcoatRoughnessFactor", 0.0, file, place);
            m.clearcoat_alpha = r * r;
            if (m.clearcoat > 0.0f) {
                m.textures.clearcoat = bind_extension_texture(v, extension, "clearcoatTexture", TextureSpace::Data, m,
                                                              file, place, where, ignored, model, scene);
                m.textures.clearcoat_roughness =
                    bind_extension_texture(v, extension, "clearcoatRoughnessTexture", TextureSpace::Data, m, file,
                                           place, where, ignored, model, scene);
                m.textures.clearcoat_normal =
                    bind_extension_texture(v, extension, "clearcoatNormalTexture", TextureSpace::Data, m, file, place,
                                           where, ignored, model, scene, &m.textures.clearcoat_normal_scale);
            }
            continue;
        }
        if (v.Has("sheenColorFactor")) {
            const tinygltf::Value& c = v.Get("sheenColorFactor");
            if (!c.IsArray() || c.ArrayLen() != 3)
                throw Error(
                    fmt::format("{}: {}.extensions.{}.sheenColorFactor: must have 3 numbers", file, place, extension));
            for (int i = 0; i < 3; ++i) {
                const double x = c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : std::nan("");
                if (!(x >= 0.0 && x <= 1.0))
                    throw Error(fmt::format("{}: {}.extensions.{}.sheenColorFactor[{}]: must be a number in [0, 1]",
                                            file, place, extension, i));
                m.sheen[i] = float(x);
            }
        }
        m.sheen_roughness = layer_factor(v, extension, "sheenRoughnessFactor", 0.0, file, place);
        if (std::max(m.sheen.x, std::max(m.sheen.y, m.sheen.z)) > 0.0f) {
            m.textures.sheen_color = bind_extension_texture(v, extension, "sheenColorTexture", TextureSpace::Color, m,
                                                            file, place, where, ignored, model, scene);
            m.textures.sheen_roughness =
                bind_extension_texture(v, extension, "sheenRoughnessTexture", TextureSpace::Data, m, file, place, where,
                                       ignored, model, scene);
        }
    }
}

// --- anisotropy ------------------------------------------------------------------------------

// KHR_materials_anisotropy (anisotropyStrength in [0, 1], anisotropyRotation in radians,
// counter-clockwise from the tangent toward the bitangent) onto Material.anisotropy and
// anisotropy_rotation; the kernels stretch alpha along that direction to mix(alpha, 1, s^2)
// (kernels/bsdf/anisotropy.cl), for the metal and the dielectric's specular lobe alike.
// anisotropyTexture is not read (warned about and ignored).
void read_anisotropy(const tinygltf::Material& g, Material& m, const std::string& file, const std::string& place,
                     const std::string& where, Ignored& ignored) {
    const char* extension = "KHR_materials_anisotropy";
    const auto it = g.extensions.find(extension);
    if (it == g.extensions.end()) return;
    const tinygltf::Value& v = it->second;
    if (!v.IsObject()) throw Error(fmt::format("{}: {}.extensions.{}: must be an object", file, place, extension));
    if (v.Has("anisotropyTexture")) ignored.add("KHR_materials_anisotropy.anisotropyTexture", where);
    m.anisotropy = layer_factor(v, extension, "anisotropyStrength", 0.0, file, place);
    if (v.Has("anisotropyRotation")) {
        const tinygltf::Value& x = v.Get("anisotropyRotation");
        const double r = x.IsNumber() ? x.GetNumberAsDouble() : std::nan("");
        if (!std::isfinite(r) || std::fabs(r) > 1e6)
            throw Error(fmt::format("{}: {}.extensions.{}.anisotropyRotation: must be a number of radians, got {}",
                                    file, place, extension,
                                    x.IsNumber() ? fmt::format("{:g}", r) : std::string("no number")));
        m.anisotropy_rotation = float(std::remainder(r, 2.0 * std::numbers::pi));
    }
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
           name == "KHR_materials_emissive_strength" || name == "KHR_texture_transform" ||
           name == "KHR_draco_mesh_compression" || name == "KHR_materials_volume" || name == "KHR_materials_specular" ||
           name == "KHR_materials_anisotropy" || layer_extension(name);
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
                          Ignored& ignored, const tinygltf::Model& model, Scene& scene) {
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
        set_metallic_roughness(m, base, metallic, ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f)));
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

    bind_textures(g, m, base, metallic, ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f)), file, where,
                  ignored, model, scene);
    read_specular(g, m, ior, file, place, where, ignored, model, scene);
    read_volume(g, m, file, place, where, ignored);
    read_layers(g, m, file, place, where, ignored, model, scene);
    read_anisotropy(g, m, file, place, where, ignored);
    if (g.occlusionTexture.index >= 0) ignored.add("occlusionTexture (a path tracer computes occlusion itself)", where);
    // alphaMode: OPAQUE ignores alpha; MASK cuts out where alpha < alphaCutoff, BLEND is
    // stochastic transparency; alpha = baseColorFactor's A x the base colour texture's A.
    if (g.alphaMode == "MASK" || g.alphaMode == "BLEND") {
        m.alpha_mode = g.alphaMode == "MASK" ? FC_ALPHA_MASK : FC_ALPHA_BLEND;
        m.alpha =
            float(g.pbrMetallicRoughness.baseColorFactor.size() == 4 ? g.pbrMetallicRoughness.baseColorFactor[3] : 1.0);
        m.alpha_cutoff = float(g.alphaCutoff);
        if (!(m.alpha_cutoff >= 0.0f) || !std::isfinite(m.alpha_cutoff))
            throw Error(
                fmt::format("{}: {}: alphaCutoff must be a finite number >= 0 (got {:g})", file, place, g.alphaCutoff));
        m.textures.alpha = m.specular_model == FC_SPECULAR_DIELECTRIC ? m.textures.specular : m.textures.base_color;
        m.textures.alpha_channel = 3;
    } else if (g.alphaMode != "OPAQUE") {
        ignored.add(fmt::format("alphaMode {} (rendered opaque)", g.alphaMode), where);
    }
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
