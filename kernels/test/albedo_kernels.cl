/* Kernels of the albedo-table tool (tests/tools/albedo_tables.cpp) and of
 * tests/energy_compensation_test.cpp: directional albedos integrated on the BSDF kernels.
 *
 * albedo_table: one work-item per (r, mu) node of a table; E(mu) = int f_ss cos dwi with
 * F = 1 and E5(mu) with F = (1 - wo.h)^5, both with height-correlated Smith G and no
 * compensation, by visible-normal sampling (Heitz 2018 for GGX, the oracle) on a
 * Hammersley point set of `samples` points (Cranley-Patterson rotated per node). */
#include "kernels/bsdf/bsdf.cl"
#include "kernels/bsdf/microfacet.cl"
#include "kernels/util/rng.cl"
#include "kernels/util/sampler.cl"

/* Kahan-compensated float sums (no fp64 is assumed of the device). */
typedef struct {
    float3 sum, c;
} KahanSum3;

inline void kahan_add(KahanSum3* k, float3 v) {
    float3 y = v - k->c;
    float3 t = k->sum + y;
    k->c = (t - k->sum) - y;
    k->sum = t;
}

/* The roughness and cosine of table node (j, i): r = j / (n_r - 1) (alpha = r^2, at least
 * just above the mirror limit), mu = i / (n_mu - 1) (at least 1e-3: the limit mu -> 0). */
__kernel void albedo_table(int ndf, int n_mu, int n_r, uint samples, __global float2* out) {
    int id = (int)get_global_id(0);
    if (id >= n_mu * n_r) return;
    int i = id % n_mu, j = id / n_mu;
    float r = (float)j / (float)(n_r - 1);
    float mu = fmax((float)i / (float)(n_mu - 1), 1e-3f);
    FcMaterial m;
    m.diffuse_model = FC_DIFFUSE_NONE;
    m.specular_model = FC_SPECULAR_MICROFACET;
    m.ndf = ndf;
    m.geometry = FC_G_SMITH_CORRELATED;
    m.fresnel = FC_FRESNEL_ONE;
    m.sampling = FC_SAMPLE_VISIBLE;
    m.alpha_x = m.alpha_y = fmax(r * r, 2.0f * FC_ALPHA_MIRROR);
    m.flags = 0u;
    float3 wo = (float3)(sqrt(1.0f - mu * mu), 0.0f, mu);
    Rng rng = rng_init(0x41424cu, (uint)id, 0u);
    float2 shift = (float2)(rng_float(&rng), rng_float(&rng));
    KahanSum3 e = {(float3)(0.0f), (float3)(0.0f)};
    for (uint k = 0; k < samples; ++k) {
        float2 u = (float2)(((float)k + 0.5f) / (float)samples, (float)(reverse_bits_l1(k) >> 8) * 0x1p-24f);
        u = u + shift;
        u -= floor(u);
        BsdfSample s;
        if (!microfacet_sample(&m, wo, u, &s) || s.delta) continue;
        float wh = 0.5f * length(wo + s.wi); /* wo.h */
        kahan_add(&e, (float3)(s.weight.x, s.weight.x * pow5(1.0f - wh), 0.0f));
    }
    out[id] = e.sum.xy / (float)samples;
}

/* albedo_sheen_table: one work-item per (r, mu) node; E_sheen(mu) = int D V cos dwi of the
 * sheen lobe (sheen.cl, S = 1) at roughness r = j / (n_r - 1) (clamped as the kernels clamp
 * it), by cosine sampling on a Hammersley set (f cos / pdf = pi D V). */
__kernel void albedo_sheen_table(int n_mu, int n_r, uint samples, __global float* out) {
    int id = (int)get_global_id(0);
    if (id >= n_mu * n_r) return;
    int i = id % n_mu, j = id / n_mu;
    float r = (float)j / (float)(n_r - 1);
    float mu = fmax((float)i / (float)(n_mu - 1), 1e-3f);
    float3 wo = (float3)(sqrt(1.0f - mu * mu), 0.0f, mu);
    Rng rng = rng_init(0x534845u, (uint)id, 0u);
    float2 shift = (float2)(rng_float(&rng), rng_float(&rng));
    KahanSum3 e = {(float3)(0.0f), (float3)(0.0f)};
    for (uint k = 0; k < samples; ++k) {
        float2 u = (float2)(((float)k + 0.5f) / (float)samples, (float)(reverse_bits_l1(k) >> 8) * 0x1p-24f);
        u = u + shift;
        u -= floor(u);
        float3 wi = square_to_cosine_hemisphere(u);
        if (!(wi.z > 0.0f)) continue;
        kahan_add(&e, (float3)(FC_PI * sheen_dv(r, wo, wi), 0.0f, 0.0f));
    }
    out[id] = e.sum.x / (float)samples;
}

/* albedo_dielectric_table: one work-item per (x, r, mu) node of one NDF and side. The
 * energy albedo E = E_R + E_T of the rough dielectric seen from wo (above the surface),
 * transmission weighted by etap^2 (the importance, not the radiance, that crosses),
 * exact Fresnel, height-correlated Smith, no compensation, in out[id].x; in out[id].y the
 * F = 1 albedo E_c that ec_lookup reads from e_table (an [ndf][r][mu] table of the
 * fc_albedo_E layout) at the node's (mu, r), which the inside table divides out. The
 * relative index of node k is e = (1 + x) / (1 - x), x = x_max (k / (n_x - 1))^2 (the
 * axis is uniform in sqrt(x); node 0 at x = 1e-3, the limit eta -> 1 of a rough interface,
 * not the exact E = 1 of eta = 1); side 0 enters a denser medium (ior = e), side 1 leaves
 * it (ior = 1 / e). */
