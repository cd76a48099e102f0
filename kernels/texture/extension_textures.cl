/* The textures of glTF's KHR_materials_clearcoat, _sheen and _specular, read at a hit and
 * multiplied into the material's layer parameters (FcMaterialTextures, texture_layout.h), each
 * compiled only when the scene uses it:
 * - clearcoatTexture's R scales the coat's weight, clearcoatRoughnessTexture's G its
 *   perceptual roughness, so its alpha by G^2 (FC_HAS_CLEARCOAT_TEXTURES);
 * - sheenColorTexture's RGB (sRGB) scales the sheen's colour, sheenRoughnessTexture's A its
 *   roughness (FC_HAS_SHEEN_TEXTURES);
 * - KHR_materials_specular (FC_TEX_SPECULAR_EXTENSION, FC_HAS_SPECULAR_TEXTURES): the
 *   dielectric's F0 = min(F0(ior) specularColorFactor specularColorTexture.rgb, 1)
 *   specularFactor specularTexture.a and F90 = specularFactor specularTexture.a (the
 *   extension's definitions; kernels/bsdf/fresnel.cl);
 * - the coat's own normal (FC_HAS_CLEARCOAT_NORMAL): clearcoatNormalTexture applied to the
 *   surface's normal, or that normal itself where only the base is normal-mapped (the
 *   extension: no normal mapping on the coat without its own map), written to the material in
 *   world space (FC_MAT_CLEARCOAT_NORMAL) for surface_orient to bring into the shading frame. */
#ifndef FACET_TEXTURE_EXTENSION_TEXTURES_CL
#define FACET_TEXTURE_EXTENSION_TEXTURES_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/texture/tex_point.cl"

/* Whether the material binds any of the extensions' textures (or computes its specular per hit). */
inline bool extension_textures_bound(__global const FcMaterialTextures* mt) {
    return mt->clearcoat >= 0 || mt->clearcoat_roughness >= 0 || mt->clearcoat_normal >= 0 || mt->sheen_color >= 0 ||
           mt->sheen_roughness >= 0 || (mt->flags & FC_TEX_SPECULAR_EXTENSION) != 0u;
}

/* Writes the extensions' textures at texture coordinates uv (point p, ray cone `cone` meeting the
 * surface at cosine cos_hit) into `mat`. */
inline void apply_extension_textures(const SceneView* sc, __global const FcMaterialTextures* mt, float2 uv,
                                     const TexPoint* p, float cone, float cos_hit, FcMaterial* mat) {
#if FC_HAS_CLEARCOAT_TEXTURES
    if (mt->clearcoat >= 0) mat->clearcoat *= tex_lookup(sc, mt->clearcoat, uv, p, cone, cos_hit).x;
    if (mt->clearcoat_roughness >= 0) {
        float g = tex_lookup(sc, mt->clearcoat_roughness, uv, p, cone, cos_hit).y;
        mat->clearcoat_alpha *= g * g;
    }
#endif
#if FC_HAS_SHEEN_TEXTURES
    if (mt->sheen_color >= 0)
        tex_store3(mat->sheen, load3p(mat->sheen) * tex_lookup(sc, mt->sheen_color, uv, p, cone, cos_hit).xyz);
    if (mt->sheen_roughness >= 0) mat->sheen_roughness *= tex_lookup(sc, mt->sheen_roughness, uv, p, cone, cos_hit).w;
#endif
#if FC_HAS_SPECULAR_TEXTURES
    if (mt->flags & FC_TEX_SPECULAR_EXTENSION) {
        float3 colour = load3(mt->specular_color_f0);
        if (mt->specular_color >= 0) colour *= tex_lookup(sc, mt->specular_color, uv, p, cone, cos_hit).xyz;
        float strength = 1.0f;
        if (mt->specular_strength >= 0) strength = tex_lookup(sc, mt->specular_strength, uv, p, cone, cos_hit).w;
        tex_store3(mat->specular, fmin(colour, (float3)(1.0f)) * (mt->specular_weight * strength));
        mat->specular_f90 = fresnel_f90(mat) * strength;
        mat->flags |= FC_MAT_SPECULAR_F90;
    }
#endif
    (void)sc, (void)mt, (void)uv, (void)p, (void)cone, (void)cos_hit, (void)mat;
}

/* The coat's own normal from the surface's normal `ns_surface` (before any normal map) where
 * the coat has its own map or the base has one (`ns` the base's normal after it). */
inline void apply_clearcoat_normal(const SceneView* sc, __global const FcMaterialTextures* mt, float2 uv,
                                   const TexPoint* p, float cone, float cos_hit, float3 ns_surface, float3 ns,
                                   FcMaterial* mat) {
#if FC_HAS_CLEARCOAT_NORMAL
    if (!(mat->clearcoat > 0.0f) || (mt->clearcoat_normal < 0 && mt->normal < 0)) return;
    float3 n = ns_surface;
    if (mt->clearcoat_normal >= 0)
        n = normal_mapped(ns_surface, p, tex_lookup(sc, mt->clearcoat_normal, uv, p, cone, cos_hit).xyz,
                          mt->clearcoat_normal_scale);
    if (all(n == ns)) return;
    tex_store3(mat->clearcoat_normal, n);
    mat->flags |= FC_MAT_CLEARCOAT_NORMAL;
#else
    (void)sc, (void)mt, (void)uv, (void)p, (void)cone, (void)cos_hit, (void)ns_surface, (void)ns, (void)mat;
#endif
}

#endif
