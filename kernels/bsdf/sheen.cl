/* The sheen layer of glTF's KHR_materials_sheen: a retro-reflective fabric lobe of colour
 * S = `sheen` over the material, with roughness r = `sheen_roughness` in [0, 1]:
 *     f = f_sheen(wo, wi) + (1 - max(S) E_sheen(mu_o, r)) f_below(wo, wi),
 *     f_sheen = S D(h) V(wo, wi),
 * D the "Charlie" distribution and V its visibility with the fitted Lambda of Estevez &
 * Kulla 2017 ("Production Friendly Microfacet Sheen BRDF", SIGGRAPH talk, eqs. 2-4 and
 * Table 1), alpha = r^2 as the extension specifies:
 *     D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
 *     V = 1 / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i),
 *     Lambda(mu) = exp(L(mu)) for mu < 1/2, exp(2 L(1/2) - L(1 - mu)) otherwise,
 *     L(x) = a / (1 + b x^c) + d x + e, (a..e) interpolated between their alpha = 0 and
 *     alpha = 1 values by (1 - alpha)^2.
 * E_sheen is the lobe's directional albedo for S = 1 (albedo_tables_sheen.cl, integrated on
 * sheen_eval by tests/tools/albedo_tables.cpp). The extension's albedo scaling weights the
 * layer below by min(1 - max(S) E(mu_o), 1 - max(S) E(mu_i)); the min loses energy, so the
 * form here uses mu_o alone: a white sheen over a white base reflects everything (not
 * reciprocal, docs/brdf.md). Where the fitted lobe's albedo exceeds 1 (grazing, small r) it
 * is scaled down to 1. r is clamped below at FC_SHEEN_ROUGHNESS_MIN (the peak of D
 * at grazing becomes a delta at r = 0). Sampled by the cosine. Left out of programs for
 * scenes without sheen (FC_HAS_SHEEN). */
#ifndef FACET_BSDF_SHEEN_CL
#define FACET_BSDF_SHEEN_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/albedo_tables_sheen.cl"
#include "kernels/util/math.cl"

#define FC_SHEEN_ROUGHNESS_MIN 0.07f

/* Whether the material has a sheen layer (some channel of S above 0). */
inline bool sheen_present(const FcMaterial* m) {
#if FC_HAS_SHEEN
    return fmax(m->sheen[0], fmax(m->sheen[1], m->sheen[2])) > 0.0f;
#else
    (void)m;
    return false;
#endif
}

/* The colour S, clamped to [0, 1]. */
inline float3 sheen_color(const FcMaterial* m) { return clamp(load3p(m->sheen), 0.0f, 1.0f); }

/* r clamped to [FC_SHEEN_ROUGHNESS_MIN, 1] (NaN -> the minimum). */
inline float sheen_r(float roughness) { return clamp(fmax(roughness, FC_SHEEN_ROUGHNESS_MIN), 0.0f, 1.0f); }

/* Estevez & Kulla 2017's L(x) at alpha (Table 1: the alpha = 0 and alpha = 1 rows). */
inline float sheen_L(float x, float alpha) {
    float t = sqr(1.0f - alpha);
    float a = mix(21.5473f, 25.3245f, t), b = mix(3.82987f, 3.32435f, t), c = mix(0.19823f, 0.16801f, t);
    float d = mix(-1.97760f, -1.27393f, t), e = mix(-4.32054f, -4.85967f, t);
    return a / (1.0f + b * pow(x, c)) + d * x + e;
}

inline float sheen_lambda(float mu, float alpha) {
    return mu < 0.5f ? exp(sheen_L(mu, alpha)) : exp(2.0f * sheen_L(0.5f, alpha) - sheen_L(1.0f - mu, alpha));
}

/* D V for S = 1 at roughness r (no cosine), wo.z and wi.z > 0. */
inline float sheen_dv(float roughness, float3 wo, float3 wi) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float alpha = sqr(sheen_r(roughness));
    float3 v = wo + wi;
    float len = length(v);
    if (!(len > 0.0f)) return 0.0f;
    float cos_h = v.z / len;
    float sin2_h = fmax(1.0f - cos_h * cos_h, 0.0f);
    /* sin^(1/alpha) = (sin^2)^(1/(2 alpha)) */
    float d = (2.0f + 1.0f / alpha) * pow(sin2_h, 0.5f / alpha) / (2.0f * FC_PI);
    float vis = 1.0f / ((1.0f + sheen_lambda(wo.z, alpha) + sheen_lambda(wi.z, alpha)) * 4.0f * wo.z * wi.z);
    float f = d * vis;
    return isfinite(f) ? fmax(f, 0.0f) : 0.0f;
}

/* The table's E_sheen(mu, r) of D V alone, bilinear in its (mu, r) grid. Above 1 near
 * grazing for r below about 0.2 (up to 2.9: the fitted Lambda is not exact there). */
inline float sheen_table_albedo(float roughness, float mu) {
    float x = clamp(mu, 0.0f, 1.0f) * (float)(FC_SHEEN_N_MU - 1);
    float y = sheen_r(roughness) * (float)(FC_SHEEN_N_R - 1);
    int i = min((int)x, FC_SHEEN_N_MU - 2), j = min((int)y, FC_SHEEN_N_R - 2);
    float tx = x - (float)i, ty = y - (float)j;
    __constant const float* row = fc_albedo_sheen + j * FC_SHEEN_N_MU + i;
    return mix(mix(row[0], row[1], tx), mix(row[FC_SHEEN_N_MU], row[FC_SHEEN_N_MU + 1], tx), ty);
}

/* f_sheen = S D V / max(1, E_table(mu_o)): where the fit's lobe would reflect more than it
 * receives it is scaled down to albedo 1 (a deliberate departure, docs/brdf.md). */
inline float3 sheen_eval(const FcMaterial* m, float3 wo, float3 wi) {
    float e = sheen_table_albedo(m->sheen_roughness, wo.z);
    return sheen_color(m) * (sheen_dv(m->sheen_roughness, wo, wi) / fmax(e, 1.0f));
}

/* E_sheen(mu, r): the directional albedo of sheen_eval for S = 1, in [0, 1]. */
inline float sheen_albedo(float roughness, float mu) { return fmin(sheen_table_albedo(roughness, mu), 1.0f); }

/* The layer below's weight 1 - max(S) E_sheen(mu_o). */
inline float sheen_below_weight(const FcMaterial* m, float mu_o) {
    return clamp(1.0f - max3(sheen_color(m)) * sheen_albedo(m->sheen_roughness, mu_o), 0.0f, 1.0f);
}

#endif
