/* The microfacet specular lobe (FC_SPECULAR_MICROFACET):
 *     f(wo, wi) = D(h) G(wo, wi, h) F(wo.h) / (4 cos_o cos_i),  h = normalize(wo + wi)
 * (Cook & Torrance 1982; Walter et al. 2007, eq. 20), with D, G and F chosen
 * independently (ndf.cl, geometry.cl, fresnel.cl). Sampling draws h from the NDF
 * (visible or all normals, ndf.cl) and reflects wo; the density of wi is
 * pdf_h(h) / (4 |wo.h|) (Walter 2007, eq. 14).
 *
 * Numerical policy (docs/brdf.md):
 * - Ranges: alpha from 1e-7 to 1, anisotropy ratio up to 1e4, Blinn-Phong exponents up
 *   to 2e14, cosines down to 1e-7, wi = +-wo, ior 1 to 20, conductor eta up to 20 and k
 *   up to 10. Every output is finite, f >= 0, pdf >= 0 for all of them.
 * - Mirror limit: below FC_ALPHA_MIRROR (max(alpha_x, alpha_y), or Blinn-Phong's
 *   equivalent alpha) the lobe IS a perfect mirror: eval and pdf give 0, sample gives
 *   the mirror direction with delta = 1, pdf = INFINITY and weight = F(cos_o) (the
 *   limit of G -> 1 as alpha -> 0). At and above it everything is evaluated exactly:
 *   alpha is never clamped.
 * - No float overflow for tiny alphas: D is written in stretched forms (x/ax, y/ay),
 *   Lambda without cancellation (ggx.cl, beckmann.cl), Blinn-Phong's cos^e through
 *   log1p(tan^2). No pow of a negative base. No division that can reach 0: every
 *   denominator is tested or bounded away from 0 by the ranges above (wo.z, wi.z >= 1e-7
 *   make |wo + wi| >= 2e-7).
 * - Degenerate half vectors (wo + wi of zero length, wi = -wo) give f = 0 and pdf = 0;
 *   wo or wi at or below the horizon give 0.
 * - A sampled wi at or below the horizon is refused (sample returns false); so is a
 *   sample whose recomputed pdf is 0. f and pdf of a sample are exactly what eval and
 *   pdf return for its wi (recomputed from wo + wi), so weight = f cos_i / pdf is
 *   G F / G1(wo) for visible-normal sampling: at most 1 for F = 1 and the exact Smith
 *   terms, separable or height-correlated (Heitz 2014, section 6).
 * - No fast or finite math anywhere (docs/conventions.md): NaN/Inf tests must hold.
 *
 * Energy compensation (FC_MAT_ENERGY_COMPENSATION, GGX / Beckmann with height-correlated
 * Smith): f adds Kulla & Conty's multiple-scattering lobe f_ms (energy_compensation.cl),
 * and sampling becomes a mixture: with probability p = 1 - E(mu_o) a cosine-weighted
 * direction, else the NDF's; pdf = p cos_i / pi + (1 - p) pdf_ss. The weight bound
 * above then no longer holds (f_ms is not importance-sampled exactly). */
#ifndef FACET_BSDF_MICROFACET_CL
#define FACET_BSDF_MICROFACET_CL

#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/geometry.cl"
#include "kernels/bsdf/lambert.cl"
#include "kernels/bsdf/ndf.cl"

inline bool microfacet_is_mirror(const FcMaterial* m) {
    float2 a = ndf_alpha(m);
    return !(fmax(a.x, a.y) >= FC_ALPHA_MIRROR); /* NaN roughness: a mirror too */
}

/* The half vector of wo and wi (both above the surface) and |wo + wi| / 2 = wo.h;
 * false when it is degenerate. */
inline bool microfacet_half_vector(float3 wo, float3 wi, float3* h, float* wo_h) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return false;
    float3 v = wo + wi;
    float len = length(v);
    if (!(len > 0.0f) || !isfinite(len)) return false;
    *h = v / len;
    *wo_h = 0.5f * len;
    return true;
}

/* The BRDF at wi of half vector h, where D(h) = d and the projected area seen from wo is
 * area_o (read where geometry_uses_area). */
inline float3 microfacet_eval_at(const FcMaterial* m, float3 wo, float3 wi, float3 h, float d, float area_o) {
    float3 f = ec_enabled(m) ? ec_ms_eval(m, wo, wi) : (float3)(0.0f);
    if (!(d > 0.0f)) return all_finite(f) ? f : (float3)(0.0f); /* D underflows far from a narrow peak */
    /* G / (4 cos_o cos_i); the implicit G cancels the denominator exactly. */
    float g_over =
        (m->geometry == FC_G_IMPLICIT) ? 0.25f : geometry_G_area(m, wo, wi, h, area_o) / (4.0f * wo.z * wi.z);
    f += fresnel_eval(m, dot(wo, h)) * (d * g_over);
    return all_finite(f) ? fmax(f, (float3)(0.0f)) : (float3)(0.0f);
}

