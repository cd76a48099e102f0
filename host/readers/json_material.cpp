// JSON scene files: materials (docs/scene-format.md, "Materials"): a named model's
// preset (host/scene/material.hpp), then its parameters, and references to materials.
#include <algorithm>
#include <array>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/json_loader.hpp"
#include "host/readers/text_parse.hpp"
#include "host/scene/material.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

// One material's keys, read against its JSON path.
struct MaterialKeys {
    const JsonReader& r;
    const Json& v;
    const std::string& path;

    std::string key(const std::string& k) const { return JsonReader::key(path, k); }
    bool has(const char* k) const { return v.contains(k); }
    glm::vec3 color(const char* k) const { return r.color(v[k], key(k)); }
    float number(const std::string& k, double lo, double hi) const { return r.number_in(v[k], key(k), lo, hi); }
    std::string string(const char* k) const { return r.string(v[k], key(k)); }
};

Material preset(const MaterialKeys& m) {
    const std::string model = m.has("model") ? m.string("model") : "lambert";
    std::optional<Material> preset = material_preset(model);
    if (!preset) m.r.fail(m.key("model"), unknown_name("model", model, name_list(material_model_names())));
    return *preset;
}

// "clearcoat" (0 to 1) and "clearcoat_roughness" (0 to 1; alpha = roughness^2), "sheen" (a
// colour, each 0 to 1) and "sheen_roughness" (0 to 1): glTF's KHR_materials_clearcoat and
// KHR_materials_sheen layers (kernels/bsdf/clearcoat.cl, sheen.cl), over any material that
// does not transmit (docs/scene-format.md). "specular_f90" (0 to 1): the Schlick Fresnel's
// reflectance at grazing incidence (KHR_materials_specular's F90; 1 by default).
void layers(const MaterialKeys& k, Material& m) {
    if (k.has("specular_f90")) {
        if (m.fresnel != FC_FRESNEL_SCHLICK || m.specular_model != FC_SPECULAR_MICROFACET)
            k.r.fail(k.key("specular_f90"), "needs a microfacet lobe with \"fresnel\": \"schlick\"");
        m.specular_f90 = k.number("specular_f90", 0, 1);
    }
    for (const char* key : {"clearcoat", "clearcoat_roughness", "sheen", "sheen_roughness"})
        if (k.has(key) && m.specular_model == FC_SPECULAR_DIELECTRIC)
            k.r.fail(k.key(key), "is a layer over a material that does not transmit (not model \"dielectric\")");
    if (k.has("clearcoat")) m.clearcoat = k.number("clearcoat", 0, 1);
    if (k.has("clearcoat_roughness")) {
        const float r = k.number("clearcoat_roughness", 0, 1);
        m.clearcoat_alpha = r * r;
    }
    if (k.has("sheen")) {
        m.sheen = k.color("sheen");
        for (int c = 0; c < 3; ++c)
            if (m.sheen[c] > 1.0f) k.r.fail(k.key("sheen"), "each component must be at most 1");
    }
    if (k.has("sheen_roughness")) m.sheen_roughness = k.number("sheen_roughness", 0, 1);
}

// "anisotropy" (0 to 1) and "anisotropy_rotation" (degrees, counter-clockwise from the
// tangent toward the bitangent): glTF's KHR_materials_anisotropy on the material's microfacet
// lobes (kernels/bsdf/anisotropy.cl).
void anisotropy(const MaterialKeys& k, Material& m) {
    if (k.has("anisotropy")) m.anisotropy = k.number("anisotropy", 0, 1);
    if (k.has("anisotropy_rotation"))
        m.anisotropy_rotation = float(double(k.number("anisotropy_rotation", -360, 360)) * std::numbers::pi / 180.0);
}

// "specular", "f0" and "transmittance" all give the specular lobe's colour: F0 for the
// Schlick Fresnel, Ks for the Blinn-Phong lobes, the dielectric's transmittance
// (specular_colour in material.hpp). Whichever the file writes, the colour goes to the
// field the lobe chosen in the end reads (the lobe may be set after the colour: see
// JsonLoader::material); the last one written wins.
using SpecularColour = std::optional<glm::vec3>;

// "diffuse", "specular", "f0" (numbers or a preset name) and "emission".
void colours(const MaterialKeys& k, Material& m, SpecularColour& specular) {
    if (k.has("diffuse")) m.diffuse = k.color("diffuse");
    if (k.has("specular")) specular = k.color("specular");
    if (k.has("f0")) {
        if (k.v["f0"].is_string()) {
            const std::string preset_name = k.string("f0");
            std::optional<std::array<float, 3>> f0 = f0_preset(preset_name);
            if (!f0) k.r.fail(k.key("f0"), unknown_name("F0 preset", preset_name, name_list(f0_preset_names())));
            specular = glm::vec3((*f0)[0], (*f0)[1], (*f0)[2]);
        } else {
            specular = k.color("f0");
        }
    }
    if (k.has("emission")) m.emission = k.color("emission");
}

