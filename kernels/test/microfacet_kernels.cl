/* Test kernels for tests/microfacet_test.cpp: batches of the NDF terms, the microfacet
 * lobe, the specular lobes and the whole BSDF, the sampling histograms of the
 * chi-square tests (binned here, on the device) and the extreme-parameter sweep.
 *
 * `mode` picks what is sampled and whose density is evaluated:
 *   0  the microfacet lobe, wi   (microfacet_sample / microfacet_pdf)
 *   1  the NDF's normals, h      (ndf_sample / ndf_pdf)
 *   2  the specular lobe, wi     (specular_sample / specular_pdf)
 *   3  the whole BSDF, wi        (bsdf_sample / bsdf_pdf) */
#ifndef FACET_TEST_MICROFACET_KERNELS_CL
#define FACET_TEST_MICROFACET_KERNELS_CL

#include "kernels/bsdf/bsdf.cl"
#include "kernels/bsdf/microfacet.cl"
#include "kernels/util/rng.cl"

#define MF_MODE_MICROFACET 0
#define MF_MODE_NDF 1
#define MF_MODE_SPECULAR 2
#define MF_MODE_BSDF 3

/* Draws one sample; false when the sampler refused. */
inline bool mf_draw(const FcMaterial* m, float3 wo, int mode, float3 u, float3* w) {
    BsdfSample s;
    bool ok;
    switch (mode) {
        case MF_MODE_NDF:
            *w = ndf_sample(m, wo, u.xy);
            return true;
        case MF_MODE_SPECULAR:
            ok = specular_sample(m, wo, u.xy, &s);
            break;
        case MF_MODE_BSDF:
            ok = bsdf_sample(m, wo, u, &s);
            break;
        default:
            ok = microfacet_sample(m, wo, u.xy, &s);
            break;
    }
    *w = s.wi;
    return ok;
}

inline float mf_density(const FcMaterial* m, float3 wo, int mode, float3 w) {
    switch (mode) {
        case MF_MODE_NDF:
            return ndf_pdf(m, wo, w);
        case MF_MODE_SPECULAR:
            return specular_pdf(m, wo, w);
        case MF_MODE_BSDF:
            return bsdf_pdf(m, wo, w);
        default:
            return microfacet_pdf(m, wo, w);
    }
}

