/* The anisotropic Phong BRDF of Ashikhmin & Shirley 2000 ("An Anisotropic Phong BRDF
 * Model", JGT 5(2)), eqs. 4 (specular), 5 (diffuse) and 9 (sampling):
 *
 *   f_s = sqrt((nu + 1)(nv + 1)) / (8 pi) (n.h)^((nu h_x^2 + nv h_y^2) / (1 - (n.h)^2))
 *         / ((wo.h) max(n.wo, n.wi)) F(wo.h)
 *   f_d = 28 Rd / (23 pi) (1 - F0) (1 - (1 - n.wi/2)^5) (1 - (1 - n.wo/2)^5)
 *
 * Parameters: nu = FcMaterial.exponent_x along the tangent (frame x), nv =
 * FcMaterial.exponent_y along the bitangent (y), each clamped to [0, 1e6];
 * F0 = FcMaterial.specular (Schlick's Fresnel, [0, 1]); Rd = FcMaterial.diffuse.
 * The lecture's I_spe writes shin_T for both exponents; the second must be shin_B
 * (= nv), as in the paper (docs/brdf.md). Both terms are symmetric in wo and wi. f_d
 * makes f_s + f_d energy-conserving (the 28/23 normalises f_d's albedo to Rd (1 - F0)
 * for rho_s = F0 = 0); f_s alone has albedo <= 1 for F = 1 (docs/brdf.md's table). */
#ifndef FACET_BSDF_ASHIKHMIN_SHIRLEY_CL
#define FACET_BSDF_ASHIKHMIN_SHIRLEY_CL

#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"
#include "kernels/bsdf/blinn_phong.cl"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/fresnel.cl"

inline float3 as_f0(const FcMaterial* m) { return clamp(load3p(m->specular), 0.0f, 1.0f); }

/* The exponent nu cos^2(phi_h) + nv sin^2(phi_h) of a half vector (any value at h = n,
 * where (n.h)^exponent = 1). */
inline float as_exponent(float nu, float nv, float3 h) {
    float x2 = h.x * h.x;
    float y2 = h.y * h.y;
    float s2 = x2 + y2;
    return (s2 > 0.0f) ? (nu * x2 + nv * y2) / s2 : 0.5f * (nu + nv);
}

/* p(h) = sqrt((nu + 1)(nv + 1)) / (2 pi) (n.h)^exponent (paper section 3, eq. 9). */
inline float as_half_vector_pdf(float nu, float nv, float3 h) {
    return sqrt((nu + 1.0f) * (nv + 1.0f)) * (0.5f * FC_INV_PI) * fc_pow_cos(h.z, as_exponent(nu, nv, h));
}

inline float3 ashikhmin_shirley_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    float nu = fc_phong_exponent(m->exponent_x);
    float nv = fc_phong_exponent(m->exponent_y);
    float3 h = normalize(wo + wi);
    float wo_h = dot(wo, h);
    if (!(wo_h > 0.0f)) return (float3)(0.0f);
    float d = as_half_vector_pdf(nu, nv, h);     /* = sqrt(..)/(2 pi) (n.h)^.. */
    float v = 0.25f / (wo_h * fmax(wo.z, wi.z)); /* 1/8 = (1/2)(1/4) */
    float3 f = fresnel_schlick(as_f0(m), wo_h) * (d * v);
    return all_finite(f) ? f : (float3)(0.0f);
}

inline float ashikhmin_shirley_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float nu = fc_phong_exponent(m->exponent_x);
    float nv = fc_phong_exponent(m->exponent_y);
    float3 h = normalize(wo + wi);
    float wo_h = dot(wo, h);
    if (!(wo_h > 0.0f)) return 0.0f;
    float pdf = as_half_vector_pdf(nu, nv, h) / (4.0f * wo_h);
    return isfinite(pdf) ? pdf : 0.0f;
}

inline bool ashikhmin_shirley_sample(const FcMaterial* m, float3 wo, float2 u, BsdfSample* s) {
    s->delta = 0;
    if (wo.z <= 0.0f) return false;
    float nu = fc_phong_exponent(m->exponent_x);
    float nv = fc_phong_exponent(m->exponent_y);
    /* phi_h in the first quadrant from eq. 9, tan(phi) = sqrt((nu+1)/(nv+1)) tan(pi u/2),
     * as atan2 (no tan(pi/2)); u1 in quarters picks the quadrant (mirrored, continuous) */
    float q = fmin(4.0f * u.x, FC_ONE_MINUS_EPSILON * 4.0f);
    int quadrant = (int)q;
    float uq = q - (float)quadrant;
    if (quadrant == 1 || quadrant == 3) uq = 1.0f - uq;
    float t = 0.5f * FC_PI * uq;
    float phi = atan2(sqrt(nu + 1.0f) * sin(t), sqrt(nv + 1.0f) * cos(t));
    if (quadrant == 1) phi = FC_PI - phi;
    else if (quadrant == 2) phi = FC_PI + phi;
    else if (quadrant == 3) phi = 2.0f * FC_PI - phi;
    float cos_phi = cos(phi);
    float sin_phi = sin(phi);
    /* cos(theta_h) = (1 - u2)^(1/(nu cos^2 + nv sin^2 + 1)), in log form */
    float n = nu * cos_phi * cos_phi + nv * sin_phi * sin_phi;
    float lg = log1p(-u.y) / (n + 1.0f);
    float cos_h = exp(lg);
    float sin_h = safe_sqrt(-expm1(2.0f * lg));
    float3 h = (float3)(sin_h * cos_phi, sin_h * sin_phi, cos_h);
    if (!reflect_about(wo, h, &s->wi)) return false;
    return finish_sample(s, ashikhmin_shirley_eval(m, wo, s->wi), ashikhmin_shirley_pdf(m, wo, s->wi));
}

/* The paper's eq. 5 diffuse term, which pairs with the specular lobe above. */
inline float3 ashikhmin_shirley_diffuse_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    float3 rd = fmax(load3p(m->diffuse), (float3)(0.0f));
    float a = 1.0f - pow5(1.0f - 0.5f * fmin(wi.z, 1.0f));
    float b = 1.0f - pow5(1.0f - 0.5f * fmin(wo.z, 1.0f));
    return rd * ((float3)(1.0f) - as_f0(m)) * ((28.0f / (23.0f * FC_PI)) * a * b);
}

#endif