// A lobe's width in the two quantities the models read: the microfacet roughness alpha
// and the Phong-style exponent (Blinn-Phong's shininess, Ashikhmin-Shirley's nu/nv),
// related by the lecture's alpha = sqrt(2 / (2 + exponent)) (material.hpp).
struct LobeWidth {
    float alpha, exponent;
    static LobeWidth from_roughness(float r) { return {r, shininess_from_roughness(r)}; }
    static LobeWidth from_shininess(float s) { return {roughness_from_shininess(s), s}; }
    void set_x(Material& m) const { m.alpha_x = alpha, m.exponent_x = exponent; }
    void set_y(Material& m) const { m.alpha_y = alpha, m.exponent_y = exponent; }
};

// The width keys, one knob in the units users write, each model given its own quantity:
//   "roughness" r in [0, 1]   microfacet alpha = r, exponent = 2 / r^2 - 2,
//                             Oren-Nayar's sigma = r (radians) and EON's roughness = r
//   "shininess" s in [0, 1e6] exponent = s, alpha = sqrt(2 / (2 + s))
//   "sigma" in [0, pi/2]      Oren-Nayar's sigma alone
// "_x" / "_y" set one axis (alpha and exponent only). Applied in this order: roughness,
// then shininess; the pair, then each axis; then sigma.
void lobe_widths(const MaterialKeys& k, Material& m) {
    if (k.has("roughness")) {
        const float r = k.number("roughness", 0, 1);
        LobeWidth::from_roughness(r).set_x(m);
        LobeWidth::from_roughness(r).set_y(m);
        m.sigma = r;
        m.eon_roughness = r;
    }
    if (k.has("roughness_x")) LobeWidth::from_roughness(k.number("roughness_x", 0, 1)).set_x(m);
    if (k.has("roughness_y")) LobeWidth::from_roughness(k.number("roughness_y", 0, 1)).set_y(m);
    const double max_exponent = double(FC_PHONG_EXPONENT_MAX);
    if (k.has("shininess")) {
        const float s = k.number("shininess", 0, max_exponent);
        LobeWidth::from_shininess(s).set_x(m);
        LobeWidth::from_shininess(s).set_y(m);
    }
    if (k.has("shininess_x")) LobeWidth::from_shininess(k.number("shininess_x", 0, max_exponent)).set_x(m);
    if (k.has("shininess_y")) LobeWidth::from_shininess(k.number("shininess_y", 0, max_exponent)).set_y(m);
    if (k.has("sigma")) m.sigma = k.number("sigma", 0, 1.5707963);
}

// "conductor": a metal's complex index, with its Schlick F0 beside it for "fresnel": "schlick".
void conductor(const MaterialKeys& k, Material& m, SpecularColour& specular) {
    const std::string metal = k.string("conductor");
    std::optional<ConductorIndex> c = conductor_preset(metal);
    if (!c) k.r.fail(k.key("conductor"), unknown_name("conductor", metal, name_list(conductor_preset_names())));
    const std::array<float, 3> f0 = *f0_preset(metal);
    for (int i = 0; i < 3; ++i) m.eta[i] = c->eta[i], m.k[i] = c->k[i];
    specular = glm::vec3(f0[0], f0[1], f0[2]);
    m.fresnel = FC_FRESNEL_CONDUCTOR;
}

// The lobe choices by name: "diffuse_model", "specular_model", "ndf", "geometry",
// "fresnel", "sampling".
// "attenuation_color" (each 0 to 1) and "attenuation_distance" (> 0), together: glTF's
// KHR_materials_volume, Beer-Lambert absorption inside a dielectric (docs/scene-format.md).
void volume(const MaterialKeys& k, Material& m) {
    if (!k.has("attenuation_color") || !k.has("attenuation_distance"))
        k.r.fail(k.key(k.has("attenuation_color") ? "attenuation_color" : "attenuation_distance"),
                 "needs both attenuation_color and attenuation_distance (the colour white light keeps after that "
                 "distance inside)");
    if (m.specular_model != FC_SPECULAR_DIELECTRIC)
        k.r.fail(k.key("attenuation_color"), "absorbs inside a transmissive material only (model \"dielectric\")");
    const glm::vec3 colour = k.color("attenuation_color");
    for (int c = 0; c < 3; ++c)
        if (colour[c] > 1.0f) k.r.fail(k.key("attenuation_color"), "each component must be at most 1");
    const float distance = k.number("attenuation_distance", 1e-30, 1e30);
    m.attenuation = attenuation_coefficient(colour, distance);
}

