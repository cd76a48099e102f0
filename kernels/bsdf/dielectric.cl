/* The dielectric BSDF (FC_SPECULAR_DIELECTRIC): reflection and refraction at the
 * interface between two non-absorbing media, smooth or rough.
 *
 * Parameters: ior = eta = n_below / n_above (the index of the -z side, "inside", over
 * the +z side's; the integrator passes 1 / ior when the ray arrives from inside),
 * 1.0001 to 20 and below 1; ndf and alpha_x/alpha_y (GGX or Beckmann); geometry
 * smith_separable, else height-correlated Smith; specular = a transmittance applied
 * at each refraction (1 = clear); sampling = visible or all normals. Unlike the
 * reflection lobes, wo and wi may lie on either side (wo.z != 0).
 *
 * - Rough (alpha >= FC_ALPHA_MIRROR): Walter et al. 2007, "Microfacet Models for
 *   Refraction through Rough Surfaces", EGSR. Reflection is eq. 20,
 *   D G F / (4 |cos_o| |cos_i|), h = normalize(wo + wi). Refraction uses the
 *   generalised half vector h = -(n_i wi + n_o wo) / |...| (eq. 16, n_i the index on
 *   wi's side, n_o on wo's), turned to +z, and eq. 21:
 *       f_t = |wi.h| |wo.h| / (|cos_i| |cos_o|) n_o^2 (1 - F) G D / (n_i wi.h + n_o wo.h)^2.
 *   Microfacets seen from behind by wo or wi contribute nothing (the chi+ of eq. 23).
 *   Sampling draws h from the NDF seen from wo (visible normals: Heitz 2018 for GGX,
 *   beckmann.cl for Beckmann; or D cos), then reflects with probability q = F(wo.h) (Walter
 *   2007, section 5.3), or with FC_MAT_WIDE_CHOICE F moved toward [0.25, 0.75]
 *   (dielectric_choice), and refracts otherwise, so the density of wi is
 *       reflection  q pdf_h / (4 |wo.h|)                                   (eq. 14)
 *       refraction  (1 - q) pdf_h n_i^2 |wi.h| / (n_i wi.h + n_o wo.h)^2   (eq. 17).
 * - Smooth (alpha below FC_ALPHA_MIRROR, or an index-matched ior within FC_IOR_MATCHED
 *   of 1): a delta BSDF. Sampling reflects with probability q = dielectric_choice(F(cos_o)) (exact Fresnel,
 * fresnel_dielectric: 1 under total internal reflection) and refracts otherwise (refraction.cl); the weight is F / q
 * for the reflection and specular (1 - F) / ((1 - q) etap^2) for the refraction; eval and pdf give 0.
 *
 * Radiance scaling (docs/brdf.md, "Dielectrics"): eq. 21's n_o^2 / (...)^2 makes f_t the
 * BTDF that transports radiance, which is multiplied by (n_o / n_i)^2 = 1 / etap^2
 * across the boundary (etap = n_i / n_o; pbrt-v4 DielectricBxDF in Radiance mode).
 * It is not symmetric: f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2 (Veach 1997, eq. 5.14).
 * Below, f_t is written as the importance form times 1 / etap^2.
 *
 * Energy compensation (FC_MAT_ENERGY_COMPENSATION, GGX / Beckmann with height-correlated
 * Smith): f is divided by the single-scattering energy albedo seen from wo (Turquin 2019's
 * albedo scaling, energy_compensation.cl); not reciprocal.
 *
 * Every output is finite and >= 0; degenerate half vectors (|n_i wi + n_o wo| = 0, as
 * wi = -wo at eta ~ 1) and wo or wi on the surface (z = 0) give f = 0 and pdf = 0.
 *
 * The rough interface's formulas are written once, over lanes, in dielectric_lanes.cl: these
 * functions are its W = 1 calls with any NDF of ndf.cl, and the packet paths run its GGX and
 * Beckmann visible-normal forms at W = 8 or 16 (rough_dielectric_in_lanes). */
#ifndef FACET_BSDF_DIELECTRIC_CL
#define FACET_BSDF_DIELECTRIC_CL

#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/ndf.cl"
#include "kernels/bsdf/refraction.cl"
#include "kernels/lanes/scalar.cl" /* the W = 1 forms of kernels/bsdf/dielectric_lanes.cl */
#include "kernels/util/math.cl"

