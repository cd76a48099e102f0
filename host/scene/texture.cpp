#include "host/scene/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>
#include <glm/gtc/packing.hpp>
#include <glm/vec4.hpp>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture_tangents.hpp"

namespace facet {
namespace {

// sRGB encoding (IEC 61966-2-1), the inverse of read_image's decoding of integer images.
float srgb_encode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// The next level of a pyramid: each texel the mean of the 2x2 (or, at an odd size, up
// to 3x3 edge) block of the level above it covers.
std::vector<float> half_level(const float* src, int w, int h, int nw, int nh) {
    std::vector<float> out(std::size_t(nw) * std::size_t(nh) * 4u, 0.0f);
    for (int y = 0; y < nh; ++y) {
        const int y0 = h == 1 ? 0 : 2 * y, y1 = h == 1 ? 0 : (y == nh - 1 ? h - 1 : 2 * y + 1);
        for (int x = 0; x < nw; ++x) {
            const int x0 = w == 1 ? 0 : 2 * x, x1 = w == 1 ? 0 : (x == nw - 1 ? w - 1 : 2 * x + 1);
            float* o = &out[(std::size_t(y) * nw + x) * 4u];
            const float n = float((y1 - y0 + 1) * (x1 - x0 + 1));
            for (int sy = y0; sy <= y1; ++sy)
                for (int sx = x0; sx <= x1; ++sx)
                    for (int c = 0; c < 4; ++c) o[c] += src[(std::size_t(sy) * w + sx) * 4u + c] / n;
        }
    }
    return out;
}

// The sRGB transfer function's inverse, as read_image decodes integer images.
float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::uint32_t unorm8(float v) { return std::uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// Appends texel `rgba` to the pool in `format` (kernels/shared/texture_layout.h).
void append_texel(std::vector<std::uint32_t>& pool, int format, const float* rgba) {
    switch (format) {
        case FC_TEXEL_RGBA8_SRGB:
            pool.push_back(unorm8(srgb_encode(rgba[0])) | unorm8(srgb_encode(rgba[1])) << 8 |
                           unorm8(srgb_encode(rgba[2])) << 16 | unorm8(rgba[3]) << 24);
            break;
        case FC_TEXEL_RGBA8:
            pool.push_back(unorm8(rgba[0]) | unorm8(rgba[1]) << 8 | unorm8(rgba[2]) << 16 | unorm8(rgba[3]) << 24);
            break;
        case FC_TEXEL_RGBA16F: {
            const std::uint64_t h = glm::packHalf4x16(glm::vec4(rgba[0], rgba[1], rgba[2], rgba[3]));
            pool.push_back(std::uint32_t(h));
            pool.push_back(std::uint32_t(h >> 32));
            break;
        }
        default:
            for (int c = 0; c < 4; ++c) {
                std::uint32_t bits;
                std::memcpy(&bits, &rgba[c], sizeof bits);
                pool.push_back(bits);
            }
    }
}

std::uint32_t texel_words(int format) { return format == FC_TEXEL_RGBA32F ? 4u : format == FC_TEXEL_RGBA16F ? 2u : 1u; }

}  // namespace

TextureImage make_texture(int width, int height, std::vector<float> rgba, int wrap_u, int wrap_v) {
    if (width < 1 || height < 1 || rgba.size() != std::size_t(width) * std::size_t(height) * 4u)
        throw Error(fmt::format("texture of {}x{} texels with {} values", width, height, rgba.size()));
    TextureImage t;
    t.width = width;
    t.height = height;
    t.wrap_u = wrap_u;
    t.wrap_v = wrap_v;
    t.texels = std::move(rgba);
    t.levels = 1;
    std::size_t at = 0;
    for (int w = width, h = height; w > 1 || h > 1; ++t.levels) {
        const int nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
        std::vector<float> next = half_level(&t.texels[at], w, h, nw, nh);
        at += std::size_t(w) * std::size_t(h) * 4u;
        t.texels.insert(t.texels.end(), next.begin(), next.end());
        w = nw;
        h = nh;
    }
    return t;
}

namespace {

// The texture of a decoded image (`path` names it in messages).
TextureImage texture_from_image(const ImageRGB& img, const std::string& path, TextureSpace space,
                                const std::string& owner) {
    std::vector<float> rgba(std::size_t(img.width) * std::size_t(img.height) * 4u);
    for (std::size_t i = 0; i < std::size_t(img.width) * std::size_t(img.height); ++i) {
        for (int c = 0; c < 3; ++c) {
            float v = img.rgb[3 * i + std::size_t(c)];
            // Data in an integer file is stored as is: undo read_image's sRGB decoding.
            if (space == TextureSpace::Data && img.decoded_srgb) v = srgb_encode(v);
            if (!std::isfinite(v))
                throw Error(fmt::format("texture of {}: {}: texel {} is not finite", owner, path, i));
            rgba[4 * i + std::size_t(c)] = v;
        }
        // Alpha as stored (unassociated, linear), 1 where the file has none.
        const float a = img.alpha.empty() ? 1.0f : img.alpha[i];
        if (!std::isfinite(a))
            throw Error(fmt::format("texture of {}: {}: texel {}'s alpha is not finite", owner, path, i));
        rgba[4 * i + 3] = std::clamp(a, 0.0f, 1.0f);
    }
    TextureImage t = make_texture(img.width, img.height, std::move(rgba));
    t.has_alpha = !img.alpha.empty();
    t.path = path;
    t.space = space;
    // As precise as the file: sRGB bytes decoded on the device, 16 bits as half floats.
    if (img.bits == 8)
        t.format = img.decoded_srgb && space == TextureSpace::Color ? FC_TEXEL_RGBA8_SRGB : FC_TEXEL_RGBA8;
    else if (img.bits == 16) t.format = FC_TEXEL_RGBA16F;
    if (img.bits == 8 || img.bits == 16) t.mip_format = FC_TEXEL_RGBA16F;  // averages of 8 bits kept to 11
    return t;
}

}  // namespace

TextureImage load_texture(const std::string& path, TextureSpace space, const std::string& owner) {
    ImageRGB img;
    try {
        img = read_image(path);
    } catch (const Error& e) {
        throw Error(fmt::format("texture of {}: {}", owner, e.what()));
    }
    return texture_from_image(img, path, space, owner);
}

TextureImage missing_texture() {
    constexpr int kSize = 8, kCheck = 2;  // 4 x 4 checks over the uv square
    std::vector<float> rgba(kSize * kSize * 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float on = ((x / kCheck + y / kCheck) % 2 == 0) ? 1.0f : 0.0f;
            float* t = &rgba[std::size_t(y * kSize + x) * 4u];
            t[0] = on, t[1] = 0.0f, t[2] = on, t[3] = 1.0f;
        }
    return make_texture(kSize, kSize, std::move(rgba));
}

TextureImage load_texture_bytes(const void* data, std::size_t size, const std::string& ext, TextureSpace space,
                                const std::string& owner) {
    if (size == 0) throw Error(fmt::format("texture of {}: the image has no data", owner));
    // Decoded from memory (OpenImageIO's IOMemReader): no temporary file to leave behind on a
    // signal, and no $TMPDIR needed. The name's extension tells the format.
    const std::string name = "embedded image" + ext;
    ImageRGB img;
    try {
        img = read_image_bytes(name, std::string(static_cast<const char*>(data), size));
    } catch (const Error& e) {
        throw Error(fmt::format("texture of {}: {}", owner, e.what()));
    }
    TextureImage t = texture_from_image(img, name, space, owner);
    t.path.clear();
    return t;
}

int add_texture(Scene& scene, const std::string& path, TextureSpace space, const std::string& owner, int wrap_u,
                int wrap_v) {
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const TextureImage& t = scene.textures[i];
        if (t.path == path && t.space == space && t.wrap_u == wrap_u && t.wrap_v == wrap_v) return int(i);
    }
    TextureImage t;
    try {
        t = load_texture(path, space, owner);
    } catch (const Error& e) {
        if (scene.strict_assets) throw Error(fmt::format("{} (--strict: a missing asset is an error)", e.what()));
        if (space == TextureSpace::Data) {  // a checker would be noise as roughness or normals
            scene.warnings.push_back(fmt::format("{}; the texture is left out", e.what()));
            return -1;
        }
        scene.warnings.push_back(fmt::format("{}; rendered as a magenta and black checker in its place", e.what()));
        t = missing_texture();
        t.path = path;  // found again by the loop above: one warning per file
        t.space = space;
    }
    t.wrap_u = wrap_u;
    t.wrap_v = wrap_v;
    scene.textures.push_back(std::move(t));
    return int(scene.textures.size() - 1);
}

void set_triangle_texcoords(Scene& scene, std::size_t tri, glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2) {
    if (scene.texcoords.size() < scene.shading.size()) scene.texcoords.resize(scene.shading.size(), FcTriTexcoords{});
    FcTriTexcoords& t = scene.texcoords.at(tri);
    const glm::vec2 uv[3] = {uv0, uv1, uv2};
    for (int v = 0; v < 3; ++v) {
        t.uv[v][0] = uv[v].x;
        t.uv[v][1] = uv[v].y;
    }
}

bool scene_uses_textures(const Scene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    mark_triangle_materials(scene, used);
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (used[i] && scene.materials[i].textures.any()) return true;
    return false;
}

bool scene_uses_texcoords(const Scene& scene) {
    if (scene_uses_textures(scene)) return true;
    std::vector<bool> used(scene.materials.size(), false);
    mark_triangle_materials(scene, used);
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (used[i] && material_is_anisotropic(scene.materials[i])) return true;
    return false;
}

FcMaterialTextures device_material_textures(const MaterialTextures& t) {
    FcMaterialTextures d{};
    d.base_color = t.base_color;
    d.specular = t.specular;
    d.roughness = t.roughness;
    d.metalness = t.metalness;
    d.emission = t.emission;
    d.normal = t.normal;
    d.roughness_channel = t.roughness_channel;
    d.metal_channel = t.metal_channel;
    for (int c = 0; c < 3; ++c) d.base_factor[c] = t.base_factor[c];
    d.metallic_factor = t.metallic_factor;
    d.roughness_mode = t.roughness_mode;
    d.normal_scale = t.normal_scale;
    d.dielectric_f0 = t.dielectric_f0;
    d.flags =
        (t.metallic_workflow ? FC_TEX_METALLIC_WORKFLOW : 0u) | (t.specular_extension ? FC_TEX_SPECULAR_EXTENSION : 0u);
    d.clearcoat = t.clearcoat;
    d.clearcoat_roughness = t.clearcoat_roughness;
    d.clearcoat_normal = t.clearcoat_normal;
    d.sheen_color = t.sheen_color;
    d.sheen_roughness = t.sheen_roughness;
    d.specular_strength = t.specular_strength;
    d.specular_color = t.specular_color;
    d.clearcoat_normal_scale = t.clearcoat_normal_scale;
    for (int c = 0; c < 3; ++c) d.specular_color_f0[c] = t.specular_color_f0[c];
    d.specular_weight = t.specular_weight;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) d.uv_transform[r][c] = t.uv_transform[std::size_t(3 * r + c)];
    return d;
}