void lobe_choices(const MaterialKeys& k, Material& m) {
    auto choice = [&](const char* key, MaterialEnum kind, int& field) {
        if (!k.has(key)) return;
        const std::string value = k.string(key);
        std::optional<int> e = enum_from_name(kind, value);
        if (!e) k.r.fail(k.key(key), unknown_name(enum_kind_name(kind), value, enum_name_list(kind)));
        field = *e;
    };
    choice("diffuse_model", MaterialEnum::Diffuse, m.diffuse_model);
    choice("specular_model", MaterialEnum::Specular, m.specular_model);
    choice("ndf", MaterialEnum::Ndf, m.ndf);
    choice("geometry", MaterialEnum::Geometry, m.geometry);
    choice("fresnel", MaterialEnum::Fresnel, m.fresnel);
    choice("sampling", MaterialEnum::Sampling, m.sampling);
}

// One entry of "textures": a file name, or {"file", "wrap", "channel"}; paths are
// relative to the scene file. Returns the index in scene.textures.
int texture_entry(const MaterialKeys& k, const Json& e, const std::string& path, TextureSpace space,
                  const std::string& owner, Scene& scene, int* channel) {
    const JsonReader& r = k.r;
    std::string file;
    int wrap = FC_WRAP_REPEAT;
    if (e.is_string()) {
        file = r.string(e, path);
    } else {
        r.object(e, path, {"file", "wrap", "channel"});
        if (!e.contains("file")) r.fail(path, "a texture needs \"file\"");
        file = r.string(e["file"], JsonReader::key(path, "file"));
        if (e.contains("wrap")) {
            const std::string w = r.string(e["wrap"], JsonReader::key(path, "wrap"));
            if (w == "repeat") wrap = FC_WRAP_REPEAT;
            else if (w == "clamp") wrap = FC_WRAP_CLAMP;
            else if (w == "mirror") wrap = FC_WRAP_MIRROR;
            else r.fail(JsonReader::key(path, "wrap"), unknown_name("wrap mode", w, "repeat, clamp or mirror"));
        }
        if (e.contains("channel")) {
            const std::string c = r.string(e["channel"], JsonReader::key(path, "channel"));
            const std::string_view names = "rgba";
            if (c.size() != 1 || names.find(c[0]) == std::string_view::npos || !channel)
                r.fail(JsonReader::key(path, "channel"),
                       fmt::format("'{}' is not a channel of this texture (r, g, b or a)", c));
            *channel = int(names.find(c[0]));
        }
    }
    const std::string resolved = text::join_path(text::directory_of(r.file()), file);
    try {
        return add_texture(scene, resolved, space, owner, wrap, wrap);
    } catch (const Error& err) {
        r.fail(path, err.what());
    }
}

