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
 * wi = -wo at eta ~ 1) and wo or wi on the surface (z = 0) give f = 0 and pdf = 0. */
#ifndef FACET_BSDF_DIELECTRIC_CL
#define FACET_BSDF_DIELECTRIC_CL

#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/ndf.cl"
#include "kernels/bsdf/refraction.cl"
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
inline float3 dielectric_upper(float3 w) { return w.z < 0.0f ? -w : w; }

/* Shadowing-masking for both sides, Lambda of |w.z|: 1 + Lambda(w) as the projected area
 * seen from w turned up over |w.z| (geometry.cl), with area_o = ndf_projected_area(m,
 * dielectric_upper(wo)), which the visible normals' density divides by too. */
inline float dielectric_G_area(const FcMaterial* m, float3 wo, float3 wi, float area_o) {
    float lo = area_o / fabs(wo.z);
    float li = ndf_projected_area(m, dielectric_upper(wi)) / fabs(wi.z);
    if (m->geometry == FC_G_SMITH_SEPARABLE) return 1.0f / (lo * li);
    return 1.0f / (lo + li - 1.0f);
}

/* The (generalised) half vector of wo and wi, on the +z side, and etap = n_i / n_o
 * (1 for a reflection) and |wo + etap wi|; false when degenerate or when wo or wi sees
 * the back of h. */
typedef struct {
    float3 h;
    float etap;
    float len;
    bool reflect;
} DielectricPair;

inline bool dielectric_pair(const FcMaterial* m, float3 wo, float3 wi, DielectricPair* p) {
    float co = wo.z, ci = wi.z;
    if (!(fabs(co) > 0.0f) || !(fabs(ci) > 0.0f)) return false;
    p->reflect = co * ci > 0.0f;
    p->etap = p->reflect ? 1.0f : relative_eta(m->ior, co);
    float3 v = wo + p->etap * wi;
    p->len = length(v);
    if (!(p->len > 0.0f) || !isfinite(p->len)) return false;
    p->h = v / p->len;
    if (p->h.z < 0.0f) p->h = -p->h;
    return dot(p->h, wi) * ci > 0.0f && dot(p->h, wo) * co > 0.0f;
}

/* The Fresnel factor of the pair's lobe: F for a reflection; for a refraction 1 - F,
 * as the transmittance of the pair's two cosines (well conditioned near the critical
 * angle, and reciprocal). */
inline float dielectric_lobe_fresnel(const FcMaterial* m, const DielectricPair* p, float oh, float ih) {
    if (p->reflect) return fresnel_dielectric(oh, m->ior);
    return fresnel_dielectric_transmittance(fabs(oh), fabs(ih), p->etap);
}

/* The density of h seen from wo (either side): the NDF's, for wo turned to +z; d = D(h) and
 * area_o = ndf_projected_area(m, dielectric_upper(wo)) are read for visible normals only. */
inline float dielectric_pdf_h_at(const FcMaterial* m, float3 wo, float3 h, float d, float area_o) {
    float3 wv = dielectric_upper(wo);
    if (ndf_samples_visible(m)) return d * fmax(dot(wv, h), 0.0f) / area_o;
    return ndf_pdf(m, wv, h);
}

/* The BSDF of the pair p (oh = wo.h, ih = wi.h, fl its lobe's Fresnel factor) where D(h) = d,
 * area_o as dielectric_G_area takes it. */
inline float3 dielectric_eval_at(const FcMaterial* m, float3 wo, float3 wi, const DielectricPair* p, float d, float oh,
                                 float ih, float fl, float area_o) {
    if (!(d > 0.0f)) return (float3)(0.0f);
    float g = dielectric_G_area(m, wo, wi, area_o);
    float3 f;
    if (p->reflect) {
        f = (float3)(d * g * fl / (4.0f * fabs(wo.z) * fabs(wi.z)));
    } else {
        /* Eq. 21 as the BTDF of importance (no scaling, pbrt-v4's Importance mode),
         * (1 - F) D G |wi.h| |wo.h| etap^2 / (|cos_i| |cos_o| |wo + etap wi|^2), times the
         * radiance scaling 1 / etap^2 (|wo + etap wi| = |n_i wi.h + n_o wo.h| / n_o). */
        float importance =
            fl * d * g * fabs(ih * oh) / (fabs(wi.z) * fabs(wo.z)) * (p->etap * p->etap) / (p->len * p->len);
        f = dielectric_tint(m) * (importance / (p->etap * p->etap));
    }
    if (ec_enabled(m)) f /= ec_dielectric_albedo(m, wo); /* Turquin 2019 (energy_compensation.cl) */
    return all_finite(f) ? fmax(f, (float3)(0.0f)) : (float3)(0.0f);
}

