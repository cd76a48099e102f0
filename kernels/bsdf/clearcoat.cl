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
 * albedo scaling this is not reciprocal (docs/brdf.md). The coat has a normal of its own
 * (FC_MAT_CLEARCOAT_NORMAL: its clearcoatNormalTexture, or the surface's normal where only the
 * base is normal-mapped, as the extension says) and is then evaluated in its frame: wo and wi
 * of the shading frame turned into the coat's, E_coat read at the coat's mu_o, and
 *     f_coat seen from the shading frame = f_coat(wo_c, wi_c) cos_c(wi) / cos(wi),
 * so that it reflects what a surface of the coat's normal would (cosines are the
 * integrator's, of the shading normal). alpha below
 * FC_ALPHA_MIRROR is a perfect mirror (a delta lobe). Left out of programs for scenes
 * without clearcoat (FC_HAS_CLEARCOAT). */
#ifndef FACET_BSDF_CLEARCOAT_CL
#define FACET_BSDF_CLEARCOAT_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/microfacet.cl"
#include "kernels/util/frame.cl"
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

/* Whether the coat has a normal of its own (in the shading frame, after surface_orient). */
inline bool clearcoat_has_normal(const FcMaterial* m) {
#if FC_HAS_CLEARCOAT_NORMAL
    return (m->flags & FC_MAT_CLEARCOAT_NORMAL) != 0u;
#else
    (void)m;
    return false;
#endif
}

/* Direction w of the shading frame in the coat's frame (itself without a normal of its own). */
inline float3 clearcoat_local(const FcMaterial* m, float3 w) {
    if (!clearcoat_has_normal(m)) return w;
    Frame f = frame_from_normal(load3p(m->clearcoat_normal));
    return frame_to_local(&f, w);
}

/* Direction w of the coat's frame in the shading frame. */
inline float3 clearcoat_to_shading(const FcMaterial* m, float3 w) {
    if (!clearcoat_has_normal(m)) return w;
    Frame f = frame_from_normal(load3p(m->clearcoat_normal));
    return frame_to_world(&f, w);
}

/* c f_coat(wo, wi) of the shading frame (wo.z, wi.z > 0): in the coat's frame, seen through the
 * shading cosine. */
inline float3 clearcoat_eval(const FcMaterial* m, const FcMaterial* coat, float3 wo, float3 wi) {
    if (!clearcoat_has_normal(m)) return clearcoat_weight(m) * microfacet_eval(coat, wo, wi);
    float3 wo_c = clearcoat_local(m, wo), wi_c = clearcoat_local(m, wi);
    return clearcoat_weight(m) * microfacet_eval(coat, wo_c, wi_c) * (fmax(wi_c.z, 0.0f) / wi.z);
}

/* The density of the coat's sampling (solid angle: the same in either frame). */
inline float clearcoat_pdf(const FcMaterial* m, const FcMaterial* coat, float3 wo, float3 wi) {
    return microfacet_pdf(coat, clearcoat_local(m, wo), clearcoat_local(m, wi));
}

/* The world-space coat normal that apply_textures wrote, into the shading frame `f` of a surface
 * seen from wo (`flipped`: the surface was turned to face a ray from behind). A coat normal facing
 * away from wo or below the shading horizon gives way to the shading normal. */
inline void clearcoat_normal_to_shading(FcMaterial* m, const Frame* f, float3 wo, bool flipped) {
    if (!clearcoat_has_normal(m)) return;
    float3 n = load3p(m->clearcoat_normal);
    if (flipped) n = -n;
    float3 l = frame_to_local(f, n);
    if (!(l.z > 0.0f) || !(dot(n, wo) > 0.0f)) {
        m->flags &= ~FC_MAT_CLEARCOAT_NORMAL;
        return;
    }
    l = normalize(l);
    for (int k = 0; k < 3; ++k) m->clearcoat_normal[k] = k == 0 ? l.x : k == 1 ? l.y : l.z;
}

/* E_coat(mu): the coat lobe's directional albedo, F0 E + (1 - F0) E5 (exact for Schlick). */
inline float clearcoat_albedo(const FcMaterial* coat, float mu) {
    float r = ec_r(coat);
    int ndf = ec_ndf(coat);
    return FC_CLEARCOAT_F0 * ec_lookup(fc_albedo_E, ndf, mu, r) +
           (1.0f - FC_CLEARCOAT_F0) * ec_lookup(fc_albedo_E5, ndf, mu, r);
}

#endif
