/* The clearcoat layer of glTF's KHR_materials_clearcoat: a clear dielectric coat of
 * weight c = `clearcoat` in [0, 1] over the material, a GGX lobe of its own roughness
 * (alpha = `clearcoat_alpha`, the extension's clearcoatRoughness squared) with
 * height-correlated Smith G and Schlick's Fresnel from F0 = 0.04 (ior 1.5):
 *     f = c f_coat(wo, wi) + (1 - c E_coat(mu_o)) f_below(wo, wi).
 * The extension weights the layer below by 1 - c F(wo.h); this takes the albedo-scaling
 * form instead (Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks",
 * layering by albedo), weighting it by 1 - c E_coat(mu_o), E_coat the coat's directional
 * albedo (0.04 E + 0.96 E5 from the GGX tables of albedo_tables_conductor.cl and
 * albedo_tables_schlick.cl), so that the energy the coat reflects is exactly what the
 * layer below loses: a white material stays white (a white furnace gives 1). Like all
 * albedo scaling this is not reciprocal (docs/brdf.md). The coat uses the shading normal;
 * the extension's separate clearcoat normal texture is not read. alpha below
 * FC_ALPHA_MIRROR is a perfect mirror (a delta lobe). Left out of programs for scenes
 * without clearcoat (FC_HAS_CLEARCOAT). */
#ifndef FACET_BSDF_CLEARCOAT_CL
#define FACET_BSDF_CLEARCOAT_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/microfacet.cl"
#include "kernels/util/math.cl"

/* The coat's Schlick F0: ((1.5 - 1) / (1.5 + 1))^2. */
#define FC_CLEARCOAT_F0 0.04f

/* Whether the material has a clearcoat layer. */
inline bool clearcoat_present(const FcMaterial* m) {
#if FC_HAS_CLEARCOAT
    return m->clearcoat > 0.0f;
#else
    (void)m;
    return false;
#endif
}

/* c clamped to [0, 1]. */
inline float clearcoat_weight(const FcMaterial* m) { return clamp(m->clearcoat, 0.0f, 1.0f); }

/* The coat as a material of its own: a GGX lobe with F0 0.04, no diffuse, no compensation. */
inline FcMaterial clearcoat_lobe(const FcMaterial* m) {
    FcMaterial c = *m;
    c.diffuse_model = FC_DIFFUSE_NONE;
    c.specular_model = FC_SPECULAR_MICROFACET;
    c.ndf = FC_NDF_GGX;
    c.geometry = FC_G_SMITH_CORRELATED;
    c.fresnel = FC_FRESNEL_SCHLICK;
    c.sampling = FC_SAMPLE_VISIBLE;
    c.flags = 0u;
    c.metallic = 0.0f;
    c.clearcoat = 0.0f;
    for (int k = 0; k < 3; ++k) c.specular[k] = FC_CLEARCOAT_F0, c.sheen[k] = 0.0f;
    float a = clamp(m->clearcoat_alpha, 0.0f, 1.0f); /* NaN -> 0, a mirror */
    c.alpha_x = c.alpha_y = a;
    return c;
}

/* E_coat(mu): the coat lobe's directional albedo, F0 E + (1 - F0) E5 (exact for Schlick). */
inline float clearcoat_albedo(const FcMaterial* coat, float mu) {
    float r = ec_r(coat);
    int ndf = ec_ndf(coat);
    return FC_CLEARCOAT_F0 * ec_lookup(fc_albedo_E, ndf, mu, r) +
           (1.0f - FC_CLEARCOAT_F0) * ec_lookup(fc_albedo_E5, ndf, mu, r);
}

#endif
