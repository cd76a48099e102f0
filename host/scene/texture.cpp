#include "host/scene/texture.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/film/image_io.hpp"
#include "host/scene/scene.hpp"

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

TextureImage load_texture(const std::string& path, TextureSpace space, const std::string& owner) {
    ImageRGB img;
    try {
        img = read_image(path);
    } catch (const Error& e) {
        throw Error(fmt::format("texture of {}: {}", owner, e.what()));
    }
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
        rgba[4 * i + 3] = 1.0f;
    }
    TextureImage t = make_texture(img.width, img.height, std::move(rgba));
    t.path = path;
    t.space = space;
    return t;
}

int add_texture(Scene& scene, const std::string& path, TextureSpace space, const std::string& owner, int wrap_u,
                int wrap_v) {
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const TextureImage& t = scene.textures[i];
        if (t.path == path && t.space == space && t.wrap_u == wrap_u && t.wrap_v == wrap_v) return int(i);
    }
    TextureImage t = load_texture(path, space, owner);
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
    d.flags = t.metallic_workflow ? FC_TEX_METALLIC_WORKFLOW : 0u;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) d.uv_transform[r][c] = t.uv_transform[std::size_t(3 * r + c)];
    return d;
}

DeviceTextures compile_textures(const Scene& scene) {
    DeviceTextures d;
    // One binding a material even without textures: the generic program reads them.
    for (const Material& m : scene.materials) d.materials.push_back(device_material_textures(m.textures));
    if (d.materials.empty()) d.materials.push_back(device_material_textures(MaterialTextures{}));
    if (!scene_uses_textures(scene)) {
        for (FcMaterialTextures& m : d.materials) m = device_material_textures(MaterialTextures{});
        d.table.push_back(FcTexture{});
        d.texels.assign(4, 0.0f);
        d.texcoords.push_back(FcTriTexcoords{});
        return d;
    }
    for (const TextureImage& t : scene.textures) {
        FcTexture e{};
        if (d.texels.size() / 4u > 0xffffffffull - t.texels.size() / 4u)
            throw Error(fmt::format("textures: more than 2^32 texels in all (at {})", t.path));
        e.offset = std::uint32_t(d.texels.size() / 4u);
        e.width = t.width;
        e.height = t.height;
        e.levels = t.levels;
        e.wrap_u = t.wrap_u;
        e.wrap_v = t.wrap_v;
        d.table.push_back(e);
        d.texels.insert(d.texels.end(), t.texels.begin(), t.texels.end());
    }
    d.texcoords = scene.texcoords;
    d.texcoords.resize(scene.shading.size(), FcTriTexcoords{});
    for (const FcLight& l : scene.lights) {
        if (l.type != FC_LIGHT_AREA_TRIANGLE) continue;
        const std::size_t t = std::size_t(l.prim);
        const glm::vec3 e1 = scene.vertices[3 * t + 1] - scene.vertices[3 * t];
        d.texcoords[t].light_swapped = !(l.e1[0] == e1.x && l.e1[1] == e1.y && l.e1[2] == e1.z);
    }
    return d;
}

}  // namespace facet