/* The cell k of sorted edges e[0..n] with e[k] <= v < e[k+1], or -1 outside. */
inline int mf_find_cell(__global const float* e, int n, float v) {
    if (!(v >= e[0] && v < e[n])) return -1;
    int lo = 0, hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (v >= e[mid]) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Histogram of `per_item` samples per work-item in the (theta, phi) chart of
 * tests/chi2_test_util.hpp: theta from the +z axis, phi - phi0 wrapped into [0, 2pi).
 * hist[nt * np] counts refused samples, hist[nt * np + 1] invalid ones (non-finite or
 * outside the chart, which covers the sphere). Each work-group bins into `local_hist`
 * (nt * np + 2 counters) and adds it to `hist` at the end. */
__kernel void mf_sample_hist(__global const FcMaterial* mat, float4 wo4, int mode, uint seed, uint per_item, int nt,
                             int np, __global const float* theta_edges, __global const float* phi_edges, float phi0,
                             __global uint* hist, __local uint* local_hist) {
    int cells = nt * np + 2;
    for (int c = (int)get_local_id(0); c < cells; c += (int)get_local_size(0)) local_hist[c] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    FcMaterial m = *mat;
    float3 wo = wo4.xyz;
    Rng rng = rng_init(seed, (uint)get_global_id(0), 0x6d66u);
    for (uint i = 0; i < per_item; ++i) {
        float3 u;
        u.x = rng_float(&rng);
        u.y = rng_float(&rng);
        u.z = rng_float(&rng);
        float3 w;
        int cell = nt * np;
        if (mf_draw(&m, wo, mode, u, &w)) {
            float theta = atan2(sqrt(w.x * w.x + w.y * w.y), w.z);
            float phi = atan2(w.y, w.x) - phi0;
            while (phi < 0.0f) phi += 2.0f * FC_PI;
            while (phi >= 2.0f * FC_PI) phi -= 2.0f * FC_PI;
            int a = mf_find_cell(theta_edges, nt, theta);
            int b = mf_find_cell(phi_edges, np, phi);
            cell = (a < 0 || b < 0 || !all_finite(w)) ? nt * np + 1 : a * np + b;
        }
        atomic_inc(&local_hist[cell]);
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (int c = (int)get_local_id(0); c < cells; c += (int)get_local_size(0))
        if (local_hist[c] != 0u) atomic_add(&hist[c], local_hist[c]);
}

/* out[i] = the density of dirs[i] (mode as above). */
__kernel void mf_pdf_batch(__global const FcMaterial* mat, float4 wo4, int mode, __global const float4* dirs,
                           __global float* out) {
    size_t i = get_global_id(0);
    FcMaterial m = *mat;
    out[i] = mf_density(&m, wo4.xyz, mode, dirs[i].xyz);
}

/* out[i] = (D(m), Lambda(m as a direction), ndf_pdf(wo, m), G1(wo, m)). */
__kernel void mf_ndf_terms(__global const FcMaterial* mat, float4 wo4, __global const float4* dirs,
                           __global float4* out) {
    size_t i = get_global_id(0);
    FcMaterial m = *mat;
    float3 d = dirs[i].xyz;
    out[i] = (float4)(ndf_D(&m, d), ndf_lambda(&m, d), ndf_pdf(&m, wo4.xyz, d), smith_G1(&m, wo4.xyz, d));
}

/* out[i * FC_G_COUNT + g] = G of kind g for (wo[i], wi[i]) and their half vector. */
__kernel void mf_geometry(__global const FcMaterial* mat, __global const float4* wo, __global const float4* wi,
                          __global float* out) {
    size_t i = get_global_id(0);
    FcMaterial m = *mat;
    float3 h = normalize(wo[i].xyz + wi[i].xyz);
    for (int g = 0; g < FC_G_COUNT; ++g) {
        m.geometry = g;
        out[i * FC_G_COUNT + g] = geometry_G(&m, wo[i].xyz, wi[i].xyz, h);
    }
}

/* For material i, wo[i], u[i]: out[4i] = the specular lobe's sample (f, pdf), out[4i+1]
 * its eval/pdf at the sampled wi, out[4i+2] = bsdf_sample's (weight, ok),
 * out[4i+3] = (bsdf_eval cos / bsdf_pdf at its wi, delta). ok = 0/1 in .w. */
__kernel void mf_consistency(__global const FcMaterial* mats, __global const float4* wo, __global const float4* u,
                             __global float4* out) {
    size_t i = get_global_id(0);
    FcMaterial m = mats[i];
    float3 o = wo[i].xyz;
    BsdfSample s;
    bool ok = specular_sample(&m, o, u[i].xy, &s);
    bool live = ok && !s.delta;
    out[4 * i] = (float4)(s.f, live ? s.pdf : -1.0f);
    out[4 * i + 1] =
        live ? (float4)(specular_eval(&m, o, s.wi), specular_pdf(&m, o, s.wi)) : (float4)(0.0f, 0.0f, 0.0f, -1.0f);
    ok = bsdf_sample(&m, o, u[i].xyz, &s);
    out[4 * i + 2] = (float4)(s.weight, ok ? 1.0f : 0.0f);
    float3 expect = (float3)(0.0f);
    if (ok && !s.delta) expect = bsdf_eval(&m, o, s.wi) * (fabs(s.wi.z) / bsdf_pdf(&m, o, s.wi));
    out[4 * i + 3] = (float4)(expect, (float)s.delta);
}

/* ---- the extreme-parameter sweep ------------------------------------------------ */

inline float sweep_log_uniform(Rng* r, float lo_exp10, float hi_exp10) {
    return exp10(lo_exp10 + (hi_exp10 - lo_exp10) * rng_float(r));
}

/* A direction above the surface whose cosine is log-uniform in [1e-7, 1] half the time. */
inline float3 sweep_direction(Rng* r) {
    float c = (rng_float(r) < 0.5f) ? sweep_log_uniform(r, -7.0f, 0.0f) : 1.0f - rng_float(r);
    float s = safe_sqrt(1.0f - c * c);
    float phi = 2.0f * FC_PI * rng_float(r);
    return (float3)(s * cos(phi), s * sin(phi), c);
}

inline FcMaterial sweep_material(Rng* r) {
    FcMaterial m;
    m.diffuse_model = (int)(rng_next(r) % FC_DIFFUSE_COUNT);
    m.specular_model = (rng_float(r) < 0.5f) ? FC_SPECULAR_MICROFACET : (int)(rng_next(r) % FC_SPECULAR_COUNT);
    m.ndf = (int)(rng_next(r) % FC_NDF_COUNT);
    m.geometry = (int)(rng_next(r) % FC_G_COUNT);
    m.fresnel = (int)(rng_next(r) % FC_FRESNEL_COUNT);
    m.sampling = (int)(rng_next(r) % FC_SAMPLE_COUNT);
    m.alpha_x = sweep_log_uniform(r, -7.0f, 0.0f);
    float ratio = (rng_float(r) < 0.25f) ? 1.0f : sweep_log_uniform(r, -4.0f, 4.0f);
    m.alpha_y = clamp(m.alpha_x * ratio, 1e-7f, 1.0f);
    m.exponent_x = 2.0f / (m.alpha_x * m.alpha_x) - 2.0f; /* 0 to 2e14 */
    m.exponent_y = 2.0f / (m.alpha_y * m.alpha_y) - 2.0f;
    m.ior = 1.0f + 19.0f * rng_float(r);
    m.sigma = 0.5f * FC_PI * rng_float(r);
    for (int c = 0; c < 3; ++c) {
        m.diffuse[c] = rng_float(r);
        m.specular[c] = rng_float(r);
        m.emission[c] = 0.0f;
        m.eta[c] = 20.0f * rng_float(r);
        m.k[c] = 10.0f * rng_float(r);
    }
    m.flags = (rng_float(r) < 0.5f) ? FC_MAT_ENERGY_COMPENSATION : 0u;
    if (m.specular_model == FC_SPECULAR_DIELECTRIC) {
        /* eta from 1.0001 to 20, and its inverse (below 1) half the time. */
        float u = rng_float(r);
        m.ior = (u < 0.25f) ? 1.0001f : sweep_log_uniform(r, 0.0f, 1.30103f);
        if (rng_float(r) < 0.5f) m.ior = 1.0f / m.ior;
    }
    return m;
}

inline bool sweep_value_ok(float3 f) { return all_finite(f) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f; }
inline bool sweep_pdf_ok(float p) { return isfinite(p) && p >= 0.0f; }

/* Records a failure: code 1 eval, 2 pdf, 3 bsdf_sample, 4 microfacet_sample values,
 * 5 microfacet weight above 1 + 1e-3 where it is bounded by 1. */
inline void sweep_fail(__global uint* counters, __global FcMaterial* fail_mats, __global float4* fail_dirs,
                       const FcMaterial* m, float3 wo, float3 wi, int code, float value) {
    uint slot = atomic_inc(&counters[1]);
    if (slot >= 16u) return;
    fail_mats[slot] = *m;
    fail_dirs[2 * slot] = (float4)(wo, (float)code);
    fail_dirs[2 * slot + 1] = (float4)(wi, value);
}

/* Work-item i draws a material, wo and five wi (random, wo, -wo, the mirror, and the
 * refracted direction), checks eval and pdf of the BSDF and of the microfacet lobe for
 * each, and both samplers. Dielectrics take wo and the random wi on either side (code 6:
 * a dielectric sample's energy weight, weight etap^2, above 1 + 1e-3 with visible
 * normals, where it is G2 / G1(wo) <= 1). counters[0] += cases checked, counters[1] =
 * failures. */
__kernel void mf_extreme_sweep(uint seed, __global uint* counters, __global FcMaterial* fail_mats,
                               __global float4* fail_dirs) {
    Rng r = rng_init(seed, (uint)get_global_id(0), 0x7377u);
    FcMaterial m = sweep_material(&r);
    bool dielectric = m.specular_model == FC_SPECULAR_DIELECTRIC;
    float3 wo = sweep_direction(&r);
    if (dielectric && rng_float(&r) < 0.5f) wo = -wo;
    float3 wr = sweep_direction(&r);
    if (dielectric && rng_float(&r) < 0.5f) wr = -wr;
    float3 wt = -wo;
    refract_about(wo, (float3)(0.0f, 0.0f, 1.0f), m.ior, &wt);
    float3 dirs[5] = {wr, wo, -wo, (float3)(-wo.x, -wo.y, wo.z), wt};
    uint checked = 0u;
    for (int k = 0; k < 5; ++k) {
        float3 wi = dirs[k];
        float3 f = bsdf_eval(&m, wo, wi);
        if (!sweep_value_ok(f)) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, wi, 1, f.x);
        float p = bsdf_pdf(&m, wo, wi);
        if (!sweep_pdf_ok(p)) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, wi, 2, p);
        f = microfacet_eval(&m, wo, wi);
        p = microfacet_pdf(&m, wo, wi);
        if (!sweep_value_ok(f) || !sweep_pdf_ok(p)) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, wi, 4, p);
        ++checked;
    }
    float3 u = (float3)(rng_float(&r), rng_float(&r), rng_float(&r));
    BsdfSample s;
    if (bsdf_sample(&m, wo, u, &s)) {
        bool ok = sweep_value_ok(s.weight) && all_finite(s.wi);
        bool side_ok = dielectric ? fabs(s.wi.z) > 0.0f : s.wi.z > 0.0f;
        if (!s.delta) ok = ok && side_ok && sweep_value_ok(s.f) && s.pdf > 0.0f && isfinite(s.pdf);
        if (!ok) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, s.wi, 3, s.pdf);
        if (ok && dielectric && !ec_enabled(&m) && (s.delta || ndf_samples_visible(&m))) {
            float etap = (s.wi.z * wo.z > 0.0f) ? 1.0f : relative_eta(m.ior, wo.z);
            float energy = max3(s.weight) * etap * etap;
            if (!(energy <= 1.001f)) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, s.wi, 6, energy);
        }
    }
    if (microfacet_sample(&m, wo, u.xy, &s)) {
        bool ok = sweep_value_ok(s.weight) && all_finite(s.wi);
        if (!s.delta) ok = ok && s.wi.z > 0.0f && sweep_value_ok(s.f) && s.pdf > 0.0f && isfinite(s.pdf);
        if (!ok) sweep_fail(counters, fail_mats, fail_dirs, &m, wo, s.wi, 4, s.pdf);
        /* weight = G F / G1(wo) <= 1 for F = 1, exact Smith G and visible normals (bounded
         * ones too: their pdf is larger), without energy compensation. */
        bool bounded = m.fresnel == FC_FRESNEL_ONE && !ec_enabled(&m) &&
                       (s.delta || (ndf_samples_visible(&m) &&
                                    (m.geometry == FC_G_SMITH_SEPARABLE || m.geometry == FC_G_SMITH_CORRELATED)));
        if (ok && bounded && !(max3(s.weight) <= 1.001f))
            sweep_fail(counters, fail_mats, fail_dirs, &m, wo, s.wi, 5, max3(s.weight));
    }
    checked += 2u;
    atomic_add(&counters[0], checked);
}

#endif
