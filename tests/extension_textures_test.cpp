// ExtensionTextures.*: the textures of glTF's KHR_materials_clearcoat, _sheen and _specular
// (kernels/texture/extension_textures.cl) rendered through the real kernels: a quad seen
// straight down (orthographic) under a constant environment L = 1 renders its directional
// albedo, and a 16 x 1 texture splits it into a left half (u < 0.5) and a right one. A
// black base with specularFactor 0 reflects nothing, so a layer shows alone: a clearcoat
// texture of 0 | 1 coats only the right half (as the untextured coat does), a sheen colour
// texture of 0 | (1, 0.25, 0) tints only the right half; a specular texture of 0 | 1 leaves the
// left half its Lambert base (0.5) and the right one the untextured material; a white base
// under a textured coat and sheen stays white (furnace). Each fails with the textures ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "host/bvh/bvh.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

constexpr int kSize = 32;

// The quad x, z in [-1, 1] at y = 0 facing +y (u = (x + 1) / 2) of material `m`, filling the
// image of an orthographic camera looking straight down, in a constant environment of 1.
Scene quad_scene(const Material& m) {
    Scene s;
    add_material(s, m, "m");
    add_quad(s, glm::vec3(-1, 0, 1), glm::vec3(2, 0, 0), glm::vec3(0, 0, -2), 0);
    s.environment = constant_environment(glm::vec3(1.0f));
    build_lights(s);
    s.camera.eye = glm::vec3(0.0f, 5.0f, 0.0f);
    s.camera.target = glm::vec3(0.0f);
    s.camera.up = glm::vec3(0, 0, -1);  // right = +x
    s.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    s.camera.ortho_height = 2.0f;
    s.settings.width = s.settings.height = kSize;
    s.settings.max_depth = 4;
    return s;
}

// A 16 x 1 texture (clamped) of `left` on u < 0.5 and `right` on u >= 0.5 (linear RGBA).
TextureImage halves(glm::vec4 left, glm::vec4 right) {
    std::vector<float> rgba;
    for (int x = 0; x < 16; ++x) {
        const glm::vec4 v = x < 8 ? left : right;
        rgba.insert(rgba.end(), {v.x, v.y, v.z, v.w});
    }
    return make_texture(16, 1, rgba, FC_WRAP_CLAMP, FC_WRAP_CLAMP);
}

std::vector<float> render(const Scene& scene, std::uint32_t spp) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp, spp);
    return r.image();
}

struct Region {
    double mean, error;  // channel c's mean over the region and its standard error
};

// Channel c over the pixels of the left (x < -0.15) or right (x > 0.15) half, rows away from
// the edges.
Region region(const std::vector<float>& img, bool right, int c) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int j = 2; j < kSize - 2; ++j)
        for (int i = 0; i < kSize; ++i) {
            const double x = -1.0 + 2.0 * (i + 0.5) / kSize;
            if (right ? x < 0.15 : x > -0.15) continue;
            const double v = img[3 * std::size_t(j * kSize + i) + std::size_t(c)];
            sum += v, sum2 += v * v, ++n;
        }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, (sum2 - sum * mean) / (n - 1)) / n)};
}

// glTF's dielectric over base colour `base` (metallic 0, GGX alpha 0.3) under
// KHR_materials_specular's specularFactor s.
Material gltf_material(glm::vec3 base, float s) {
    Material m = make_material("ggx");
    set_metallic_roughness(m, base, 0.0f, 0.04f * s);
    m.alpha_x = m.alpha_y = 0.3f;
    m.specular_f90 = s;
    return m;
}

void expect_same(const Region& a, const Region& b, const char* what) {
    EXPECT_NEAR(a.mean, b.mean, 1e-3 + 4.0 * std::hypot(a.error, b.error)) << what;
}

TEST(ExtensionTextures, ClearcoatTextureCoatsOneHalf) {
    Material m = gltf_material(glm::vec3(0.0f), 0.0f);  // reflects nothing by itself
    m.clearcoat = 1.0f;
    m.clearcoat_alpha = 0.01f;
    const std::vector<float> plain = render(quad_scene(m), 16);
    m.textures.clearcoat = 0;
    Scene s = quad_scene(m);
    s.textures.push_back(halves(glm::vec4(0.0f, 1.0f, 1.0f, 1.0f), glm::vec4(1.0f)));  // R: 0 | 1
    const std::vector<float> img = render(s, 16);
    EXPECT_LT(region(img, false, 0).mean, 1e-4) << "the left half has no coat";
    EXPECT_GT(region(plain, true, 0).mean, 0.02) << "the coat's reflectance";
    expect_same(region(img, true, 0), region(plain, true, 0), "the right half is the untextured coat");
}