namespace {

// The world triangles' uvs and tangents, and which area lights' corners run the other way.
std::vector<FcTriTexcoords> triangle_texcoords(const Scene& scene) {
    std::vector<FcTriTexcoords> tc = scene.texcoords;
    tc.resize(scene.shading.size(), FcTriTexcoords{});
    compute_tangents(scene, tc);
    for (const FcLight& l : scene.lights) {
        if (l.type != FC_LIGHT_AREA_TRIANGLE) continue;
        const std::size_t t = std::size_t(l.prim);
        const glm::vec3 e1 = scene.vertices[3 * t + 1] - scene.vertices[3 * t];
        tc[t].light_swapped = !(l.e1[0] == e1.x && l.e1[1] == e1.y && l.e1[2] == e1.z);
    }
    return tc;
}

}  // namespace

DeviceTextures compile_textures(const Scene& scene) {
    DeviceTextures d;
    // One binding a material even without textures: the generic program reads them.
    for (const Material& m : scene.materials) d.materials.push_back(device_material_textures(m.textures));
    if (d.materials.empty()) d.materials.push_back(device_material_textures(MaterialTextures{}));
    if (!scene_uses_textures(scene)) {
        for (FcMaterialTextures& m : d.materials) m = device_material_textures(MaterialTextures{});
        d.table.push_back(FcTexture{});
        d.texels.assign(4, 0u);
        if (scene_uses_texcoords(scene)) d.texcoords = triangle_texcoords(scene);  // anisotropic: the tangents
        else d.texcoords.push_back(FcTriTexcoords{});
        return d;
    }
    for (std::uint32_t k = 0; k < FC_SRGB_TABLE_WORDS; ++k) {
        const float linear = srgb_decode(float(k) / 255.0f);
        std::uint32_t bits;
        std::memcpy(&bits, &linear, sizeof bits);
        d.texels.push_back(bits);
    }
    for (const TextureImage& t : scene.textures) {
        FcTexture e{};
        const std::size_t level0 = std::size_t(t.width) * std::size_t(t.height);
        const std::uint64_t words =
            level0 * texel_words(t.format) + (t.texels.size() / 4u - level0) * texel_words(t.mip_format);
        if (words > 0xffffffffull || d.texels.size() > 0xffffffffull - words)
            throw Error(fmt::format("textures: more than 16 GiB of texels in all (at {})", t.path));
        e.offset = std::uint32_t(d.texels.size());
        e.width = t.width;
        e.height = t.height;
        e.levels = t.levels;
        e.wrap_u = t.wrap_u;
        e.wrap_v = t.wrap_v;
        e.format = t.format;
        e.mip_format = t.mip_format;
        d.table.push_back(e);
        d.texels.reserve(d.texels.size() + words);
        for (std::size_t i = 0; i + 3 < t.texels.size(); i += 4)
            append_texel(d.texels, i < 4u * level0 ? t.format : t.mip_format, &t.texels[i]);
    }
    d.texcoords = triangle_texcoords(scene);
    return d;
}

}  // namespace facet
