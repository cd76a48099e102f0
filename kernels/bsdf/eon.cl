/* EON, the energy-preserving Oren-Nayar model (Portsmouth, Kutz & Hill 2024, "EON: A
 * practical energy-preserving rough diffuse BRDF", JCGT 14(1); the diffuse model of
 * OpenPBR), FC_DIFFUSE_EON:
 *
 *   f = f_ss + f_ms
 *   f_ss = rho/pi A (1 + r s/t)              Fujii's Oren-Nayar ("FON"), A = 1 / (1 + c1 r),
 *        s = wi.wo - mu_i mu_o, s/t = s / max(mu_i, mu_o) for s > 0, else s
 *   f_ms = rho_ms/pi (1 - E(mu_o)) (1 - E(mu_i)) / (1 - E_avg)   (Kulla-Conty style)
 *   E(mu) = A + (r A / pi) G(mu),  G = S (acos mu - S mu) + 2/3 ((S / mu)(1 - S^3) - S),
 *        S = sqrt(1 - mu^2): f_ss's exact albedo at rho = 1 (the paper's eq. 11)
 *   E_avg = A (1 + c2 r),  rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg))
 *   c1 = 1/2 - 2/(3 pi), c2 = 2/3 - 28/(15 pi).
 *
 * Parameters: rho = FcMaterial.diffuse ([0, 1]), r = FcMaterial.sigma read as EON's
 * roughness in [0, 1] (clamped; NaN -> 0, which is Lambert). Symmetric in wo and wi; at
 * rho = 1 its albedo is exactly 1.
 *
 * Importance sampling (the paper's section 5): with probability P_u(mu_o, r) uniform
 * hemisphere directions, else "clipped linearly transformed cosine" (CLTC) directions: a
 * cosine lobe clipped so that its image under the 3x3 LTC matrix M = [[a, 0, b], [0, c, 0],
 * [d, 0, 1]] (fitted polynomials in mu_o and r) is the upper hemisphere, sampled in the
 * frame whose x axis is wo's azimuth. pdf = P_u / (2 pi) + (1 - P_u) pdf_cltc. */
#ifndef FACET_BSDF_EON_CL
#define FACET_BSDF_EON_CL

#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

#define FC_EON_C1 0.28779341f /* 1/2 - 2/(3 pi) */
#define FC_EON_C2 0.07248821f /* 2/3 - 28/(15 pi) */

inline float eon_roughness(const FcMaterial* m) { return (m->sigma > 0.0f) ? fmin(m->sigma, 1.0f) : 0.0f; }

/* E(mu): f_ss's albedo at rho = 1, with (S / mu)(1 - S^3) = S mu (1 + S + S^2) / (1 + S)
 * free of cancellation at grazing mu. */
inline float eon_fon_albedo(float mu, float r) {
    mu = clamp(mu, 0.0f, 1.0f);
    float a = 1.0f / (1.0f + FC_EON_C1 * r);
    float s = safe_sqrt(1.0f - mu * mu);
    float g = s * (acos(mu) - s * mu) + (2.0f / 3.0f) * (s * mu * (1.0f + s + s * s) / (1.0f + s) - s);
    return a + (r * a * FC_INV_PI) * g;
}

inline float3 eon_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return (float3)(0.0f);
    float3 rho = clamp(load3p(m->diffuse), 0.0f, 1.0f);
    float r = eon_roughness(m);
    float a = 1.0f / (1.0f + FC_EON_C1 * r);
    /* single scattering (FON) */
    float s = dot(wi, wo) - wi.z * wo.z;
    float s_over_t = s > 0.0f ? s / fmax(wi.z, wo.z) : s;
    float3 f = rho * (FC_INV_PI * a * fmax(1.0f + r * s_over_t, 0.0f));
    /* multiple scattering */
    float e_avg = a * (1.0f + FC_EON_C2 * r);
    float loss = 1.0f - e_avg;
    if (loss > 1e-7f) {
        float3 rho_ms = rho * rho * e_avg / ((float3)(1.0f) - rho * loss);
        float k = fmax(1.0f - eon_fon_albedo(wo.z, r), 0.0f) * fmax(1.0f - eon_fon_albedo(wi.z, r), 0.0f) / loss;
        f += rho_ms * (FC_INV_PI * k);
    }
    return all_finite(f) ? fmax(f, (float3)(0.0f)) : (float3)(0.0f);
}