// "textures": {"diffuse", "specular", "roughness", "shininess", "metalness", "emission",
// "normal", "normal_scale", "metallic", "uv_scale", "uv_offset", "alpha", and glTF's layers'
// "clearcoat" (R), "clearcoat_roughness" (G), "sheen" (RGB), "sheen_roughness" (A) and
// KHR_materials_specular's "specular_strength" (A: F0 and F90)} (docs/textures.md).
void textures(const MaterialKeys& k, Material& m, const std::string& name, Scene& scene) {
    const std::string path = k.key("textures");
    const Json& t = k.v["textures"];
    const JsonReader& r = k.r;
    r.object(t, path,
             {"diffuse", "specular", "roughness", "shininess", "metalness", "emission", "normal", "normal_scale",
              "metallic", "uv_scale", "uv_offset", "alpha", "clearcoat", "clearcoat_roughness", "sheen",
              "sheen_roughness", "specular_strength"});
    MaterialTextures& b = m.textures;
    auto slot = [&](const char* key, TextureSpace space, int* channel = nullptr) {
        if (!t.contains(key)) return -1;
        return texture_entry(k, t[key], JsonReader::key(path, key), space, fmt::format("material '{}' ({})", name, key),
                             scene, channel);
    };
    b.base_color = slot("diffuse", TextureSpace::Color);
    b.specular = slot("specular", TextureSpace::Color);
    b.roughness = slot("roughness", TextureSpace::Data, &b.roughness_channel);
    if (t.contains("shininess")) {
        if (b.roughness >= 0) r.fail(path, "give \"roughness\" or \"shininess\", not both");
        b.roughness = slot("shininess", TextureSpace::Data, &b.roughness_channel);
        b.roughness_mode = FC_ROUGHNESS_SHININESS;
    }
    b.metalness = slot("metalness", TextureSpace::Data, &b.metal_channel);
    b.emission = slot("emission", TextureSpace::Color);
    b.normal = slot("normal", TextureSpace::Data);
    // Coverage: channel "a" by default, "r" for an image without alpha (a grey mask).
    b.alpha_channel = -1;
    b.alpha = slot("alpha", TextureSpace::Data, &b.alpha_channel);
    if (b.alpha >= 0 && b.alpha_channel < 0) b.alpha_channel = scene.textures[std::size_t(b.alpha)].has_alpha ? 3 : 0;
    if (b.alpha_channel != 0 && b.alpha_channel != 3) {
        if (b.alpha >= 0) r.fail(JsonReader::key(path, "alpha"), "the alpha texture's channel must be \"r\" or \"a\"");
        b.alpha_channel = 3;
    }
    if (b.alpha >= 0 && !k.has("alpha_mode")) m.alpha_mode = FC_ALPHA_BLEND;
    if (t.contains("normal_scale"))
        b.normal_scale = r.number_in(t["normal_scale"], JsonReader::key(path, "normal_scale"), 0, 100);
    if (b.metalness >= 0 || t.contains("metallic")) {
        // The metallic workflow: "diffuse" is the base colour, F0 of the non-metal from the ior.
        b.metallic_workflow = true;
        b.base_factor = m.diffuse;
        b.metallic_factor =
            t.contains("metallic") ? r.number_in(t["metallic"], JsonReader::key(path, "metallic"), 0, 1) : 1.0f;
        b.dielectric_f0 = ((m.ior - 1.0f) / (m.ior + 1.0f)) * ((m.ior - 1.0f) / (m.ior + 1.0f));
    }
    auto pair = [&](const char* key, double lo, double hi, float fallback) {
        glm::vec2 v(fallback);
        if (!t.contains(key)) return v;
        const Json& a = t[key];
        if (!a.is_array() || a.size() != 2) r.fail(JsonReader::key(path, key), "expected two numbers [u, v]");
        for (std::size_t i = 0; i < 2; ++i)
            v[int(i)] = r.number_in(a[i], fmt::format("{}[{}]", JsonReader::key(path, key), i), lo, hi);
        return v;
    };
    // The layers' textures multiply their factors, which must be there (> 0) for them to show.
    auto layer = [&](const char* key, TextureSpace space, bool present, const char* factor) {
        if (!t.contains(key)) return -1;
        if (!present) r.fail(JsonReader::key(path, key), fmt::format("needs the material's \"{}\" above 0", factor));
        return slot(key, space);
    };
    const bool coat = m.clearcoat > 0.0f, sheen = std::max(m.sheen.x, std::max(m.sheen.y, m.sheen.z)) > 0.0f;
    b.clearcoat = layer("clearcoat", TextureSpace::Data, coat, "clearcoat");
    b.clearcoat_roughness = layer("clearcoat_roughness", TextureSpace::Data, coat, "clearcoat");
    b.sheen_color = layer("sheen", TextureSpace::Color, sheen, "sheen");
    b.sheen_roughness = layer("sheen_roughness", TextureSpace::Data, sheen, "sheen");
    if (t.contains("specular_strength")) {
        // KHR_materials_specular's specularTexture: A scales F0 and F90 (kernels/texture/extension_textures.cl)
        if (m.specular_model != FC_SPECULAR_MICROFACET || m.fresnel != FC_FRESNEL_SCHLICK)
            r.fail(JsonReader::key(path, "specular_strength"), "needs a microfacet lobe with \"fresnel\": \"schlick\"");
        b.specular_strength = slot("specular_strength", TextureSpace::Data);
        b.specular_extension = true;
        b.specular_color_f0 = b.metallic_workflow ? glm::vec3(b.dielectric_f0) : m.f0;
        b.specular_weight = 1.0f;
        b.specular_color = b.specular;  // the colour texture multiplies F0 before the strength
        b.specular = -1;
    }
    const glm::vec2 scale = pair("uv_scale", -1e6, 1e6, 1.0f), offset = pair("uv_offset", -1e6, 1e6, 0.0f);
    b.uv_transform = {scale.x, 0.0f, offset.x, 0.0f, scale.y, offset.y};
}

