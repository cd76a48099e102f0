/* Image textures (docs/textures.md): one texel pool, a table of textures into it, the
 * textures bound to each material, and each triangle's texture coordinates.
 *
 * The pool is an array of 32-bit words. Its first 256 words (FC_SRGB_TABLE) are the
 * sRGB decoding table (word k: the float bits of the linear value of 8-bit code k);
 * then each texture's texels in its format (FcTexture.format):
 *   FC_TEXEL_RGBA32F     linear float RGBA, 4 words a texel (float images: EXR, HDR, PFM)
 *   FC_TEXEL_RGBA16F     linear half RGBA, 2 words (16-bit images, decoded on the host)
 *   FC_TEXEL_RGBA8       linear 8-bit unorm RGBA, 1 word, R in the low byte (8-bit data
 *                        textures: roughness, metalness, normal maps)
 *   FC_TEXEL_RGBA8_SRGB  8-bit RGB in sRGB, decoded through the table, and linear A
 * A texture is a box-filtered mip pyramid: level 0 of width x
 * height texels, top row first, then each level of max(1, w/2) x max(1, h/2) texels
 * until 1 x 1, all from `offset` in the pool. Level 0 is in `format`, the levels after it in
 * `mip_format`: an average of 8-bit texels is no 8-bit value, so those levels are half
 * floats rather than re-quantised (which biased dark sRGB gradients by up to +5 %). Texel (x, y) of a level covers
 * [x/w, (x+1)/w) x [y/h, (y+1)/h) of the (u, v) square; v = 0 is the image's top row
 * (glTF's and facet's convention; OBJ/MTL's v runs upward and its reader flips it). */
#ifndef FACET_SHARED_TEXTURE_LAYOUT_H
#define FACET_SHARED_TEXTURE_LAYOUT_H

#include "kernels/shared/types.h"

/* Wrap modes (FcTexture.wrap_u / wrap_v), as glTF's samplers name them. */
#define FC_WRAP_REPEAT 0
#define FC_WRAP_CLAMP 1
#define FC_WRAP_MIRROR 2

/* Texel formats (FcTexture.format), and the pool's sRGB table. */
#define FC_TEXEL_RGBA32F 0
#define FC_TEXEL_RGBA16F 1
#define FC_TEXEL_RGBA8 2
#define FC_TEXEL_RGBA8_SRGB 3
#define FC_SRGB_TABLE 0u /* the table's first word in the pool */
#define FC_SRGB_TABLE_WORDS 256u

/* A texture of the pool. */
typedef struct FcTexture {
    fc_uint offset; /* first texel of level 0, in 32-bit words of the pool */
    fc_int width;
    fc_int height;
    fc_int levels; /* mip levels, >= 1 */
    fc_int wrap_u;
    fc_int wrap_v;
    fc_int format;     /* FC_TEXEL_* of level 0 */
    fc_int mip_format; /* FC_TEXEL_* of levels 1 and up */
} FcTexture;

/* How a material's roughness texture is read (FcMaterialTextures.roughness_mode). */
#define FC_ROUGHNESS_PERCEPTUAL 0 /* r = texel; alpha_x, alpha_y scaled by r^2 (glTF, map_Pr) */
#define FC_ROUGHNESS_SHININESS 1  /* Phong exponent = Ns x texel, alpha from it (MTL map_Ns) */

/* Material texture flags (FcMaterialTextures.flags). */
/* glTF's metallic-roughness workflow: base colour B and metalness M give diffuse B,
 * the dielectric's F0 dielectric_f0 and metallic M (the mix of kernels/bsdf/metallic.cl),
 * as host/scene/material.cpp's set_metallic_roughness does for the factors. Without it the base colour texture scales
 * `diffuse` and the specular texture scales `specular`. */
#define FC_TEX_METALLIC_WORKFLOW 1u
/* KHR_materials_specular per hit (kernels/texture/extension_textures.cl): the dielectric's
 * F0 = min(specular_color_f0 x the colour texture's RGB, 1) x specular_weight x the strength
 * texture's A, and its F90 = the material's F90 x A (FC_MAT_SPECULAR_F90), replacing the
 * material's (or the metallic workflow's) F0. */
#define FC_TEX_SPECULAR_EXTENSION 2u

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
    /* glTF's KHR_materials_* textures, each multiplying the material's factor (extension_textures.cl):
     * clearcoat (R) the coat's weight, clearcoat_roughness (G) its perceptual roughness (its alpha
     * by G^2), sheen_color (RGB) the sheen's colour, sheen_roughness (A) its roughness,
     * specular_strength (A) and specular_color (RGB) KHR_materials_specular's (with
     * FC_TEX_SPECULAR_EXTENSION), clearcoat_normal the coat's own tangent-space normal map, x
     * and y scaled by clearcoat_normal_scale. */
    fc_int clearcoat;
    fc_int clearcoat_roughness;
    fc_int clearcoat_normal;
    fc_int sheen_color;
    fc_int sheen_roughness;
    fc_int specular_strength;
    fc_int specular_color;
    float clearcoat_normal_scale;
    float specular_color_f0[3];
    float specular_weight;
} FcMaterialTextures;

/* FcTriTexcoords.tangent_flags: bit c (0..2) set when corner c's bitangent is
 * -cross(n, t) (handedness w = -1), FC_TANGENTS_SET when `tangent` holds the corners'
 * vertex tangents (the file's, or MikkTSpace-style ones: host/scene/texture_tangents.cpp). */
#define FC_TANGENTS_SET 8u

/* Texture coordinates of one triangle's vertices (indexed like FcTriShading).
 * light_swapped is 1 when the triangle's area light (FcLight) has its edges swapped
 * (e1 = v2 - v0), so that a light sample's barycentrics find the right uv.
 * tangent[c]: corner c's unit world-space tangent, octahedral-encoded as two 16-bit
 * signed normalised integers (x in the low half, y in the high half; Cigolle et al.
 * 2014, "A Survey of Efficient Representations for Independent Unit Vectors"); read
 * only by programs with a normal map. */
typedef struct FcTriTexcoords {
    float uv[3][2];
    fc_int light_swapped;
    fc_uint tangent_flags;
    fc_uint tangent[3];
    fc_uint pad0;
} FcTriTexcoords;

FC_STATIC_ASSERT(sizeof(FcTexture) == 32, "FcTexture is 32 bytes");
FC_STATIC_ASSERT(sizeof(FcMaterialTextures) == 144, "FcMaterialTextures is 144 bytes");
FC_STATIC_ASSERT(offsetof(FcMaterialTextures, base_factor) == 32 && offsetof(FcMaterialTextures, uv_transform) == 64 &&
                     offsetof(FcMaterialTextures, clearcoat) == 96 &&
                     offsetof(FcMaterialTextures, specular_color_f0) == 128,
                 "FcMaterialTextures offsets");
FC_STATIC_ASSERT(sizeof(FcTriTexcoords) == 48, "FcTriTexcoords is 48 bytes");
FC_STATIC_ASSERT(offsetof(FcTriTexcoords, tangent) == 32, "FcTriTexcoords offsets");

#endif
