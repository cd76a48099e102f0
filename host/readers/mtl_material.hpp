// Wavefront MTL materials: a strict reader (every number checked, errors name the
// file and line) and the mapping of MTL parameters onto the host's Material.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// A texture statement of a material (map_Kd, norm, ...), read by bind_mtl_textures.
struct MtlTexture {
    std::string statement;  // "map_Kd", "map_Ks", "map_Ns", "map_Pr", "map_Pm", "map_Ke", "norm", "map_Bump", "bump"
    std::string file;       // resolved against the MTL file's directory
    std::string where;      // "file.mtl:LINE"
    float bump_multiplier = 1.0f;    // -bm
    bool clamp = false;              // -clamp on
    float scale[2] = {1.0f, 1.0f};   // -s u v
    float offset[2] = {0.0f, 0.0f};  // -o u v
};

struct MtlMaterial {
    std::string name;
    Material material;
    std::vector<MtlTexture> textures;
    glm::vec3 base_color{0.5f};  // Kd as read (the PBR base colour)
    // Kept as read for the models still to come; Material has no field for them yet.
    float dissolve = 1.0f;  // d (1 = opaque)
    float metallic = 0.0f;  // Pm
    int illum = 2;
};

// Parses the MTL text of `path`. Kd, Ks, Ke (emission), Ns, Ni (ior, default 1.5),
// illum and the PBR extension's Pr/Pm choose the model: GGX for Pr/Pm, normalized
// Blinn-Phong for Ks > 0 with illum >= 2, Lambert otherwise (mtl_material.cpp, finish()).
// Texture statements map_Kd, map_Ks, map_Ns, map_Pr, map_Pm, map_Ke, norm, map_Bump and
// bump are kept in MtlMaterial::textures (a map_Pr or map_Pm makes the material PBR);
// others (map_d, disp, decal, refl, ...) add a warning to `warnings` and are ignored.
// Throws facet::Error "file.mtl:LINE: ..." on malformed numbers or misplaced statements.
std::vector<MtlMaterial> parse_mtl(const std::string& path, std::string_view text, std::vector<std::string>& warnings);

// Loads the textures of `mtl` into scene.textures and binds them to `m` (its converted
// material): map_Kd the diffuse (the PBR base) colour, map_Ks the specular colour,
// map_Ns the Phong exponent (Ns x texel), map_Pr roughness, map_Pm metalness, map_Ke
// emission, norm / map_Bump / bump a tangent-space normal map (a grey image, a bump
// height map, is ignored with a warning). Throws facet::Error naming the MTL line, the
// image and the material when an image cannot be read.
void bind_mtl_textures(const MtlMaterial& mtl, Material& m, Scene& scene);

}  // namespace facet