/* The probability of choosing the lobe whose Fresnel factor is fl (F for the reflection, 1 - F for
 * the refraction): fl itself; with FC_MAT_WIDE_CHOICE (scenes whose light is not uniform), fl raised toward
 * FC_DIELECTRIC_MIN_CHOICE by at most a factor of 4 and lowered to match on the other side, so that the two choices add
 * to 1 and a lobe that carries nothing (F = 0, total internal reflection's refraction) is never chosen: q = clamp(fl,
 * min(Q, 4 fl), 1 - min(Q, 4 (1 - fl))). Choosing by F alone (pbrt-v4, Mitsuba 3) picks a glass ball's reflection of
 * the sun once in 25 at normal incidence, each time carrying the sun's whole radiance: once the caustics are sampled,
 * the brightest fireflies of glass_metal_sky (docs/sampling.md, "Sampling toward glass"). F's own choice stays where
 * the light is uniform (a constant environment alone, the white furnace), where it is exact: every sample weighs 1. */
#ifndef FC_DIELECTRIC_MIN_CHOICE
#define FC_DIELECTRIC_MIN_CHOICE 0.25f
#endif
inline float dielectric_choice(const FcMaterial* m, float fl) {
    fl = clamp(fl, 0.0f, 1.0f);
    if (!(m->flags & FC_MAT_WIDE_CHOICE)) return fl;
    return clamp(fl, fmin(FC_DIELECTRIC_MIN_CHOICE, 4.0f * fl),
                 1.0f - fmin(FC_DIELECTRIC_MIN_CHOICE, 4.0f * (1.0f - fl)));
}

/* The density of wi for the pair p, from h's density pdf_h (fl: the lobe's Fresnel factor, which
 * dielectric_choice turns into the lobe's probability). */
inline float dielectric_pdf_at(const FcMaterial* m, const DielectricPair* p, float oh, float ih, float fl,
                               float pdf_h) {
    const float q = dielectric_choice(m, fl);
    float pdf =
        p->reflect ? q * pdf_h / (4.0f * fabs(oh)) : q * pdf_h * (p->etap * p->etap) * fabs(ih) / (p->len * p->len);
    return isfinite(pdf) ? fmax(pdf, 0.0f) : 0.0f;
}

inline float3 dielectric_eval(const FcMaterial* m, float3 wo, float3 wi) {
    DielectricPair p;
    if (dielectric_is_smooth(m) || !dielectric_pair(m, wo, wi, &p)) return (float3)(0.0f);
    float d = ndf_D(m, p.h);
    if (!(d > 0.0f)) return (float3)(0.0f);
    float oh = dot(wo, p.h), ih = dot(wi, p.h);
    return dielectric_eval_at(m, wo, wi, &p, d, oh, ih, dielectric_lobe_fresnel(m, &p, oh, ih),
                              ndf_projected_area(m, dielectric_upper(wo)));
}

inline float dielectric_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    DielectricPair p;
    if (dielectric_is_smooth(m) || !dielectric_pair(m, wo, wi, &p)) return 0.0f;
    float oh = dot(wo, p.h), ih = dot(wi, p.h);
    float fl = dielectric_lobe_fresnel(m, &p, oh, ih);
    const bool visible = ndf_samples_visible(m);
    float d = visible ? ndf_D(m, p.h) : 0.0f;
    float area_o = visible ? ndf_projected_area(m, dielectric_upper(wo)) : 0.0f;
    return dielectric_pdf_at(m, &p, oh, ih, fl, dielectric_pdf_h_at(m, wo, p.h, d, area_o));
}

/* dielectric_eval's value and dielectric_pdf's in *pdf at once: the pair, D(h), the Fresnel
 * factor and the projected area seen from wo found once for both (the same bits as the two
 * calls). */
inline float3 dielectric_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
    DielectricPair p;
    *pdf = 0.0f;
    if (dielectric_is_smooth(m) || !dielectric_pair(m, wo, wi, &p)) return (float3)(0.0f);
    float d = ndf_D(m, p.h);
    float oh = dot(wo, p.h), ih = dot(wi, p.h);
    float fl = dielectric_lobe_fresnel(m, &p, oh, ih);
    float area_o = ndf_projected_area(m, dielectric_upper(wo));
    *pdf = dielectric_pdf_at(m, &p, oh, ih, fl, dielectric_pdf_h_at(m, wo, p.h, d, area_o));
    return dielectric_eval_at(m, wo, wi, &p, d, oh, ih, fl, area_o);
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

/* u.xy draws the microfacet normal, u.z chooses reflection or refraction. */
inline bool dielectric_sample(const FcMaterial* m, float3 wo, float3 u, BsdfSample* s) {
    s->delta = 0;
    if (!(fabs(wo.z) > 0.0f)) return false;
    if (dielectric_is_smooth(m)) return dielectric_sample_smooth(m, wo, u.z, s);
    float3 wv = wo.z < 0.0f ? -wo : wo;
    float3 h = ndf_sample_two_sided(m, wv, u.xy);
    float oh = dot(wo, h);
    if (u.z < dielectric_choice(m, fresnel_dielectric(oh, m->ior))) {
        s->wi = 2.0f * oh * h - wo; /* Walter 2007, eq. 39 */
        if (!(s->wi.z * wo.z > 0.0f)) return false;
    } else {
        if (!refract_about(wo, h, m->ior, &s->wi)) return false; /* eq. 40 */
        if (!(s->wi.z * wo.z < 0.0f)) return false;
    }
    float pdf;
    const float3 f = dielectric_eval_pdf(m, wo, s->wi, &pdf);
    return finish_sample(s, f, pdf);
}

#endif
