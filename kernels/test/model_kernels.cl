/* Test kernels of the reflection models (tests/models_test.cpp): the whole BSDF's
 * eval/pdf, directional albedos by importance sampling, and the specular lobes'
 * sample/eval/pdf agreement. Directions are in the local frame (n = +z). */
#ifndef FACET_TEST_MODEL_KERNELS_CL
#define FACET_TEST_MODEL_KERNELS_CL

#include "kernels/bsdf/bsdf.cl"
#include "kernels/util/rng.cl"

/* out[4i..4i+2] = bsdf_eval(mats[i], wo_i, wi_i), out[4i+3] = bsdf_pdf;
 * dirs holds wo_i, wi_i as 6 floats per item. */
__kernel void models_eval(__global const FcMaterial* mats, __global const float* dirs, __global float* out, int n) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    float3 wo = vload3(2 * i, dirs);
    float3 wi = vload3(2 * i + 1, dirs);
    float3 f = bsdf_eval(&m, wo, wi);
    out[4 * i + 0] = f.x;
    out[4 * i + 1] = f.y;
    out[4 * i + 2] = f.z;
    out[4 * i + 3] = bsdf_pdf(&m, wo, wi);
}

/* models_eval through the general route of bsdf.cl's two-lobe base (specular_eval_pdf,
 * bsdf_base_f, bsdf_base_density), which bsdf_eval and bsdf_pdf leave for the plain base's
 * lanes where bsdf_plain holds: the two routes side by side. */
__kernel void models_eval_general(__global const FcMaterial* mats, __global const float* dirs, __global float* out,
                                  int n) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    float3 wo = vload3(2 * i, dirs);
    float3 wi = vload3(2 * i + 1, dirs);
    float ps = 0.0f;
    float4 r = (float4)(0.0f);
    if (wo.z > 0.0f && wi.z > 0.0f) {
        const float3 fs = specular_eval_pdf(&m, wo, wi, &ps);
        r = (float4)(bsdf_base_f(&m, wo, wi, fs), bsdf_base_density(&m, wo, wi, ps));
    }
    vstore4(r, i, out);
}

/* bsdf_eval_pdf against bsdf_eval and bsdf_pdf on the same pairs: out[i] = 1 where any of
 * the four values differs in its bits. */
__kernel void models_eval_pdf_bits(__global const FcMaterial* mats, __global const float* dirs, __global int* out,
                                   int n) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    float3 wo = vload3(2 * i, dirs);
    float3 wi = vload3(2 * i + 1, dirs);
    float pdf;
    float3 f = bsdf_eval_pdf(&m, wo, wi, &pdf);
    float3 g = bsdf_eval(&m, wo, wi);
    float q = bsdf_pdf(&m, wo, wi);
    out[i] = any(as_int3(f) != as_int3(g)) || as_int(pdf) != as_int(q);
}

/* Directional albedo of channel 0 of mats[i] seen from wos[i], from `samples`
 * bsdf_sample draws: out[4i] = mean weight, out[4i+1] = standard error of the mean,
 * out[4i+2] = number of samples with a NaN, infinite or negative weight, f or pdf,
 * out[4i+3] = largest weight. */
__kernel void models_albedo(__global const FcMaterial* mats, __global const float* wos, __global float* out, int n,
                            int samples) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    float3 wo = vload3(i, wos);
    Rng rng = rng_init(1234u, (uint)i, 0u);
    /* Welford's running mean and variance */
    float mean = 0.0f, m2 = 0.0f, wmax = 0.0f;
    int bad = 0;
    for (int k = 0; k < samples; ++k) {
        float3 u = (float3)(rng_float(&rng), rng_float(&rng), rng_float(&rng));
        BsdfSample s;
        float w = 0.0f;
        if (bsdf_sample(&m, wo, u, &s)) {
            w = s.weight.x;
            bool ok = isfinite(w) && w >= 0.0f && all_finite(s.f) && s.f.x >= 0.0f && s.f.y >= 0.0f && s.f.z >= 0.0f &&
                      (s.delta || (isfinite(s.pdf) && s.pdf > 0.0f));
            if (!ok) {
                ++bad;
                w = 0.0f;
            }
        }
        float d = w - mean;
        mean += d / (float)(k + 1);
        m2 += d * (w - mean);
        wmax = fmax(wmax, w);
    }
    out[4 * i + 0] = mean;
    out[4 * i + 1] = sqrt(m2 / ((float)samples * (float)(samples - 1)));
    out[4 * i + 2] = (float)bad;
    out[4 * i + 3] = wmax;
}

/* Samples `samples` directions from wo with random u and counts the mismatches, those whose
 * reported f, pdf or weight differ from the evaluation, and the bad ones, with a NaN,
 * infinite or negative value or below the surface; returns (mismatches, bad).
 * `whole` == 0: specular_sample against specular_eval / specular_pdf, exactly (the lobes
 * report what eval and pdf give); 1: bsdf_sample against bsdf_eval, bsdf_pdf and
 * f cos / pdf, to float rounding (3e-6 relative: a short route such as a Lambertian
 * lobe's computes them in closed form). */
inline int2 sample_consistency(const FcMaterial* m, float3 wo, uint seed, uint index, int samples, int whole) {
    Rng rng = rng_init(seed, index, 0u);
    int mismatch = 0, bad = 0;
    for (int k = 0; k < samples; ++k) {
        BsdfSample s;
        float2 u2 = rng_float2(&rng);
        bool made = whole ? bsdf_sample(m, wo, (float3)(u2, rng_float(&rng)), &s) : specular_sample(m, wo, u2, &s);
        if (!made) continue;
        float3 f = whole ? bsdf_eval(m, wo, s.wi) : specular_eval(m, wo, s.wi);
        float pdf = whole ? bsdf_pdf(m, wo, s.wi) : specular_pdf(m, wo, s.wi);
        float3 w = f * (s.wi.z / pdf);
        if (!all_finite(f) || !all_finite(s.f) || !all_finite(s.weight) || !isfinite(pdf) || !isfinite(s.pdf) ||
            !(pdf > 0.0f) || any(f < 0.0f) || any(s.weight < 0.0f) || !(s.wi.z > 0.0f)) {
            ++bad;
            continue;
        }
        const float tol = whole ? 3e-6f : 0.0f;
        if (any(fabs(f - s.f) > tol * f) || fabs(pdf - s.pdf) > tol * pdf || any(fabs(w - s.weight) > tol * w))
            ++mismatch;
    }
    return (int2)(mismatch, bad);
}

/* specular_sample of mats[i] from wos[i] (sample_consistency, exact): mismatches in
 * out[2i], bad samples in out[2i + 1]. */
__kernel void models_sample_consistency(__global const FcMaterial* mats, __global const float* wos, __global int* out,
                                        int n, int samples) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    vstore2(sample_consistency(&m, vload3(i, wos), 99u, (uint)i, samples, 0), i, out);
}

/* The whole BSDF's sample of mats[i] from wos[i] (sample_consistency, to rounding). */
__kernel void models_bsdf_sample_consistency(__global const FcMaterial* mats, __global const float* wos,
                                             __global int* out, int n, int samples) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    FcMaterial m = mats[i];
    vstore2(sample_consistency(&m, vload3(i, wos), 7u, (uint)i, samples, 1), i, out);
}

#endif