__kernel void albedo_dielectric_table(int ndf, int side, int n_mu, int n_r, int n_x, float x_max, uint samples,
                                      __constant const float* e_table, __global float2* out) {
    int id = (int)get_global_id(0);
    if (id >= n_mu * n_r * n_x) return;
    int i = id % n_mu, j = (id / n_mu) % n_r, k = id / (n_mu * n_r);
    float r = (float)j / (float)(n_r - 1);
    float mu = fmax((float)i / (float)(n_mu - 1), 1e-3f);
    float sx = (float)k / (float)(n_x - 1);
    float x = fmax(x_max * sx * sx, 1e-3f);
    float e = (1.0f + x) / (1.0f - x);
    FcMaterial m;
    m.diffuse_model = FC_DIFFUSE_NONE;
    m.specular_model = FC_SPECULAR_DIELECTRIC;
    m.ndf = ndf;
    m.geometry = FC_G_SMITH_CORRELATED;
    m.fresnel = FC_FRESNEL_DIELECTRIC;
    m.sampling = FC_SAMPLE_VISIBLE;
    m.alpha_x = m.alpha_y = fmax(r * r, 2.0f * FC_ALPHA_MIRROR);
    m.ior = side == 0 ? e : 1.0f / e;
    m.flags = 0u;
    for (int c = 0; c < 3; ++c) m.specular[c] = 1.0f;
    float3 wo = (float3)(sqrt(1.0f - mu * mu), 0.0f, mu);
    Rng rng = rng_init(0x444c54u, (uint)id, 0u);
    float2 shift = (float2)(rng_float(&rng), rng_float(&rng));
    KahanSum3 sum = {(float3)(0.0f), (float3)(0.0f)};
    for (uint q = 0; q < samples; ++q) {
        float2 u = (float2)(((float)q + 0.5f) / (float)samples, (float)(reverse_bits_l1(q) >> 8) * 0x1p-24f);
        u = u + shift;
        u -= floor(u);
        BsdfSample s;
        if (!bsdf_sample(&m, wo, (float3)(u, rng_float(&rng)), &s) || s.delta) continue;
        float etap = s.wi.z > 0.0f ? 1.0f : relative_eta(m.ior, wo.z);
        kahan_add(&sum, (float3)(s.weight.x * etap * etap, 0.0f, 0.0f));
    }
    float e_c = ec_lookup(e_table, ec_ndf(&m), (float)i / (float)(n_mu - 1), r);
    out[id] = (float2)(sum.sum.x / (float)samples, e_c);
}

/* out[2i] = the mean of bsdf_sample's weight (rgb) from wos[i] over `samples` random
 * samples, out[2i+1] = (its standard error per channel, the count of invalid samples):
 * the directional albedo of mats[i], for the furnace tests (a dielectric's transmissions
 * weighted by etap^2: the energy albedo). */
__kernel void albedo_furnace(__global const FcMaterial* mats, __global const float4* wos, uint samples,
                             __global float4* out) {
    int i = (int)get_global_id(0);
    FcMaterial m = mats[i];
    float3 wo = wos[i].xyz;
    Rng rng = rng_init(0x66726eu, (uint)i, 0u);
    KahanSum3 sum = {(float3)(0.0f), (float3)(0.0f)}, sum2 = sum;
    int bad = 0;
    for (uint k = 0; k < samples; ++k) {
        float3 u = (float3)(rng_float(&rng), rng_float(&rng), rng_float(&rng));
        BsdfSample s;
        if (!bsdf_sample(&m, wo, u, &s)) continue;
        /* a dielectric's transmission carries radiance / etap^2: count the energy */
        if (bsdf_is_dielectric(&m) && s.wi.z * wo.z < 0.0f) s.weight *= sqr(relative_eta(m.ior, wo.z));
        if (!all_finite(s.weight) || s.weight.x < 0.0f || s.weight.y < 0.0f || s.weight.z < 0.0f) {
            ++bad;
            continue;
        }
        kahan_add(&sum, s.weight);
        kahan_add(&sum2, s.weight * s.weight);
    }
    float n = (float)samples;
    float3 mean = sum.sum / n;
    float3 var = fmax(sum2.sum / n - mean * mean, (float3)(0.0f));
    out[2 * i] = (float4)(mean, 0.0f);
    out[2 * i + 1] = (float4)(sqrt(var / n), (float)bad);
}

/* out[i] = (f(wo_i, wi_i), f(wi_i, wo_i) rgb interleaved as two float4: f.xyz, 0). */
__kernel void albedo_reciprocity(__global const FcMaterial* mats, __global const float4* wo, __global const float4* wi,
                                 __global float4* out) {
    int i = (int)get_global_id(0);
    FcMaterial m = mats[i];
    out[2 * i] = (float4)(bsdf_eval(&m, wo[i].xyz, wi[i].xyz), 0.0f);
    out[2 * i + 1] = (float4)(bsdf_eval(&m, wi[i].xyz, wo[i].xyz), 0.0f);
}

/* out[i] = (F_avg of mats[i], the cosine-weighted mean of its Fresnel term, 0). */
__kernel void albedo_fresnel_avg(__global const FcMaterial* mats, __global float4* out) {
    int i = (int)get_global_id(0);
    FcMaterial m = mats[i];
    out[i] = (float4)(ec_fresnel_avg(&m), 0.0f);
}