inline float3 microfacet_eval(const FcMaterial* m, float3 wo, float3 wi) {
    float3 h;
    float wo_h;
    if (microfacet_is_mirror(m) || !microfacet_half_vector(wo, wi, &h, &wo_h)) return (float3)(0.0f);
    return microfacet_eval_at(m, wo, wi, h, ndf_D(m, h), geometry_uses_area(m) ? ndf_projected_area(m, wo) : 0.0f);
}

/* The density of the NDF's sampling, for wi of half vector h (wo.h = wo_h), D(h) = d and the
 * projected area seen from wo area_o (read for unbounded visible normals only): ndf_pdf(h) /
 * (4 wo.h); for visible normals the factor wo.h cancels analytically, D(h) / (4 wo.z (1 +
 * Lambda(wo))), which keeps f cos / pdf = G F / G1(wo) <= 1 in float even where wo.h suffers
 * cancellation (wi ~ -wo at grazing angles). */
inline float microfacet_ss_pdf_at(const FcMaterial* m, float3 wo, float3 h, float wo_h, float d, float area_o) {
    return ndf_samples_visible(m) ? ndf_reflection_pdf_visible_at(m, wo, h, d, area_o)
                                  : ndf_pdf(m, wo, h) / (4.0f * wo_h);
}

/* Whether the NDF's sampling density reads D(h) and the projected area seen from wo. */
inline bool microfacet_pdf_uses_area(const FcMaterial* m) { return ndf_samples_visible(m) && !ndf_samples_bounded(m); }

/* The lobe's density at wi from its NDF sampler's density q there: with compensation, the
 * cosine-sampled multiple-scattering lobe's share mixed in. */
inline float microfacet_pdf_from(const FcMaterial* m, float3 wo, float3 wi, float q) {
    if (ec_enabled(m)) {
        float p = ec_ms_probability(m, wo);
        q = p * cosine_hemisphere_pdf(wo, wi) + (1.0f - p) * q;
    }
    return isfinite(q) ? fmax(q, 0.0f) : 0.0f;
}

inline float microfacet_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    float3 h;
    float wo_h;
    if (microfacet_is_mirror(m) || !microfacet_half_vector(wo, wi, &h, &wo_h)) return 0.0f;
    const bool area = microfacet_pdf_uses_area(m);
    return microfacet_pdf_from(
        m, wo, wi,
        microfacet_ss_pdf_at(m, wo, h, wo_h, area ? ndf_D(m, h) : 0.0f, area ? ndf_projected_area(m, wo) : 0.0f));
}

/* microfacet_eval's value, and microfacet_pdf's in *pdf, at once: the half vector, D(h) and
 * the projected area seen from wo (Smith's G and the visible normals' density) found once for
 * both (the same operations, so the same bits as the two calls). */
inline float3 microfacet_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
    float3 h;
    float wo_h;
    *pdf = 0.0f;
    if (microfacet_is_mirror(m) || !microfacet_half_vector(wo, wi, &h, &wo_h)) return (float3)(0.0f);
    const float d = ndf_D(m, h);
    const float area_o = geometry_uses_area(m) || microfacet_pdf_uses_area(m) ? ndf_projected_area(m, wo) : 0.0f;
    *pdf = microfacet_pdf_from(m, wo, wi, microfacet_ss_pdf_at(m, wo, h, wo_h, d, area_o));
    return microfacet_eval_at(m, wo, wi, h, d, area_o);
}

inline bool microfacet_sample(const FcMaterial* m, float3 wo, float2 u, BsdfSample* s) {
    s->delta = 0;
    if (!(wo.z > 0.0f)) return false;
    if (microfacet_is_mirror(m)) {
        s->wi = (float3)(-wo.x, -wo.y, wo.z);
        s->delta = 1;
        s->pdf = INFINITY;
        s->f = (float3)(0.0f);
        s->weight = fresnel_eval(m, wo.z);
        return true;
    }
    /* With compensation, the multiple-scattering lobe's share by cosine sampling. */
    float p = ec_enabled(m) ? ec_ms_probability(m, wo) : 0.0f;
    if (u.x < p) {
        s->wi = square_to_cosine_hemisphere((float2)(u.x / p, u.y));
        if (!(s->wi.z > 0.0f)) return false;
    } else {
        u.x = fmin((u.x - p) / (1.0f - p), FC_ONE_MINUS_EPSILON);
        /* Draw a normal, reflect wo about it (Walter 2007, eq. 39). */
        if (!reflect_about(wo, ndf_sample(m, wo, u), &s->wi)) return false;
    }
    float pdf;
    const float3 f = microfacet_eval_pdf(m, wo, s->wi, &pdf);
    return finish_sample(s, f, pdf);
}

#endif
