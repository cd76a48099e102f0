#include "host/readers/mtl_material.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/readers/text_parse.hpp"

namespace facet {
namespace {

struct MtlLine {
    const std::string& path;
    int line;
    const std::vector<std::string_view>& f;

    [[noreturn]] void fail(const std::string& what) const { throw Error(fmt::format("{}:{}: {}", path, line, what)); }

    float number(std::size_t i) const {
        float v = 0.0f;
        if (!text::parse_float(f[i], v)) {
            fail(fmt::format("'{}': '{}' is {}", f[0], f[i], text::number_problem(f[i])));
        }
        if (!std::isfinite(v)) fail(fmt::format("'{}': '{}' is not finite", f[0], f[i]));
        return v;
    }

    // One number, within [lo, hi].
    float scalar(float lo, float hi) const {
        if (f.size() != 2) fail(fmt::format("'{}' takes one number, found {}", f[0], f.size() - 1));
        const float v = number(1);
        if (v < lo || v > hi) fail(fmt::format("'{}' must be in [{}, {}], got {}", f[0], lo, hi, v));
        return v;
    }

    // "Kd r g b" or "Kd r" (grey); colours must not be negative.
    void color(glm::vec3& out) const {
        if (f.size() >= 2 && (f[1] == "spectral" || f[1] == "xyz")) {
            fail(fmt::format("'{} {}' is not supported; give linear RGB numbers", f[0], f[1]));
        }
        if (f.size() != 2 && f.size() != 4) {
            fail(fmt::format("'{}' takes 3 numbers (or 1 for grey), found {}", f[0], f.size() - 1));
        }
        for (int c = 0; c < 3; ++c) {
            out[c] = number(f.size() == 2 ? 1 : 1 + c);
            if (out[c] < 0.0f) fail(fmt::format("'{}': negative colour {}", f[0], out[c]));
        }
    }
};

bool is_texture_statement(std::string_view kw) {
    return kw.substr(0, 4) == "map_" || kw == "bump" || kw == "disp" || kw == "decal" || kw == "refl" || kw == "norm";
}

bool is_read_texture(std::string_view kw) {
    return kw == "map_Kd" || kw == "map_Ks" || kw == "map_Ns" || kw == "map_Pr" || kw == "map_Pm" || kw == "map_Ke" ||
           kw == "norm" || kw == "map_Bump" || kw == "map_bump" || kw == "bump" || kw == "map_d";
}

// A texture statement's options (-bm, -s, -o, -clamp; others skipped with their
// numbers) and its file, the last field.
MtlTexture texture_statement(const MtlLine& l, const std::string& dir) {
    MtlTexture t;
    t.statement = std::string(l.f[0]);
    t.where = fmt::format("{}:{}", l.path, l.line);
    const std::size_t last = l.f.size() - 1;
    for (std::size_t i = 1; i < last; ++i) {
        const std::string_view o = l.f[i];
        if (o.empty() || o[0] != '-') continue;
        // The numbers after an option (at most 3, never the file name).
        std::size_t n = 0;
        float v[3] = {0.0f, 0.0f, 0.0f};
        while (n < 3 && i + 1 + n < last && text::parse_float(l.f[i + 1 + n], v[n])) ++n;
        if (o == "-bm" && n >= 1) t.bump_multiplier = v[0];
        else if (o == "-s" && n >= 1) t.scale[0] = v[0], t.scale[1] = n >= 2 ? v[1] : v[0];
        else if (o == "-o" && n >= 1) t.offset[0] = v[0], t.offset[1] = n >= 2 ? v[1] : 0.0f;
        else if (o == "-clamp" && i + 1 < last) {
            t.clamp = l.f[i + 1] == "on";
            ++i;
        }
        i += n;
    }
    t.file = text::join_asset_path(dir, std::string(l.f[last]));
    return t;
}

struct Pending {
    MtlMaterial m;
    bool has_pr = false;
    bool has_pm = false;
    bool has_pbr_map = false;  // map_Pr or map_Pm
    bool pm_given = false;
    bool has_ks = false;
    float pr = 0.0f;
    bool has_ns = false;
    float ns = 0.0f;
    glm::vec3 tf{1.0f};
    bool has_d = false;
    float tr = 0.0f;  // Tr, the transparency 1 - d, read when no d is given
    // The PBR extension's layers: Pc (clearcoat weight), Pcr (its perceptual roughness),
    // Ps (sheen, grey), aniso and anisor (anisotropy and its rotation as a fraction of a
    // turn, as Blender writes them); any of them makes the material a PBR one.
    bool has_layers = false;
    float pc = 0.0f, pcr = 0.0f, ps = 0.0f, aniso = 0.0f, anisor = 0.0f;
};

// Chooses the model from what the MTL gives (docs/scene-format.md, "MTL materials"):
// - the PBR extension (Pr or Pm): GGX with height-correlated Smith; base colour Kd,
//   metallic Pm: glTF's mix by Pm of a dielectric (F0(Ni) over a Lambert base Kd) and a
//   metal (F0 = Kd), set_metallic_roughness; alpha = Pr^2 (Pr is
//   perceptual roughness, as in glTF and Disney 2012); no Pr: alpha from Ns;
// - a specular colour (Ks > 0) with illum 2 or more: normalized Blinn-Phong with Ks
//   and exponent Ns (the energy-normalised form of MTL's Phong highlight);
// - illum 5 (a ray-traced mirror): a perfect mirror reflecting Ks (Schlick Fresnel
//   with F0 = Ks, alpha 0), no diffuse lobe;
// - illum 7 (refraction on, Fresnel on): smooth glass of index Ni (exact Fresnel, Snell
//   refraction), tinted by the colour of Tf. The MTL model scales refraction by
//   (1 - Ks) Ft Tf, amounts that the exact Fresnel split replaces, and files use Tf
//   inconsistently (McGuire's glass and water give Tf 0.1 for the clear glass of
//   Jensen's figures): so only Tf's hue is kept, t = Tf / max(Tf), applied as sqrt(t)
//   at each refraction so that light through a closed object is filtered by t once;
// - otherwise Lambert with Kd.
MtlMaterial finish(Pending& p) {
    MtlMaterial m = p.m;
    Material& mat = m.material;
    const float shininess = p.has_ns ? p.ns : 10.0f;
    const bool pbr = p.has_pr || p.has_pm || p.has_pbr_map || p.has_layers;
    // A roughness or metalness map without its number: the map alone gives it (factor 1).
    auto has_map = [&](const char* s) {
        return std::any_of(p.m.textures.begin(), p.m.textures.end(),
                           [&](const MtlTexture& t) { return t.statement == s; });
    };
    if (has_map("map_Pr") && !p.has_pr) p.pr = 1.0f, p.has_pr = true;
    if (has_map("map_Pm") && !p.pm_given) m.metallic = 1.0f;
    const bool has_ks = p.has_ks && (mat.ks[0] > 0.0f || mat.ks[1] > 0.0f || mat.ks[2] > 0.0f);
    Material base = mat;
    m.base_color = base.diffuse;
    if (m.illum == 5 && !pbr) {
        mat = make_material("conductor");
        mat.fresnel = FC_FRESNEL_SCHLICK;
        for (int c = 0; c < 3; ++c) mat.f0[c] = p.has_ks ? std::min(base.ks[c], 1.0f) : 1.0f;
        mat.alpha_x = mat.alpha_y = 0.0f;
    } else if (m.illum == 7 && !pbr) {
        mat = make_material("dielectric");
        const float tf_max = std::max({p.tf[0], p.tf[1], p.tf[2]});
        for (int c = 0; c < 3; ++c)
            mat.transmittance[c] = tf_max > 0.0f ? std::sqrt(std::clamp(p.tf[c] / tf_max, 0.0f, 1.0f)) : 1.0f;
    } else if (pbr) {
        mat = make_material("ggx");
        float alpha = p.has_pr ? std::max(p.pr * p.pr, 1e-3f) : roughness_from_shininess(shininess);
        float f0 = ((base.ior - 1.0f) / (base.ior + 1.0f)) * ((base.ior - 1.0f) / (base.ior + 1.0f));
        set_metallic_roughness(mat, base.diffuse, m.metallic, f0);
        if (mat.diffuse_model != FC_DIFFUSE_NONE) mat.diffuse_model = FC_DIFFUSE_LAMBERT;
        mat.alpha_x = mat.alpha_y = alpha;
        mat.exponent_x = mat.exponent_y = shininess_from_roughness(alpha);
        // glTF's clearcoat and sheen layers (kernels/bsdf/clearcoat.cl, sheen.cl): the MTL
        // extension gives no sheen roughness, so Blender's default, 0.5.
        mat.clearcoat = p.pc;
        mat.clearcoat_alpha = p.pcr * p.pcr;
        mat.sheen = glm::vec3(p.ps);
        mat.sheen_roughness = p.ps > 0.0f ? 0.5f : 0.0f;
        // glTF's anisotropy (kernels/bsdf/anisotropy.cl): anisor turns of a full circle.
        mat.anisotropy = p.aniso;
        mat.anisotropy_rotation = float(2.0 * std::numbers::pi * double(p.anisor));
    } else if (has_ks && m.illum >= 2) {
        mat = make_material("blinn_phong_normalized");
        mat.diffuse = base.diffuse;
        mat.ks = base.ks;
        mat.exponent_x = mat.exponent_y = shininess;
        mat.alpha_x = mat.alpha_y = roughness_from_shininess(shininess);
    } else {
        mat = make_material("lambert");
        mat.diffuse = base.diffuse;
        mat.ks = base.ks;  // as read; no lobe of Lambert's reads it
    }
    for (int c = 0; c < 3; ++c) mat.emission[c] = base.emission[c];
    mat.ior = base.ior;
    mat.two_sided_emission = base.two_sided_emission;
    // Dissolve d (or 1 - Tr without d) below 1: stochastic transparency, the surface there
    // with probability d (map_d multiplies it in bind_mtl_textures). Glass (illum 7) is
    // transparent by refraction and keeps d = 1.
    if (!p.has_d) m.dissolve = 1.0f - p.tr;
    if (m.dissolve < 1.0f && mat.specular_model != FC_SPECULAR_DIELECTRIC) {
        mat.alpha_mode = FC_ALPHA_BLEND;
        mat.alpha = m.dissolve;
    }
    return m;
}

}  // namespace

std::vector<MtlMaterial> parse_mtl(const std::string& path, std::string_view content,
                                   std::vector<std::string>& warnings) {
    std::vector<MtlMaterial> out;
    std::vector<Pending> list;
    std::set<std::string> names;  // to warn about a second definition
    const std::string dir = text::directory_of(path);
    const auto lines = text::split_lines(content);
    for (std::size_t li = 0; li < lines.size(); ++li) {
        const auto f = text::split_fields(lines[li]);
        if (f.empty()) continue;
        const MtlLine l{path, static_cast<int>(li + 1), f};
        const std::string_view kw = f[0];
        if (kw == "newmtl") {
            if (f.size() < 2) l.fail("'newmtl' without a name");
            Pending p;
            p.m.name = std::string(text::rest_after_keyword(lines[li]));
            if (!names.insert(p.m.name).second)
                warnings.push_back(fmt::format("{}:{}: material '{}' is defined again; the last definition is used",
                                               path, l.line, p.m.name));
            p.m.material = default_material();
            list.push_back(p);
            continue;
        }
        const bool known = kw == "Kd" || kw == "Ks" || kw == "Ke" || kw == "Ns" || kw == "Ni" || kw == "d" ||
                           kw == "Tr" || kw == "illum" || kw == "Pr" || kw == "Pm" || kw == "Tf" || kw == "Pc" ||
                           kw == "Pcr" || kw == "Ps" || kw == "aniso" || kw == "anisor";
        if (!known && !is_texture_statement(kw)) continue;  // Ka, ...: not used
        if (list.empty()) l.fail(fmt::format("'{}' before any 'newmtl'", kw));
        Pending& p = list.back();
        Material& mat = p.m.material;
        if (kw == "Kd") l.color(mat.diffuse);
        else if (kw == "Ks") {
            l.color(mat.ks);
            p.has_ks = true;
        } else if (kw == "Ke") l.color(mat.emission);
        else if (kw == "Tf") l.color(p.tf);
        else if (kw == "Ns") {
            p.ns = l.scalar(0.0f, 1e9f);
            p.has_ns = true;
        } else if (kw == "Ni") mat.ior = l.scalar(1e-3f, 100.0f);
        else if (kw == "d") {
            p.m.dissolve = l.scalar(0.0f, 1.0f);
            p.has_d = true;
        } else if (kw == "Tr") p.tr = l.scalar(0.0f, 1.0f);
        else if (kw == "Pr") {
            p.pr = l.scalar(0.0f, 1.0f);
            p.has_pr = true;
        } else if (kw == "Pm") {
            p.m.metallic = l.scalar(0.0f, 1.0f);
            p.pm_given = true;
        } else if (kw == "Pc" || kw == "Pcr" || kw == "Ps" || kw == "aniso" || kw == "anisor") {
            (kw == "Pc"      ? p.pc
             : kw == "Pcr"   ? p.pcr
             : kw == "Ps"    ? p.ps
             : kw == "aniso" ? p.aniso
                             : p.anisor) = l.scalar(0.0f, 1.0f);
            p.has_layers = true;
        } else if (kw == "illum") {
            const float v = l.scalar(0.0f, 10.0f);
            if (v != std::floor(v)) l.fail(fmt::format("'illum' must be an integer, got {}", v));
            p.m.illum = static_cast<int>(v);
        } else if (is_read_texture(kw)) {
            if (f.size() < 2) l.fail(fmt::format("'{}' without a file name", kw));
            p.m.textures.push_back(texture_statement(l, dir));
            if (kw == "map_Pr" || kw == "map_Pm") p.has_pbr_map = true;
        } else {
            // Texture: the file name is the last field (options such as -bm 1 come first).
            if (f.size() < 2) l.fail(fmt::format("'{}' without a file name", kw));
            const std::string file(f.back());
            std::error_code ec;
            const bool exists = std::filesystem::exists(text::join_asset_path(dir, file), ec);
            warnings.push_back(
                fmt::format("{}:{}: texture '{}' ({}) of material '{}' ignored: facet does not read '{}'{}", path,
                            l.line, file, kw, p.m.name, kw, exists ? "" : " (and the file is missing)"));
        }
    }
    out.reserve(list.size());
    for (Pending& p : list) out.push_back(finish(p));
    return out;
}

void bind_mtl_textures(const MtlMaterial& mtl, Material& m, Scene& scene) {
    MaterialTextures& b = m.textures;
    const bool pbr = m.specular_model == FC_SPECULAR_MICROFACET && m.diffuse_model == FC_DIFFUSE_LAMBERT;
    for (const MtlTexture& t : mtl.textures) {
        const std::string& s = t.statement;
        const bool normal = s == "norm" || s == "map_Bump" || s == "map_bump" || s == "bump";
        const bool data = normal || s == "map_Ns" || s == "map_Pr" || s == "map_Pm" || s == "map_d";
        const int wrap = t.clamp ? FC_WRAP_CLAMP : FC_WRAP_REPEAT;
        const int index = add_texture(scene, t.file, data ? TextureSpace::Data : TextureSpace::Color,
                                      fmt::format("material '{}' ({} at {})", mtl.name, s, t.where), wrap, wrap);
        if (index < 0) continue;  // unreadable data texture: left out with its warning
        if (s == "map_Kd") b.base_color = index;
        else if (s == "map_d") {
            // Coverage: the image's alpha channel, or its grey (R) value when it has none.
            if (m.specular_model != FC_SPECULAR_DIELECTRIC) {
                b.alpha = index;
                b.alpha_channel = scene.textures[std::size_t(index)].has_alpha ? 3 : 0;
                m.alpha_mode = FC_ALPHA_BLEND;
            }
        } else if (s == "map_Ks") b.specular = index;
        else if (s == "map_Ke") b.emission = index;
        else if (s == "map_Pr") b.roughness = index, b.roughness_mode = FC_ROUGHNESS_PERCEPTUAL;
        else if (s == "map_Pm") b.metalness = index;
        else if (s == "map_Ns") {
            if (pbr)
                scene.warnings.push_back(fmt::format(
                    "{}: map_Ns of the PBR material '{}' ignored (map_Pr gives its roughness)", t.where, mtl.name));
            else b.roughness = index, b.roughness_mode = FC_ROUGHNESS_SHININESS;
        } else if (normal) {
            // A grey image is a bump (height) map, which facet does not read; colours are a normal map.
            const TextureImage& img = scene.textures[std::size_t(index)];
            bool grey = true;
            for (std::size_t i = 0; grey && i < std::size_t(img.width) * std::size_t(img.height); ++i)
                grey = img.texels[4 * i] == img.texels[4 * i + 1] && img.texels[4 * i] == img.texels[4 * i + 2];
            if (grey)
                scene.warnings.push_back(fmt::format(
                    "{}: {} '{}' of material '{}' is a grey (height) bump map, which facet does not read; ignored",
                    t.where, s, t.file, mtl.name));
            else b.normal = index, b.normal_scale = t.bump_multiplier;
        }
        b.uv_transform = {t.scale[0], 0.0f, t.offset[0], 0.0f, t.scale[1], t.offset[1]};
    }
    if (pbr && (b.base_color >= 0 || b.metalness >= 0)) {
        b.metallic_workflow = true;
        b.base_factor = mtl.base_color;
        b.metallic_factor = mtl.metallic;
        b.dielectric_f0 = ((m.ior - 1.0f) / (m.ior + 1.0f)) * ((m.ior - 1.0f) / (m.ior + 1.0f));
    }
}

}  // namespace facet
