/* Materials: a diffuse lobe plus a specular lobe, each chosen from a closed list, with
 * the specular microfacet terms D, G and F chosen independently (docs/brdf.md).
 * The named models of docs/brdf.md ("lambert", "ggx", "dielectric", ...) are presets of
 * these choices, listed once in host/scene/material.cpp (kPresets).
 * The dielectric reads ior as n_below / n_above (inside over outside), the microfacet
 * terms as the microfacet lobe does, and `specular` as a transmittance applied at each
 * refraction (kernels/bsdf/dielectric.cl). */
#ifndef FACET_SHARED_MATERIAL_LAYOUT_H
#define FACET_SHARED_MATERIAL_LAYOUT_H

#include "kernels/shared/types.h"

/* Each closed list of a material's choices is written once, here, as X(VALUE, "name")
 * in value order from 0 (the X-macro idiom of feature_flags.h): the FC_* constants are
 * generated below, the host's name tables (host/scene/material.cpp), which the scene
 * format and `facet info` use, from the same lists. */

/* Diffuse lobes (FcMaterial.diffuse_model). */
#define FC_DIFFUSE_LIST(X)                                                                                             \
    X(FC_DIFFUSE_NONE, "none")                                                                                         \
    X(FC_DIFFUSE_LAMBERT, "lambert")                                                                                   \
    X(FC_DIFFUSE_LAMBERT_1MF0, "lambert_1mf0")           /* Lambert x (1 - F0), tri-Ace (Gotanda 2010) */              \
    X(FC_DIFFUSE_OREN_NAYAR, "oren_nayar")               /* the A, B, sin(alpha) tan(beta) form (Oren & Nayar 1994) */ \
    X(FC_DIFFUSE_ASHIKHMIN_SHIRLEY, "ashikhmin_shirley") /* 28/23 energy-conserving term (Ashikhmin & Shirley 2000) */ \
    X(FC_DIFFUSE_EON, "eon")                             /* energy-preserving Oren-Nayar (Portsmouth et al. 2024) */

/* Specular lobes (FcMaterial.specular_model). */
#define FC_SPECULAR_LIST(X)                                                                                            \
    X(FC_SPECULAR_NONE, "none")                                                                                        \
    X(FC_SPECULAR_MICROFACET, "microfacet")                         /* D G F / (4 cos_o cos_i) */                      \
    X(FC_SPECULAR_BLINN_PHONG, "blinn_phong")                       /* Ks (n.h)^e / pi, the original (Blinn 1977) */   \
    X(FC_SPECULAR_BLINN_PHONG_NORMALIZED, "blinn_phong_normalized") /* Ks (e + 8) / (8 pi) (n.h)^e */                  \
    X(FC_SPECULAR_ASHIKHMIN_SHIRLEY, "ashikhmin_shirley")           /* anisotropic Phong (Ashikhmin & Shirley 2000) */ \
    X(FC_SPECULAR_DIELECTRIC, "dielectric") /* reflection + refraction, smooth or rough (Walter 2007) */

/* Normal distributions (FcMaterial.ndf). */
#define FC_NDF_LIST(X)             \
    X(FC_NDF_BECKMANN, "beckmann") \
    X(FC_NDF_GGX, "ggx")           \
    X(FC_NDF_BLINN_PHONG, "blinn_phong") /* (e + 2) / (2 pi) cos^e, e = exponent_x */

/* Geometry (shadowing-masking) terms (FcMaterial.geometry). */
#define FC_G_LIST(X)                                                                                          \
    X(FC_G_IMPLICIT, "implicit")                 /* (n.l)(n.v) */                                             \
    X(FC_G_COOK_TORRANCE, "cook_torrance")       /* min(1, 2(n.h)(n.v)/(v.h), 2(n.h)(n.l)/(v.h)) */           \
    X(FC_G_SMITH_SEPARABLE, "smith_separable")   /* G1(v) G1(l), exact Lambda of the NDF */                   \
    X(FC_G_SMITH_CORRELATED, "smith_correlated") /* 1 / (1 + Lambda(v) + Lambda(l)) (Heitz 2014) */           \
    X(FC_G_SMITH_SCHLICK, "smith_schlick")       /* Schlick's approximation of Smith, k = alpha sqrt(2/pi) */ \
    X(FC_G_SMITH_WALTER, "smith_walter")         /* Walter et al. 2007's rational approximation (Beckmann) */

/* Fresnel terms (FcMaterial.fresnel). */
#define FC_FRESNEL_LIST(X)                                                                        \
    X(FC_FRESNEL_ONE, "one")                 /* F = 1, for tests */                               \
    X(FC_FRESNEL_SCHLICK, "schlick")         /* Schlick from the RGB F0 in `specular` */          \
    X(FC_FRESNEL_SCHLICK_IOR, "schlick_ior") /* Schlick with F0 = ((n - 1)/(n + 1))^2, n = ior */ \
    X(FC_FRESNEL_DIELECTRIC, "dielectric")   /* exact, unpolarised, relative index ior */         \
    X(FC_FRESNEL_CONDUCTOR, "conductor")     /* exact, complex index eta + i k per channel */