TEST(ExtensionTextures, SheenColourTextureTintsWhereSet) {
    Material m = gltf_material(glm::vec3(0.0f), 0.0f);
    m.sheen = glm::vec3(1.0f);
    m.sheen_roughness = 0.5f;
    m.textures.sheen_color = 0;
    Scene s = quad_scene(m);
    s.textures.push_back(halves(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(1.0f, 0.25f, 0.0f, 1.0f)));
    const std::vector<float> img = render(s, 16);
    for (int c = 0; c < 3; ++c) EXPECT_LT(region(img, false, c).mean, 1e-4) << "left half, channel " << c;
    const Region r = region(img, true, 0), g = region(img, true, 1);
    EXPECT_GT(r.mean, 0.01) << "the sheen on the right half";
    EXPECT_NEAR(g.mean, 0.25 * r.mean, 1e-3 + 4.0 * (g.error + 0.25 * r.error)) << "tinted (1, 0.25, 0)";
    EXPECT_LT(region(img, true, 2).mean, 1e-4);
}

// specularTexture's A of 0 removes the specular lobe: the left half renders the Lambert base
// (albedo 0.5, as a diffuse-only material does); A = 1 keeps the untextured material (0.5 + 0.5
// E_s(1), about 0.52).
TEST(ExtensionTextures, SpecularTextureZeroLeavesTheDiffuseBase) {
    Material m = gltf_material(glm::vec3(0.5f), 1.0f);
    const std::vector<float> plain = render(quad_scene(m), 16);
    Material lambert = make_material("lambert");
    lambert.diffuse = glm::vec3(0.5f);
    const std::vector<float> diffuse = render(quad_scene(lambert), 16);
    m.textures.specular_extension = true;
    m.textures.specular_strength = 0;
    m.textures.specular_color_f0 = glm::vec3(0.04f);
    m.textures.specular_weight = 1.0f;
    Scene s = quad_scene(m);
    s.textures.push_back(halves(glm::vec4(1.0f, 1.0f, 1.0f, 0.0f), glm::vec4(1.0f)));  // A: 0 | 1
    const std::vector<float> img = render(s, 16);
    for (int c = 0; c < 3; ++c) {
        expect_same(region(img, false, c), region(diffuse, false, c), "the left half is the diffuse-only material");
        expect_same(region(img, true, c), region(plain, true, c), "the right half is the untextured material");
    }
    EXPECT_GT(region(plain, true, 0).mean - region(diffuse, true, 0).mean, 0.01) << "the specular lobe's share";
}

// A white base under a coat and a sheen whose weight, roughness and colour are textured (and a
// textured specular) reflects everything: the image is L = 1 within 1 %.
TEST(ExtensionTextures, FurnaceHoldsWithTexturedLayers) {
    Material m = gltf_material(glm::vec3(1.0f), 0.6f);
    m.clearcoat = 1.0f;
    m.clearcoat_alpha = 0.25f;
    m.sheen = glm::vec3(1.0f);
    m.sheen_roughness = 0.6f;
    m.textures.clearcoat = m.textures.clearcoat_roughness = m.textures.sheen_color = m.textures.sheen_roughness = 0;
    m.textures.specular_extension = true;
    m.textures.specular_strength = 0;
    m.textures.specular_color_f0 = glm::vec3(0.04f);
    m.textures.specular_weight = 0.6f;
    Scene s = quad_scene(m);
    // grey (a coloured sheen over white is not white) and A for the sheen's roughness and specular
    s.textures.push_back(halves(glm::vec4(0.3f, 0.3f, 0.3f, 0.5f), glm::vec4(0.9f, 0.9f, 0.9f, 0.9f)));
    const std::vector<float> img = render(s, 32);
    for (bool right : {false, true})
        for (int c = 0; c < 3; ++c) {
            const Region r = region(img, right, c);
            EXPECT_NEAR(r.mean, 1.0, 0.01 + 4.0 * r.error) << (right ? "right" : "left") << " half, channel " << c;
        }
}

// Khronos's ClearCoatTest (Debian's assimp-testmodels; skipped without it): the glTF reader binds
// its clearcoat, clearcoat roughness and clearcoat normal textures and warns about none of them.
TEST(ExtensionTextures, ClearCoatTestBindsItsTextures) {
    const std::string file = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is missing (Debian's assimp-testmodels)";
    const Scene s = load_scene(file);
    auto material = [&](const std::string& name) -> const Material& {
        for (std::size_t i = 0; i < s.material_names.size(); ++i)
            if (s.material_names[i] == name) return s.materials[i];
        ADD_FAILURE() << "no material " << name;
        return s.materials.at(0);
    };
    EXPECT_GE(material("Partial_Coated").textures.clearcoat, 0);
    EXPECT_GE(material("RoughVariations_Coated").textures.clearcoat_roughness, 0);
    EXPECT_GE(material("CoatNorm_Coated").textures.clearcoat_normal, 0);
    EXPECT_LT(material("Simple_Coated").textures.clearcoat, 0);
    for (const std::string& w : s.warnings) {
        EXPECT_EQ(w.find("clearcoatTexture"), std::string::npos) << w;
        EXPECT_EQ(w.find("clearcoatRoughnessTexture"), std::string::npos) << w;
        EXPECT_EQ(w.find("clearcoatNormalTexture"), std::string::npos) << w;
    }
}

}  // namespace
}  // namespace facet