/* An index-matched interface (|ior - 1| below FC_IOR_MATCHED) does not scatter: the
 * refracted direction is -wo whatever the microfacet, F = 0, and Walter's half vector
 * wo + etap wi vanishes (a rough one would lose the light as degenerate). It is treated
 * as smooth, so light passes straight through as a delta lobe of weight 1. */
#define FC_IOR_MATCHED 1e-5f

inline bool dielectric_is_smooth(const FcMaterial* m) {
    if (fabs(m->ior - 1.0f) < FC_IOR_MATCHED) return true;
    float2 a = ndf_alpha(m);
    return !(fmax(a.x, a.y) >= FC_ALPHA_MIRROR);
}

inline float3 dielectric_tint(const FcMaterial* m) { return load3p(m->specular); }

/* w turned to the +z side. */
inline float3 dielectric_upper(float3 w) { return dielectric_upper_l1(w); }

/* The material's parameters as dielectric_lanes.cl takes them at W = 1, with the projected
 * area seen from wo and the compensation's albedo read at wo where it is on. */
inline RoughDielectric_l1 rough_dielectric_of(const FcMaterial* m, float3 wo) {
    RoughDielectric_l1 b;
    const float2 a = ndf_alpha(m);
    b.tint = dielectric_tint(m);
    b.ax = a.x;
    b.ay = a.y;
    b.ior = m->ior;
    b.ggx = m->ndf == FC_NDF_GGX;
    b.beckmann = m->ndf == FC_NDF_BECKMANN;
    b.correlated = m->geometry != FC_G_SMITH_SEPARABLE;
    b.wide = (m->flags & FC_MAT_WIDE_CHOICE) != 0u;
    b.ec = ec_enabled(m);
    b.ec_e = b.ec ? ec_dielectric_albedo(m, wo) : 1.0f;
    b.area_o = ndf_projected_area(m, dielectric_upper(wo));
    return b;
}

/* Whether the packet paths evaluate and sample material m in lanes (dielectric_lanes.cl's
 * rough_dielectric_*): a rough dielectric of GGX or Beckmann visible normals, as
 * ndf_sample_two_sided draws them. */
inline bool rough_dielectric_in_lanes(const FcMaterial* m) {
    if (m->specular_model != FC_SPECULAR_DIELECTRIC || dielectric_is_smooth(m)) return false;
    if (m->ndf == FC_NDF_GGX) return m->sampling == FC_SAMPLE_VISIBLE;
    return m->ndf == FC_NDF_BECKMANN && m->sampling != FC_SAMPLE_ALL;
}

/* The probability of choosing the lobe whose Fresnel factor is fl (F for the reflection, 1 - F for
 * the refraction): fl itself; with FC_MAT_WIDE_CHOICE (scenes whose light is not uniform), fl raised toward
 * FC_DIELECTRIC_MIN_CHOICE by at most a factor of 4 and lowered to match on the other side, so that the two choices add
 * to 1 and a lobe that carries nothing (F = 0, total internal reflection's refraction) is never chosen: q = clamp(fl,
 * min(Q, 4 fl), 1 - min(Q, 4 (1 - fl))). Choosing by F alone (pbrt-v4, Mitsuba 3) picks a glass ball's reflection of
 * the sun once in 25 at normal incidence, each time carrying the sun's whole radiance: once the caustics are sampled,
 * the brightest fireflies of glass_metal_sky (docs/sampling.md, "Sampling toward glass"). F's own choice stays where
 * the light is uniform (a constant environment alone, the white furnace), where it is exact: every sample weighs 1. */
inline float dielectric_choice(const FcMaterial* m, float fl) {
    return dielectric_choice_l1((m->flags & FC_MAT_WIDE_CHOICE) != 0u, fl);
}

/* The density of the half vector h seen from wo: the visible normals' from d = D(h) and the
 * projected area area_o seen from wo turned up, else the NDF's own (D cos). */
inline float dielectric_pdf_h(const FcMaterial* m, float3 wo, float3 h, float d, float area_o) {
    return ndf_samples_visible(m) ? dielectric_visible_pdf_h_l1(wo, h, d, area_o) : ndf_pdf(m, dielectric_upper(wo), h);
}

