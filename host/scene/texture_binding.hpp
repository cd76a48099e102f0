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

    bool any() const {
        return base_color >= 0 || specular >= 0 || roughness >= 0 || metalness >= 0 || emission >= 0 || normal >= 0 ||
               alpha >= 0;
    }
};

}  // namespace facet
