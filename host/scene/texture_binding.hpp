// The textures a material binds (docs/textures.md): indices into Scene::textures and the
// factors they multiply, as the readers (JSON, MTL, glTF) fill them. Compiled into the
// kernels' FcMaterialTextures (kernels/shared/texture_layout.h) by host/scene/texture.cpp.
#pragma once

#include <array>

#include <glm/vec3.hpp>

#include "kernels/shared/texture_layout.h"

namespace facet {

struct MaterialTextures {
    int base_color = -1;  // diffuse colour, or the metallic workflow's base colour (sRGB)
    int specular = -1;    // the specular lobe's colour: F0, Ks or the dielectric's tint (sRGB)
    int roughness = -1;   // linear: perceptual roughness, or a Phong exponent scale (roughness_mode)
    int metalness = -1;   // linear; the metallic workflow only
    int emission = -1;    // sRGB; multiplies the material's emission
    int normal = -1;      // linear, tangent space
    int alpha = -1;       // linear coverage (Material::alpha_mode): channel alpha_channel (3: A, 0: R)
    int alpha_channel = 3;
    int roughness_channel = 0;
    int metal_channel = 0;
    int roughness_mode = FC_ROUGHNESS_PERCEPTUAL;
    // glTF's metallic-roughness workflow: diffuse = base (1 - metal), F0 = mix(dielectric_f0, base, metal).
    bool metallic_workflow = false;
    glm::vec3 base_factor{1.0f};
    float metallic_factor = 0.0f;
    float dielectric_f0 = 0.04f;
    float normal_scale = 1.0f;
    // KHR_texture_transform: u' = t[0] u + t[1] v + t[2], v' = t[3] u + t[4] v + t[5].
    std::array<float, 6> uv_transform{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f};
    // glTF's KHR_materials_* textures (kernels/texture/extension_textures.cl), each multiplying
    // the material's factor: the coat's weight (R) and perceptual roughness (G), the sheen's
    // colour (RGB, sRGB) and roughness (A).
    int clearcoat = -1;
    int clearcoat_roughness = -1;
    int clearcoat_normal = -1;  // the coat's own tangent-space normal map (linear), x, y scaled:
    float clearcoat_normal_scale = 1.0f;
    int sheen_color = -1;
    int sheen_roughness = -1;
    // KHR_materials_specular per hit (specular_extension): the dielectric's F0 =
    // min(specular_color_f0 x specular_color's RGB, 1) x specular_weight x specular_strength's A,
    // its F90 = the material's specular_f90 x A.
    bool specular_extension = false;
    int specular_strength = -1;  // linear, A
    int specular_color = -1;     // sRGB
    glm::vec3 specular_color_f0{0.04f};
    float specular_weight = 1.0f;

    // Whether the layers' and KHR_materials_specular's textures are bound (or the specular per hit).
    bool any_clearcoat() const { return clearcoat >= 0 || clearcoat_roughness >= 0 || clearcoat_normal >= 0; }
    bool any_sheen() const { return sheen_color >= 0 || sheen_roughness >= 0; }
    bool any() const {
        return base_color >= 0 || specular >= 0 || roughness >= 0 || metalness >= 0 || emission >= 0 || normal >= 0 ||
               alpha >= 0 || any_clearcoat() || any_sheen() || specular_extension;
    }
};

}  // namespace facet
