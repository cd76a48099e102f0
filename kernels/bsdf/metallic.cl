/* glTF's metallic-roughness BRDF (glTF 2.0 specification, Appendix B, "Metal-Roughness
 * Material"): a dielectric and a metal mixed linearly by metallic M in [0, 1],
 *     f = (1 - M) f_dielectric + M f_metal.
 * f_dielectric is the material's own pair of lobes: the microfacet lobe with its Fresnel
 * (Schlick, F0 = `specular`: 0.04 for glTF's ior 1.5, and F90 = `specular_f90` where
 * KHR_materials_specular sets it, fresnel.cl) over the Lambert base of colour
 * `diffuse` coupled to that lobe (diffuse.cl). f_metal is the same microfacet lobe (D, G,
 * alpha) with Schlick's Fresnel from F0 = `diffuse`, the base colour, F90 = 1, and no diffuse lobe.
 * Each lobe carries its own energy compensation (energy_compensation.cl): the metal's f_ms
 * with the metal's F_ms, the dielectric's with 0.04's, and the diffuse base coupled to the
 * dielectric's albedo E_s alone, so a white base reflects everything at every M.
 *
 * The two specular lobes differ only in F, so they share one sampling density (the NDF's,
 * mixed with the cosine lobe of f_ms by E alone): bsdf.cl chooses "specular" with the
 * mixture's estimated albedo, (1 - M) w_dielectric + M w_metal, against (1 - M) w_diffuse,
 * and the pdf stays (1 - p) pdf_diffuse + p pdf_specular. Left out of programs for scenes
 * without metallic materials (FC_HAS_METALLIC). */
#ifndef FACET_BSDF_METALLIC_CL
#define FACET_BSDF_METALLIC_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"

/* Whether the material mixes in a metal lobe (a microfacet lobe and M > 0). */
inline bool metallic_mixed(const FcMaterial* m) {
#if FC_HAS_METALLIC
    return m->specular_model == FC_SPECULAR_MICROFACET && m->metallic > 0.0f;
#else
    (void)m;
    return false;
#endif
}

/* The metal lobe of a mixed material: its microfacet lobe with Schlick's F0 = the base colour. */
inline FcMaterial metallic_lobe(const FcMaterial* m) {
    FcMaterial metal = *m;
    metal.diffuse_model = FC_DIFFUSE_NONE;
    metal.fresnel = FC_FRESNEL_SCHLICK;
    metal.metallic = 0.0f;
    metal.flags &= ~FC_MAT_SPECULAR_F90; /* a metal's Schlick reaches 1 at grazing */
    for (int c = 0; c < 3; ++c) metal.specular[c] = clamp(m->diffuse[c], 0.0f, 1.0f);
    return metal;
}

/* M clamped to [0, 1]. */
inline float metallic_weight(const FcMaterial* m) { return clamp(m->metallic, 0.0f, 1.0f); }

#endif