/* f(wo, wi) and, in *pdf, the density with which dielectric_sample draws wi: the pair, D(h),
 * the Fresnel factor and the projected area seen from wo found once for both
 * (dielectric_lanes.cl's formulas; the same bits as dielectric_eval and dielectric_pdf). */
inline float3 dielectric_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
    *pdf = 0.0f;
    if (dielectric_is_smooth(m)) return (float3)(0.0f);
    DielectricPair_l1 p;
    dielectric_pair_l1(m->ior, wo, wi, &p);
    if (!p.ok) return (float3)(0.0f);
    const RoughDielectric_l1 b = rough_dielectric_of(m, wo);
    const float d = ndf_D(m, p.h);
    *pdf = dielectric_pdf_at_l1(&p, dielectric_choice_l1(b.wide, p.fl), dielectric_pdf_h(m, wo, p.h, d, b.area_o));
    return dielectric_eval_at_l1(&b, wo, wi, &p, d, ndf_projected_area(m, dielectric_upper(wi)));
}

inline float3 dielectric_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (dielectric_is_smooth(m)) return (float3)(0.0f);
    DielectricPair_l1 p;
    dielectric_pair_l1(m->ior, wo, wi, &p);
    if (!p.ok) return (float3)(0.0f);
    const RoughDielectric_l1 b = rough_dielectric_of(m, wo);
    return dielectric_eval_at_l1(&b, wo, wi, &p, ndf_D(m, p.h), ndf_projected_area(m, dielectric_upper(wi)));
}

inline float dielectric_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (dielectric_is_smooth(m)) return 0.0f;
    DielectricPair_l1 p;
    dielectric_pair_l1(m->ior, wo, wi, &p);
    if (!p.ok) return 0.0f;
    const bool visible = ndf_samples_visible(m);
    const float d = visible ? ndf_D(m, p.h) : 0.0f;
    const float area_o = visible ? ndf_projected_area(m, dielectric_upper(wo)) : 0.0f;
    return dielectric_pdf_at_l1(&p, dielectric_choice(m, p.fl), dielectric_pdf_h(m, wo, p.h, d, area_o));
}

/* The smooth interface (delta lobes) whose Fresnel factor at wo is fr: reflect with
 * probability q, else refract; q in (0, 1) wherever both lobes carry (kernels/integrator/glass_choice.cl
 * chooses one toward the light). */
inline bool dielectric_sample_smooth_by(const FcMaterial* m, float3 wo, float u, float fr, float q, BsdfSample* s) {
    s->delta = 1;
    s->pdf = INFINITY;
    s->f = (float3)(0.0f);
    if (u < q) {
        s->wi = (float3)(-wo.x, -wo.y, wo.z);
        s->weight = (float3)(fr / q);
        return true;
    }
    if (!refract_about(wo, (float3)(0.0f, 0.0f, 1.0f), m->ior, &s->wi)) return false;
    if (!(s->wi.z * wo.z < 0.0f)) return false;
    float etap = relative_eta(m->ior, wo.z);
    s->weight = dielectric_tint(m) * ((1.0f - fr) / ((1.0f - q) * etap * etap));
    return all_finite(s->weight);
}

/* The smooth interface: reflect with probability dielectric_choice(F), else refract. */
inline bool dielectric_sample_smooth(const FcMaterial* m, float3 wo, float u, BsdfSample* s) {
    const float fr = fresnel_dielectric(wo.z, m->ior);
    return dielectric_sample_smooth_by(m, wo, u, fr, dielectric_choice(m, fr), s);
}

/* u.xy draws the microfacet normal, u.z chooses reflection or refraction (Walter 2007, eqs. 39
 * and 40: dielectric_lanes.cl's dielectric_scatter). */
inline bool dielectric_sample(const FcMaterial* m, float3 wo, float3 u, BsdfSample* s) {
    s->delta = 0;
    if (!(fabs(wo.z) > 0.0f)) return false;
    if (dielectric_is_smooth(m)) return dielectric_sample_smooth(m, wo, u.z, s);
    const float3 h = ndf_sample_two_sided(m, dielectric_upper(wo), u.xy);
    if (!dielectric_scatter_l1(m->ior, (m->flags & FC_MAT_WIDE_CHOICE) != 0u, wo, h, u.z, &s->wi)) return false;
    float pdf;
    const float3 f = dielectric_eval_pdf(m, wo, s->wi, &pdf);
    return finish_sample(s, f, pdf);
}

#endif