/* The LTC matrix coefficients a, b, c, d for mu_o and r (the paper's fitted forms). */
inline float4 eon_ltc_terms(float mu, float r) {
    float a = 1.0f + r * (0.303392f + (-0.518982f + 0.111709f * mu) * mu + (-0.276266f + 0.335918f * mu) * r);
    float b = r * (-1.16407f + 1.15859f * mu + (0.150815f - 0.150105f * mu) * r) / (mu * mu * mu - 1.43545f);
    float c = 1.0f + (0.20013f + (-0.506373f + 0.261777f * mu) * mu) * r;
    float d = ((0.540852f + (-1.01625f + 0.475392f * mu) * mu) * r) / (-1.0743f + mu * (0.0725628f + mu));
    return (float4)(a, b, c, d);
}

/* The probability of the uniform part of the mixture. */
inline float eon_uniform_probability(float mu, float r) {
    if (!(r > 0.0f)) return 0.0f;
    return clamp(pow(r, 0.1f) * (0.162925f + mu * (-0.372058f + (0.538233f - 0.290822f * mu) * mu)), 0.0f, 1.0f);
}

/* The x axis of the LTC frame: wo's azimuth (x when wo is the normal). */
inline float2 eon_frame_x(float3 wo) {
    float len2 = wo.x * wo.x + wo.y * wo.y;
    return len2 > 0.0f ? (float2)(wo.x, wo.y) * rsqrt(len2) : (float2)(1.0f, 0.0f);
}

/* The CLTC density of wi (local frame). */
inline float eon_cltc_pdf(float3 wo, float3 wi, float r) {
    float2 x = eon_frame_x(wo);
    float3 w = (float3)(x.x * wi.x + x.y * wi.y, -x.y * wi.x + x.x * wi.y, wi.z);
    float4 t = eon_ltc_terms(wo.z, r);
    float det = t.z * (t.x - t.y * t.w);
    /* adj(M) w = det M^-1 w */
    float3 h = (float3)(t.z * (w.x - t.y * w.z), (t.x - t.y * t.w) * w.y, -t.z * (t.w * w.x - t.x * w.z));
    float lensq = dot(h, h);
    if (!(lensq > 0.0f) || !(det > 0.0f)) return 0.0f;
    float s = 0.5f * (1.0f + rsqrt(t.w * t.w + 1.0f));
    return sqr(det / lensq) * fmax(h.z, 0.0f) / (FC_PI * s);
}

inline float eon_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float r = eon_roughness(m);
    float pu = eon_uniform_probability(wo.z, r);
    float pdf = pu * (0.5f * FC_INV_PI) + (1.0f - pu) * eon_cltc_pdf(wo, wi, r);
    return isfinite(pdf) ? fmax(pdf, 0.0f) : 0.0f;
}

/* A direction from EON's sampling mixture; false when none was made. */
inline bool eon_sample(const FcMaterial* m, float3 wo, float2 u, float3* wi) {
    if (!(wo.z > 0.0f)) return false;
    float r = eon_roughness(m);
    float pu = eon_uniform_probability(wo.z, r);
    if (u.x < pu) {
        /* uniform on the hemisphere */
        float z = u.x / pu;
        float st = safe_sqrt(1.0f - z * z);
        float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
        *wi = (float3)(st * sc.y, st * sc.x, z);
    } else {
        /* a clipped cosine lobe (a disk warped as in Heitz 2018), then M */
        float ux = fmin((u.x - pu) / (1.0f - pu), FC_ONE_MINUS_EPSILON);
        float4 t = eon_ltc_terms(wo.z, r);
        float rad = sqrt(ux);
        float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
        float x = rad * sc.y, y = rad * sc.x;
        float s = 0.5f * (1.0f + rsqrt(t.w * t.w + 1.0f));
        x = -mix(safe_sqrt(1.0f - y * y), x, s);
        float3 h = (float3)(x, y, safe_sqrt(1.0f - (x * x + y * y)));
        float3 w = (float3)(t.x * h.x + t.y * h.z, t.z * h.y, t.w * h.x + h.z);
        float2 fx = eon_frame_x(wo);
        *wi = normalize_or((float3)(fx.x * w.x - fx.y * w.y, fx.y * w.x + fx.x * w.y, w.z), (float3)(0.0f));
    }
    return wi->z > 0.0f;
}

#endif
