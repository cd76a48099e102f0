/* The Blinn-Phong specular lobes (FcMaterial.specular_model):
 *
 *   FC_SPECULAR_BLINN_PHONG             f = Ks (n.h)^e / pi              (Blinn 1977)
 *   FC_SPECULAR_BLINN_PHONG_NORMALIZED  f = Ks (e + 8) / (8 pi) (n.h)^e  (Akenine-Moller,
 *                                        Haines & Hoffman 2008, "Real-Time Rendering" 3rd ed.)
 *
 * Ks = FcMaterial.specular (colour, [0, 1]); e = FcMaterial.exponent_x, the shininess,
 * clamped to [0, 1e6] (NaN -> 0): beyond 1e6 the lobe is narrower than float
 * directions resolve near the normal. These are the lecture's I_spe = (N.L) Ks (N.H)^e
 * and (N.L) Ks (e + 8)/8 (N.H)^e under f = I / (pi N.L) (docs/brdf.md).
 * The original lobe is not normalised (its albedo falls as e grows); the normalised
 * one has albedo near Ks at normal incidence. Both are reciprocal.
 *
 * Sampling: the half vector with density p(h) = D_BP(h) (n.h) = (e + 2)/(2 pi) (n.h)^(e+1)
 * (cos theta_h = u1^(1/(e+2)), phi_h = 2 pi u2), reflected about h;
 * pdf(wi) = p(h) / (4 |wo.h|) (Torrance & Sparrow's Jacobian, Walter et al. 2007 eq. 14). */
#ifndef FACET_BSDF_BLINN_PHONG_CL
#define FACET_BSDF_BLINN_PHONG_CL

#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/util/trig.cl"

/* A Phong-style exponent clamped to [0, FC_PHONG_EXPONENT_MAX]; NaN gives 0. */
inline float fc_phong_exponent(float e) { return (e > 0.0f) ? fmin(e, FC_PHONG_EXPONENT_MAX) : 0.0f; }

/* cos^e for cos in [0, 1]; 0 for cos <= 0 (never a pow of a negative base). */
inline float fc_pow_cos(float c, float e) { return (c > 0.0f) ? pow_positive(fmin(c, 1.0f), e) : 0.0f; }

/* The lobe at half vector h (wo, wi above the surface): its value, and through
 * *pdf its density (cos^(e+1) as cos^e cos: the one pow serves both). */
inline float3 blinn_phong_at(const FcMaterial* m, float3 wo, float3 h, float* pdf) {
    float e = fc_phong_exponent(m->exponent_x);
    float3 ks = fmax(load3p(m->specular), (float3)(0.0f));
    float cos_e = fc_pow_cos(h.z, e);
    float scale =
        (m->specular_model == FC_SPECULAR_BLINN_PHONG_NORMALIZED) ? (e + 8.0f) * (0.125f * FC_INV_PI) : FC_INV_PI;
    float wo_h = dot(wo, h);
    float p_h = (e + 2.0f) * (0.5f * FC_INV_PI) * (cos_e * fmin(h.z, 1.0f));
    float p = p_h / (4.0f * wo_h);
    *pdf = (wo_h > 0.0f && isfinite(p)) ? p : 0.0f;
    return ks * (scale * cos_e);
}

inline float3 blinn_phong_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    float pdf;
    /* wo + wi is never zero with both above the surface */
    return blinn_phong_at(m, wo, normalize(wo + wi), &pdf);
}

inline float blinn_phong_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float pdf;
    blinn_phong_at(m, wo, normalize(wo + wi), &pdf);
    return pdf;
}

inline bool blinn_phong_sample(const FcMaterial* m, float3 wo, float2 u, BsdfSample* s) {
    s->delta = 0;
    if (wo.z <= 0.0f) return false;
    float e = fc_phong_exponent(m->exponent_x);
    /* the half vector: cos^(e+2) = u1 in log form, sin^2 = 1 - cos^2 without cancellation */
    float lg = log(u.x) / (e + 2.0f);
    float cos_h = exp(lg);
    float sin_h = safe_sqrt(-expm1(2.0f * lg));
    float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
    float3 h = (float3)(sin_h * sc.y, sin_h * sc.x, cos_h);
    if (!reflect_about(wo, h, &s->wi)) return false;
    float pdf;
    float3 f = blinn_phong_at(m, wo, normalize(wo + s->wi), &pdf);
    return finish_sample(s, f, pdf);
}

#endif
