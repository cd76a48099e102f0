/* Image textures (docs/textures.md): one texel pool, a table of textures into it, the
 * textures bound to each material, and each triangle's texture coordinates.
 *
 * The pool holds linear RGBA float texels (float4): colour textures were decoded from
 * sRGB on the host, data textures (roughness, metalness, normal maps) are stored as
 * the file gives them. A texture is a box-filtered mip pyramid: level 0 of width x
 * height texels, top row first, then each level of max(1, w/2) x max(1, h/2) texels
 * until 1 x 1, all from `offset` in the pool. Texel (x, y) of a level covers
 * [x/w, (x+1)/w) x [y/h, (y+1)/h) of the (u, v) square; v = 0 is the image's top row
 * (glTF's and facet's convention; OBJ/MTL's v runs upward and its reader flips it). */
#ifndef FACET_SHARED_TEXTURE_LAYOUT_H
#define FACET_SHARED_TEXTURE_LAYOUT_H

#include "kernels/shared/types.h"

/* Wrap modes (FcTexture.wrap_u / wrap_v), as glTF's samplers name them. */
#define FC_WRAP_REPEAT 0
#define FC_WRAP_CLAMP 1
#define FC_WRAP_MIRROR 2

/* A texture of the pool. */
typedef struct FcTexture {
    fc_uint offset; /* first texel of level 0, in float4s */
    fc_int width;
    fc_int height;
    fc_int levels; /* mip levels, >= 1 */
    fc_int wrap_u;
    fc_int wrap_v;
    fc_int pad0[2];
} FcTexture;

/* How a material's roughness texture is read (FcMaterialTextures.roughness_mode). */
#define FC_ROUGHNESS_PERCEPTUAL 0 /* r = texel; alpha_x, alpha_y scaled by r^2 (glTF, map_Pr) */
#define FC_ROUGHNESS_SHININESS 1  /* Phong exponent = Ns x texel, alpha from it (MTL map_Ns) */

/* Material texture flags (FcMaterialTextures.flags). */
/* glTF's metallic-roughness workflow: base colour B and metalness M give diffuse
 * B (1 - M) and F0 = mix(dielectric_f0, B, M), as host/readers/gltf_material.cpp does
 * for the factors. Without it the base colour texture scales `diffuse` and the
 * specular texture scales `specular`. */
#define FC_TEX_METALLIC_WORKFLOW 1u

/* The textures of one material (indexed like FcMaterial), -1 where none. A texture
 * multiplies the parameter's factor: the material's own value, or base_factor /
 * metallic_factor in the metallic workflow. Channels: base colour, specular and
 * emission RGB; roughness reads channel roughness_channel (glTF: 1 = G), metalness
 * metal_channel (glTF: 2 = B). The normal map is in tangent space (RGB = (n + 1) / 2),
 * its x and y scaled by normal_scale. Every lookup uses uv' = uv_transform x (u, v, 1)
 * (two rows of a 2x3 affine matrix, KHR_texture_transform). */
typedef struct FcMaterialTextures {
    fc_int base_color;
    fc_int specular;
    fc_int roughness;
    fc_int metalness;
    fc_int emission;
    fc_int normal;
    fc_int roughness_channel;
    fc_int metal_channel;
    float base_factor[3];
    float metallic_factor;
    fc_int roughness_mode;
    float normal_scale;
    float dielectric_f0;
    fc_uint flags;
    float uv_transform[2][4]; /* rows (a, b, c, unused): u' = a u + b v + c */
} FcMaterialTextures;

/* Texture coordinates of one triangle's vertices (indexed like FcTriShading).
 * light_swapped is 1 when the triangle's area light (FcLight) has its edges swapped
 * (e1 = v2 - v0), so that a light sample's barycentrics find the right uv. */
typedef struct FcTriTexcoords {
    float uv[3][2];
    fc_int light_swapped;
    fc_int pad0;
} FcTriTexcoords;

FC_STATIC_ASSERT(sizeof(FcTexture) == 32, "FcTexture is 32 bytes");
FC_STATIC_ASSERT(sizeof(FcMaterialTextures) == 96, "FcMaterialTextures is 96 bytes");
FC_STATIC_ASSERT(offsetof(FcMaterialTextures, base_factor) == 32 && offsetof(FcMaterialTextures, uv_transform) == 64,
                 "FcMaterialTextures offsets");
FC_STATIC_ASSERT(sizeof(FcTriTexcoords) == 32, "FcTriTexcoords is 32 bytes");

#endif
