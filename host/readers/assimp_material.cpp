#include "host/readers/assimp_material.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <assimp/material.h>
#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/text_parse.hpp"
#include "host/scene/texture.hpp"

namespace facet {
namespace {

// A colour key, clamped to finite non-negative values; nullopt when absent.
bool colour(const aiMaterial& m, const char* key, unsigned type, unsigned index, glm::vec3& out) {
    aiColor4D c;
    if (m.Get(key, type, index, c) != AI_SUCCESS) return false;
    for (int i = 0; i < 3; ++i) {
        const float v = i == 0 ? c.r : i == 1 ? c.g : c.b;
        out[i] = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f;
    }
    return true;
}

bool number(const aiMaterial& m, const char* key, unsigned type, unsigned index, float& out) {
    ai_real v = 0;
    if (m.Get(key, type, index, v) != AI_SUCCESS || !std::isfinite(float(v))) return false;
    out = float(v);
    return true;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The image file a texture names: as written (backslashes read as separators,
// docs/scene-format.md), else its bare name in the model's folder (exporters write the
// absolute path of the machine they ran on, "D:\projects\wood.png"), matched without
// regard to case (3DS files name "TEST.PNG" for test.png). When none exists, the bare name
// in the model's folder (a path of another machine says nothing here).
std::string texture_file(const std::string& dir, const std::string& name) {
    const std::string joined = text::join_asset_path(dir, name);
    std::error_code ec;
    if (std::filesystem::exists(joined, ec)) return joined;
    std::string slashed = name;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    const std::string bare = std::filesystem::path(slashed).filename().string();
    if (bare.empty()) return joined;
    const std::string beside = text::join_path(dir, bare);
    if (std::filesystem::exists(beside, ec)) return beside;
    std::size_t looked = 0;  // a bounded look through the folder
    for (auto it = std::filesystem::directory_iterator(dir.empty() ? "." : dir, ec);
         !ec && it != std::filesystem::directory_iterator() && looked < 10000; it.increment(ec), ++looked)
        if (lower(it->path().filename().string()) == lower(bare))
            return text::join_path(dir, it->path().filename().string());
    const bool foreign = slashed.size() > 1 && slashed[1] == ':';
    return foreign ? beside : joined;
}

// The texture of `type` (its first), loaded into scene.textures; -1 without one.
int texture(const aiScene& ai, const aiMaterial& m, aiTextureType type, TextureSpace space, const std::string& file,
            const std::string& owner, Scene& scene, std::set<std::string>& ignored) {
    if (m.GetTextureCount(type) == 0) return -1;
    aiString name;
    if (m.GetTexture(type, 0, &name) != AI_SUCCESS || name.length == 0) return -1;
    const std::string written(name.C_Str());
    if (const aiTexture* embedded = ai.GetEmbeddedTexture(name.C_Str())) {
        const std::string key = fmt::format("{}#{}", file, written);
        for (std::size_t i = 0; i < scene.textures.size(); ++i)
            if (scene.textures[i].path == key && scene.textures[i].space == space) return int(i);
        if (embedded->mHeight != 0 || !embedded->pcData) {  // raw texels: not read
            ignored.insert("embedded images stored as raw texels (not as an image file)");
            return -1;
        }
        std::string hint(embedded->achFormatHint);
        const std::string ext = hint.empty() ? ".png" : "." + hint;
        TextureImage t = load_texture_bytes(embedded->pcData, embedded->mWidth, ext, space, owner);
        t.path = key;
        scene.textures.push_back(std::move(t));
        return int(scene.textures.size() - 1);
    }
    return add_texture(scene, texture_file(text::directory_of(file), written), space, owner);
}

}  // namespace

Material assimp_material(const aiScene& ai, unsigned index, const std::string& file, Scene& scene,
                         std::set<std::string>& ignored) {
    const aiMaterial& m = *ai.mMaterials[index];
    aiString ai_name;
    const std::string name = m.Get(AI_MATKEY_NAME, ai_name) == AI_SUCCESS && ai_name.length > 0
                                 ? std::string(ai_name.C_Str())
                                 : fmt::format("#{}", index);
    glm::vec3 diffuse{0.8f}, specular{0.0f}, emission{0.0f};
    colour(m, AI_MATKEY_COLOR_DIFFUSE, diffuse);
    const bool has_base = colour(m, AI_MATKEY_BASE_COLOR, diffuse);
    const bool has_specular = colour(m, AI_MATKEY_COLOR_SPECULAR, specular);
    colour(m, AI_MATKEY_COLOR_EMISSIVE, emission);
    float shininess = 0.0f, metallic = 0.0f, roughness = 1.0f, opacity = 1.0f, emissive_scale = 1.0f;
    number(m, AI_MATKEY_SHININESS, shininess);
    const bool has_metallic = number(m, AI_MATKEY_METALLIC_FACTOR, metallic);
    const bool has_roughness = number(m, AI_MATKEY_ROUGHNESS_FACTOR, roughness);
    if (number(m, AI_MATKEY_EMISSIVE_INTENSITY, emissive_scale)) emission *= std::max(emissive_scale, 0.0f);
    if (number(m, AI_MATKEY_OPACITY, opacity) && opacity < 1.0f) ignored.insert("opacity (rendered opaque)");
    for (int c = 0; c < 3; ++c) diffuse[c] = std::min(diffuse[c], 1.0f);

    if (name == AI_DEFAULT_MATERIAL_NAME) return default_material();  // Assimp's, for a file without materials
    Material mat;
    const bool pbr = has_metallic || has_roughness || has_base;
    const bool phong = has_specular && std::max({specular.x, specular.y, specular.z}) > 0.0f && shininess > 0.0f;
    if (pbr) {
        mat = make_material("ggx");
        const float alpha = std::max(std::clamp(roughness, 0.0f, 1.0f) * std::clamp(roughness, 0.0f, 1.0f), 1e-3f);
        set_metallic_roughness(mat, diffuse, std::clamp(metallic, 0.0f, 1.0f), 0.04f);
        mat.alpha_x = mat.alpha_y = alpha;
        mat.exponent_x = mat.exponent_y = shininess_from_roughness(alpha);
    } else if (phong) {
        mat = make_material("blinn_phong_normalized");
        mat.diffuse = diffuse;
        for (int c = 0; c < 3; ++c) mat.ks[c] = std::min(specular[c], 1.0f);
        mat.exponent_x = mat.exponent_y = std::min(shininess, 1e6f);
        mat.alpha_x = mat.alpha_y = roughness_from_shininess(mat.exponent_x);
    } else {
        mat = make_material("lambert");
        mat.diffuse = diffuse;
    }
    mat.emission = emission;

    // Textures
    MaterialTextures& b = mat.textures;
    const std::string where = fmt::format("material '{}' of {}", name, file);
    const aiTextureType colour_map =
        m.GetTextureCount(aiTextureType_BASE_COLOR) > 0 ? aiTextureType_BASE_COLOR : aiTextureType_DIFFUSE;
    b.base_color = texture(ai, m, colour_map, TextureSpace::Color, file, where + " (diffuse)", scene, ignored);
    b.emission =
        texture(ai, m, aiTextureType_EMISSIVE, TextureSpace::Color, file, where + " (emissive)", scene, ignored);
    if (b.emission >= 0 && std::max({mat.emission.x, mat.emission.y, mat.emission.z}) <= 0.0f)
        mat.emission = glm::vec3(1.0f);  // the map alone gives the emission
    b.normal = texture(ai, m, aiTextureType_NORMALS, TextureSpace::Data, file, where + " (normal map)", scene, ignored);
    if (pbr && b.base_color >= 0) {
        b.metallic_workflow = true;
        b.base_factor = diffuse;
        b.metallic_factor = std::clamp(metallic, 0.0f, 1.0f);
        b.dielectric_f0 = 0.04f;
    }
    for (aiTextureType t :
         {aiTextureType_SPECULAR, aiTextureType_AMBIENT, aiTextureType_HEIGHT, aiTextureType_SHININESS,
          aiTextureType_OPACITY, aiTextureType_DISPLACEMENT, aiTextureType_LIGHTMAP, aiTextureType_REFLECTION,
          aiTextureType_METALNESS, aiTextureType_DIFFUSE_ROUGHNESS, aiTextureType_AMBIENT_OCCLUSION})
        if (m.GetTextureCount(t) > 0) ignored.insert(fmt::format("{} textures", aiTextureTypeToString(t)));
    return mat;
}

}  // namespace facet
