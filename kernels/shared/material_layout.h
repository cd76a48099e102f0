/* Materials: a diffuse lobe plus a specular lobe, each chosen from a closed list, with
 * the specular microfacet terms D, G and F chosen independently (docs/brdf.md).
 * The named models of the source documents are presets of these choices
 * (host/scene/material.cpp):
 *   lambert                 diffuse LAMBERT,            specular NONE
 *   oren_nayar              diffuse OREN_NAYAR,         specular NONE
 *   cook_torrance           diffuse LAMBERT,            specular MICROFACET (Beckmann, Cook-Torrance G, Schlick F0)
 *   blinn_phong             diffuse LAMBERT,            specular BLINN_PHONG (original, 1977)
 *   blinn_phong_normalized  diffuse LAMBERT,            specular BLINN_PHONG_NORMALIZED ((n+8)/8pi)
 *   ashikhmin_shirley       diffuse ASHIKHMIN_SHIRLEY,  specular ASHIKHMIN_SHIRLEY
 *   ggx (the default)       diffuse LAMBERT_1MF0,       specular MICROFACET (GGX, height-correlated Smith, Schlick F0)
 *   microfacet              any diffuse, MICROFACET with any D, G, F
 *   conductor               diffuse NONE, MICROFACET (GGX, correlated Smith, exact conductor F, eta + i k)
 *   dielectric              diffuse NONE, DIELECTRIC (glass, water: the whole BSDF, any diffuse ignored)
 * The dielectric reads ior as n_below / n_above (inside over outside), the microfacet
 * terms as the microfacet lobe does, and `specular` as a transmittance applied at each
 * refraction (kernels/bsdf/dielectric.cl). */
#ifndef FACET_SHARED_MATERIAL_LAYOUT_H
#define FACET_SHARED_MATERIAL_LAYOUT_H

#include "kernels/shared/types.h"

/* Diffuse lobes (FcMaterial.diffuse_model). */
#define FC_DIFFUSE_NONE 0
#define FC_DIFFUSE_LAMBERT 1
#define FC_DIFFUSE_LAMBERT_1MF0 2       /* Lambert weighted by (1 - F0), tri-Ace (Gotanda 2010) */
#define FC_DIFFUSE_OREN_NAYAR 3         /* the A, B, sin(alpha) tan(beta) form (Oren & Nayar 1994) */
#define FC_DIFFUSE_ASHIKHMIN_SHIRLEY 4  /* 28/23 energy-conserving term (Ashikhmin & Shirley 2000) */
#define FC_DIFFUSE_COUNT 5

/* Specular lobes (FcMaterial.specular_model). */
#define FC_SPECULAR_NONE 0
#define FC_SPECULAR_MICROFACET 1              /* D G F / (4 cos_o cos_i) */
#define FC_SPECULAR_BLINN_PHONG 2             /* Ks (n.h)^e / pi, the original (Blinn 1977) */
#define FC_SPECULAR_BLINN_PHONG_NORMALIZED 3  /* Ks (e + 8) / (8 pi) (n.h)^e */
#define FC_SPECULAR_ASHIKHMIN_SHIRLEY 4       /* anisotropic Phong (Ashikhmin & Shirley 2000) */
#define FC_SPECULAR_DIELECTRIC 5              /* reflection + refraction, smooth or rough (Walter 2007) */
#define FC_SPECULAR_COUNT 6

/* Normal distributions (FcMaterial.ndf). */
#define FC_NDF_BECKMANN 0
#define FC_NDF_GGX 1
#define FC_NDF_BLINN_PHONG 2   /* (e + 2) / (2 pi) cos^e, e = exponent_x */
#define FC_NDF_COUNT 3

/* Geometry (shadowing-masking) terms (FcMaterial.geometry). */
#define FC_G_IMPLICIT 0             /* (n.l)(n.v) */
#define FC_G_COOK_TORRANCE 1        /* min(1, 2(n.h)(n.v)/(v.h), 2(n.h)(n.l)/(v.h)) */
#define FC_G_SMITH_SEPARABLE 2      /* G1(v) G1(l), exact Lambda of the NDF */
#define FC_G_SMITH_CORRELATED 3     /* 1 / (1 + Lambda(v) + Lambda(l)) (Heitz 2014) */
#define FC_G_SMITH_SCHLICK 4        /* Schlick's approximation of Smith, k = alpha sqrt(2/pi) */
#define FC_G_SMITH_WALTER 5         /* Walter et al. 2007's rational approximation (Beckmann) */
#define FC_G_COUNT 6

/* Fresnel terms (FcMaterial.fresnel). */
#define FC_FRESNEL_ONE 0            /* F = 1, for tests */
#define FC_FRESNEL_SCHLICK 1        /* Schlick from the RGB F0 in `specular` */
#define FC_FRESNEL_SCHLICK_IOR 2    /* Schlick with F0 = ((n - 1)/(n + 1))^2, n = ior */
#define FC_FRESNEL_DIELECTRIC 3     /* exact, unpolarised, relative index ior */
#define FC_FRESNEL_CONDUCTOR 4      /* exact, complex index eta + i k per channel */
#define FC_FRESNEL_COUNT 5

/* Microfacet sampling (FcMaterial.sampling). */
#define FC_SAMPLE_VISIBLE 0         /* distribution of visible normals */
#define FC_SAMPLE_ALL 1             /* D(m) cos(theta_m) */

/* Material flags (FcMaterial.flags). */
#define FC_MAT_TWO_SIDED_EMISSION 1u

/* Phong-style exponents are clamped to [0, FC_PHONG_EXPONENT_MAX] (the kernels'
 * fc_phong_exponent, the host's shininess conversions and its clamp_material). */
#define FC_PHONG_EXPONENT_MAX 1e6f

/* Below this alpha a microfacet lobe is a perfect mirror (docs/brdf.md: stability). */
#define FC_ALPHA_MIRROR 1e-4f

/* A material. Colours are linear RGB. `specular` is F0 for the Schlick Fresnel and the
 * specular colour Ks of the Blinn-Phong lobes. alpha_x/alpha_y are the microfacet
 * roughness along the tangent and bitangent; exponent_x/exponent_y the Phong-style
 * exponents (Blinn-Phong uses exponent_x; Ashikhmin-Shirley nu = exponent_x, nv =
 * exponent_y); `roughness` is Oren-Nayar's sigma (radians). */
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
    float roughness;
    fc_uint flags;
    fc_int sampling;
} FcMaterial;

FC_STATIC_ASSERT(sizeof(FcMaterial) == 112, "FcMaterial is 112 bytes");
FC_STATIC_ASSERT(offsetof(FcMaterial, emission) == 32 && offsetof(FcMaterial, flags) == 104, "FcMaterial offsets");

#endif