/* Microfacet sampling (FcMaterial.sampling). */
#define FC_SAMPLE_LIST(X)                                                                              \
    X(FC_SAMPLE_VISIBLE, "visible")             /* visible normals (Heitz 2018 for GGX; the oracle) */ \
    X(FC_SAMPLE_ALL, "all")                     /* D(m) cos(theta_m) */                                \
    X(FC_SAMPLE_SPHERICAL_CAP, "spherical_cap") /* visible normals by spherical caps (Dupuy 2023) */   \
    X(FC_SAMPLE_BOUNDED, "bounded")             /* bounded visible normals (Eto & Tokuyoshi 2023) */

/* Alpha modes (host Material.alpha_mode; the kernels read FC_MAT_ALPHA_* flags), glTF's
 * alphaMode names in lower case. */
#define FC_ALPHA_MODE_LIST(X)                                             \
    X(FC_ALPHA_OPAQUE, "opaque") /* alpha ignored */                      \
    X(FC_ALPHA_MASK, "mask")     /* cut out where alpha < alpha_cutoff */ \
    X(FC_ALPHA_BLEND, "blend")   /* stochastic transparency: there with probability alpha */

/* The constants: 0, 1, ... in list order, and FC_*_COUNT after each list. */
#define FC_MATERIAL_ENUM_VALUE(value, name) value,
enum { FC_DIFFUSE_LIST(FC_MATERIAL_ENUM_VALUE) FC_DIFFUSE_COUNT };
enum { FC_SPECULAR_LIST(FC_MATERIAL_ENUM_VALUE) FC_SPECULAR_COUNT };
enum { FC_NDF_LIST(FC_MATERIAL_ENUM_VALUE) FC_NDF_COUNT };
enum { FC_G_LIST(FC_MATERIAL_ENUM_VALUE) FC_G_COUNT };
enum { FC_FRESNEL_LIST(FC_MATERIAL_ENUM_VALUE) FC_FRESNEL_COUNT };
enum { FC_SAMPLE_LIST(FC_MATERIAL_ENUM_VALUE) FC_SAMPLE_COUNT };
enum { FC_ALPHA_MODE_LIST(FC_MATERIAL_ENUM_VALUE) FC_ALPHA_MODE_COUNT };
#undef FC_MATERIAL_ENUM_VALUE

/* Material flags (FcMaterial.flags). */
#define FC_MAT_TWO_SIDED_EMISSION 1u
/* Multiple-scattering energy compensation of the GGX / Beckmann lobes (Kulla & Conty
 * 2017; kernels/bsdf/energy_compensation.cl), and the diffuse base weighted by
 * 1 - E_spec instead of 1 - F0. The host sets it per material ("energy_compensation"). */
#define FC_MAT_ENERGY_COMPENSATION 2u
/* Alpha (coverage) modes, glTF's alphaMode (kernels/trace/alpha_test.cl): the material's
 * coverage a = `alpha` x the alpha texture's channel (none: 1). MASK: the surface is there
 * where a >= alpha_cutoff, cut away elsewhere; BLEND: there with probability a (stochastic
 * transparency). Neither set: opaque, alpha ignored. Cut-outs hold for every ray (camera,
 * bounce and shadow rays), on triangles; spheres have no alpha. */
#define FC_MAT_ALPHA_MASK 4u
#define FC_MAT_ALPHA_BLEND 8u
/* The alpha texture's coverage is its R channel (a grey image, MTL's map_d without an
 * alpha channel) instead of A. */
#define FC_MAT_ALPHA_RED 16u
/* Schlick's Fresnel (FC_FRESNEL_SCHLICK) reaches `specular_f90` at grazing incidence instead of
 * 1: F = F0 + (F90 - F0)(1 - cos)^5, KHR_materials_specular's dielectric F90 = specularFactor
 * (kernels/bsdf/fresnel.cl). Without the flag F90 is 1, whatever the field holds. */
#define FC_MAT_SPECULAR_F90 32u
/* The clearcoat has a normal of its own (KHR_materials_clearcoat's clearcoatNormalTexture, or the
 * surface's normal under a base normal map): `clearcoat_normal`, written in world space by the
 * textures (kernels/texture/extension_textures.cl) and turned into the shading frame by
 * surface_orient (kernels/integrator/surface.cl), where the coat lobe is evaluated in its own
 * frame (kernels/bsdf/clearcoat.cl). */
#define FC_MAT_CLEARCOAT_NORMAL 64u
/* The specular lobes are anisotropic (alpha_x != alpha_y, exponent_x != exponent_y, or
 * `anisotropy` > 0): the shading frame's x axis follows the surface's tangent rotated by
 * anisotropy_direction (kernels/bsdf/anisotropy.cl) instead of an arbitrary one. The host
 * sets it (material_is_anisotropic); without it the frame is frame_from_normal's. */