// Coverage (docs/scene-format.md): "alpha_mode" "opaque", "mask" or "blend" ("blend" when
// only "alpha" or an alpha texture is given), "alpha" in [0, 1], "alpha_cutoff" (mask only).
void alpha(const MaterialKeys& k, Material& m) {
    if (k.has("alpha")) {
        m.alpha = k.number("alpha", 0, 1);
        m.alpha_mode = FC_ALPHA_BLEND;
    }
    if (k.has("alpha_mode")) {
        const std::string mode = k.string("alpha_mode");
        bool found = false;
#define FC_ALPHA_NAME(value, text) \
    if (mode == text) m.alpha_mode = value, found = true;
        FC_ALPHA_MODE_LIST(FC_ALPHA_NAME)
#undef FC_ALPHA_NAME
        if (!found) k.r.fail(k.key("alpha_mode"), unknown_name("alpha mode", mode, "opaque, mask or blend"));
    }
    if (k.has("alpha_cutoff")) {
        if (m.alpha_mode != FC_ALPHA_MASK) k.r.fail(k.key("alpha_cutoff"), "needs \"alpha_mode\": \"mask\"");
        m.alpha_cutoff = k.number("alpha_cutoff", 0, 1);
    }
}

}  // namespace

void JsonLoader::material(const std::string& name, const Json& v, const std::string& path) {
    r.object(v, path,
             {"model",
              "diffuse",
              "specular",
              "f0",
              "emission",
              "two_sided_emission",
              "roughness",
              "roughness_x",
              "roughness_y",
              "shininess",
              "shininess_x",
              "shininess_y",
              "sigma",
              "ior",
              "eta",
              "k",
              "diffuse_model",
              "specular_model",
              "ndf",
              "geometry",
              "fresnel",
              "sampling",
              "conductor",
              "transmittance",
              "energy_compensation",
              "clearcoat",
              "clearcoat_roughness",
              "sheen",
              "sheen_roughness",
              "anisotropy",
              "anisotropy_rotation",
              "specular_f90",
              "metallic",
              "attenuation_color",
              "attenuation_distance",
              "alpha_mode",
              "alpha",
              "alpha_cutoff",
              "textures"});
    const MaterialKeys k{r, v, path};
    Material m = preset(k);
    SpecularColour specular;
    colours(k, m, specular);
    lobe_widths(k, m);
    if (k.has("ior")) m.ior = k.number("ior", 1e-3, 100);
    if (k.has("conductor")) conductor(k, m, specular);
    if (k.has("transmittance")) specular = k.color("transmittance");
    if (k.has("eta")) m.eta = k.color("eta");
    if (k.has("k")) m.k = k.color("k");
    lobe_choices(k, m);
    if (specular) specular_colour(m) = *specular;
    if (k.has("two_sided_emission") && r.boolean(v["two_sided_emission"], k.key("two_sided_emission")))
        m.two_sided_emission = true;
    if (k.has("energy_compensation"))
        m.energy_compensation = r.boolean(v["energy_compensation"], k.key("energy_compensation"));
    if (k.has("metallic")) {  // glTF's mix: "diffuse" the base colour, the metal's F0 (docs/brdf.md)
        m.metallic = k.number("metallic", 0, 1);
        if (m.metallic > 0.0f && m.specular_model != FC_SPECULAR_MICROFACET)
            r.fail(k.key("metallic"), "needs a microfacet specular lobe (model \"ggx\" or \"microfacet\")");
    }
    if (k.has("attenuation_color") || k.has("attenuation_distance")) volume(k, m);
    alpha(k, m);
    layers(k, m);
    anisotropy(k, m);
    if (std::string warning = clamp_reflectance(m); !warning.empty())
        scene.warnings.push_back(fmt::format("{}: {}: {}", r.file(), path, warning));
    if (std::string problem = validate_material(m); !problem.empty()) r.fail(path, problem);
    if (k.has("textures")) textures(k, m, name, scene);
    materials[name] = add_material(scene, m, name);
}

int JsonLoader::material_ref(const Json& v, const std::string& path) {
    const std::string name = r.string(v, path);
    auto it = materials.find(name);
    if (it == materials.end()) {
        const std::string known = name_list(materials, [](const auto& m) { return fmt::format("'{}'", m.first); });
        r.fail(path, fmt::format("unknown material '{}' (defined: {})", name, known.empty() ? "none" : known));
    }
    return it->second;
}

int JsonLoader::optional_material(const Json& obj, const std::string& path) {
    if (obj.contains("material")) return material_ref(obj["material"], JsonReader::key(path, "material"));
    if (default_index < 0) default_index = add_material(scene, default_material(), "default");
    return default_index;
}

}  // namespace facet