#define FC_MAT_ANISOTROPIC 128u
/* A dielectric chooses reflection or refraction by its Fresnel factor moved toward
 * [0.25, 0.75] (kernels/bsdf/dielectric.cl, dielectric_choice) instead of by the factor
 * alone: set by the host on the dielectrics of scenes whose light is not uniform
 * (host/scene/device_scene.cpp), where a glass surface's reflection of a bright light is
 * otherwise a rare, bright sample. */
#define FC_MAT_WIDE_CHOICE 256u

/* Phong-style exponents are clamped to [0, FC_PHONG_EXPONENT_MAX] (the kernels'
 * fc_phong_exponent, the host's shininess conversions and its clamp_material). */
#define FC_PHONG_EXPONENT_MAX 1e6f

/* Below this alpha a microfacet lobe is a perfect mirror (docs/brdf.md: stability). */
#define FC_ALPHA_MIRROR 1e-4f

/* A material. Colours are linear RGB. `specular` is the specular lobe's colour, by model:
 * F0 for the Schlick Fresnel (microfacet, Ashikhmin-Shirley), Ks for the Blinn-Phong
 * lobes, the transmittance at each refraction for the dielectric (the host's Material
 * names the three apart). alpha_x/alpha_y are the microfacet roughness (alpha) along
 * the tangent and bitangent; exponent_x/exponent_y the Phong-style exponents
 * (Blinn-Phong uses exponent_x; Ashikhmin-Shirley nu = exponent_x, nv = exponent_y);
 * `sigma` is Oren-Nayar's sigma (radians), or EON's roughness r in [0, 1] (the host's
 * Material names the two apart). `metallic` M in [0, 1] mixes in a metal lobe, glTF's
 * metallic-roughness BRDF (kernels/bsdf/metallic.cl): f = (1 - M) f + M f_metal, f_metal the
 * microfacet lobe with Schlick's F0 = `diffuse` (the base colour); 0 leaves the material as
 * it is. alpha, alpha_cutoff and alpha_texture (an index of the texture table, -1 for none)
 * are the coverage of the FC_MAT_ALPHA_* flags. */
typedef struct FcMaterial {
    float diffuse[3];
    fc_int diffuse_model;
    float specular[3];
    fc_int specular_model;
    float emission[3];
    fc_int ndf;
    float eta[3];
    fc_int geometry;
    float k[3];
    fc_int fresnel;
    float alpha_x;
    float alpha_y;
    float exponent_x;
    float exponent_y;
    float ior;
    float sigma;
    fc_uint flags;
    fc_int sampling;
    float metallic;
    float alpha;
    float alpha_cutoff;
    fc_int alpha_texture;
    /* glTF's KHR_materials_* layers and volume (docs/brdf.md); all 0 leaves the material as
     * it is. `attenuation` is the Beer-Lambert coefficient (per unit length, per channel)
     * inside a transmissive material (KHR_materials_volume: -ln(attenuationColor) /
     * attenuationDistance). `clearcoat` weights a clear GGX layer of roughness alpha
     * `clearcoat_alpha` over the material (KHR_materials_clearcoat); `sheen` is the sheen
     * layer's colour and `sheen_roughness` its roughness (KHR_materials_sheen).
     * `anisotropy` is KHR_materials_anisotropy's strength s in [0, 1]: the kernels stretch the
     * (textured) roughness along the anisotropy direction, alpha_x = mix(alpha_x, 1, s^2),
     * alpha_y kept; `anisotropy_direction` (cos, sin of the rotation) turns that direction
     * from the tangent toward the bitangent (used with FC_MAT_ANISOTROPIC).
     * `specular_f90` is the Schlick Fresnel's value at grazing incidence where
     * FC_MAT_SPECULAR_F90 is set (KHR_materials_specular's specularFactor); `clearcoat_normal`
     * the coat's own unit normal where FC_MAT_CLEARCOAT_NORMAL is set. */
    float attenuation[3];
    float clearcoat;
    float sheen[3];
    float clearcoat_alpha;
    float sheen_roughness;
    float anisotropy;
    float anisotropy_direction[2];
    float specular_f90;
    float clearcoat_normal[3];
} FcMaterial;

FC_STATIC_ASSERT(sizeof(FcMaterial) == 192, "FcMaterial is 192 bytes");
FC_STATIC_ASSERT(offsetof(FcMaterial, emission) == 32 && offsetof(FcMaterial, flags) == 104 &&
                     offsetof(FcMaterial, metallic) == 112 && offsetof(FcMaterial, alpha_texture) == 124 &&
                     offsetof(FcMaterial, attenuation) == 128 && offsetof(FcMaterial, sheen) == 144 &&
                     offsetof(FcMaterial, sheen_roughness) == 160 && offsetof(FcMaterial, anisotropy) == 164 &&
                     offsetof(FcMaterial, anisotropy_direction) == 168 && offsetof(FcMaterial, specular_f90) == 176 &&
                     offsetof(FcMaterial, clearcoat_normal) == 180,
                 "FcMaterial offsets");

#endif
