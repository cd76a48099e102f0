/* Test kernels for tests/caustic_guide_test.cpp: the mixture of kernels/integrator/caustic_guide.cl
 * sampled as path_radiance samples it (the cosine lobe with probability 1 - g), and the estimate
 * of the integral of cos(theta) over the hemisphere (pi) by cos / density, whose expectation is
 * pi exactly when the density is the sampler's. */
#include "kernels/integrator/caustic_guide.cl"
#include "kernels/util/rng.cl"

/* per work-item: (sum of cos / density, its sum of squares, the lens draws whose density as the
 * sampling reported it is more than 1e-3 away from the one evaluated, the lens draws) over
 * per_item samples */
__kernel void cg_estimate(__constant const FcEnvironment* env, __global const float4* texels,
                          __global const float* dist, __global const float4* casters, uint count, float4 p, float4 n,
                          float fraction, uint seed, uint per_item, __global float4* out, float glint) {
    const uint i = (uint)get_global_id(0);
    Rng rng = rng_init(seed, i, 0x6367u);
    const float3 nn = normalize(n.xyz);
    const CausticGuide c = caustic_guide_of_receiver(casters, count, fraction, glint, true, p.xyz, nn);
    const Frame f = frame_from_normal(nn);
    float sum = 0.0f, sum2 = 0.0f, gap = 0.0f, lens = 0.0f;
    for (uint k = 0; k < per_item; ++k) {
        const float2 u = rng_float2(&rng);
        const float v = rng_float(&rng);
        float3 wi;
        GuideDraw d = {-1, 0.0f};
        if (c.g > 0.0f && v < c.g) {
            if (!caustic_guide_sample(env, texels, dist, casters, &c, v / c.g, u, &wi, &d)) continue;
        } else wi = frame_to_world(&f, square_to_cosine_hemisphere(u));
        const float cos_i = dot(wi, nn);
        if (!(cos_i > 0.0f)) continue;
        const float pdf = caustic_guide_pdf(env, texels, dist, casters, count, &c, cos_i * FC_INV_PI, wi, true, 0);
        const float x = cos_i / pdf;
        sum += x;
        sum2 += x * x;
        if (d.lens >= 0) {
            lens += 1.0f;
            const float pd = caustic_guide_pdf(env, texels, dist, casters, count, &c, cos_i * FC_INV_PI, wi, true, &d);
            gap += fabs(pd - pdf) <= 1e-3f * pdf ? 0.0f : 1.0f;
        }
    }
    out[i] = (float4)(sum, sum2, gap, lens);
}

/* The mixture's g, h, total solid angle and lens count at p. */
__kernel void cg_at(__global const float4* casters, uint count, float4 p, float4 n, float fraction,
                    __global float4* out) {
    const CausticGuide c = caustic_guide_of_receiver(casters, count, fraction, 0.0f, true, p.xyz, normalize(n.xyz));
    out[0] = (float4)(c.g, c.h, c.total, (float)c.lenses);
}

/* A glossy vertex (material *mat at p, normal n, wo given in the world) sampled as path_radiance
 * samples it: with probability g (the mixture's, from fraction) by the guide, else by the BSDF
 * with its choice rescaled past g. Per work-item: (sum of f cos / density of the mixture in
 * red, its sum of squares, the guide's draws, 0): at fraction 0 the BSDF's own estimate of the
 * directional albedo, whose expectation the mixture's must share. */
__kernel void cg_glossy_estimate(__constant const FcEnvironment* env, __global const float4* texels,
                                 __global const float* dist, __global const float4* casters, uint count,
                                 __global const FcMaterial* mat, float4 p, float4 n, float4 wo_world, float fraction,
                                 uint seed, uint per_item, __global float4* out) {
    const uint i = (uint)get_global_id(0);
    Rng rng = rng_init(seed, i, 0x676cu);
    const FcMaterial m = *mat;
    const float3 nn = normalize(n.xyz);
    const CausticGuide c = caustic_guide_of_receiver(casters, count, fraction,
                                                     caustic_guide_glint(FC_CAUSTIC_GUIDE_GLOSSY), true, p.xyz, nn);
    const Frame f = frame_from_normal(nn);
    const float3 wo = frame_to_local(&f, normalize(wo_world.xyz));
    float sum = 0.0f, sum2 = 0.0f, guided = 0.0f;
    for (uint k = 0; k < per_item; ++k) {
        float3 u = (float3)(rng_float2(&rng), rng_float(&rng));
        GuideDraw d = {-1, 0.0f};
        float3 wi, wl, fv;
        float pdf_b;
        if (c.g > 0.0f && u.z < c.g) {
            guided += 1.0f;
            if (!caustic_guide_sample(env, texels, dist, casters, &c, u.z / c.g, u.xy, &wi, &d)) continue;
            wl = frame_to_local(&f, wi);
            if (!(wl.z > 0.0f)) continue;
            fv = bsdf_eval_pdf(&m, wo, wl, &pdf_b);
        } else {
            if (c.g > 0.0f) u.z = fmin((u.z - c.g) / (1.0f - c.g), FC_ONE_MINUS_EPSILON);
            BsdfSample bs;
            if (!bsdf_sample(&m, wo, u, &bs)) continue;
            wl = bs.wi;
            wi = frame_to_world(&f, wl);
            fv = bs.f;
            pdf_b = bs.pdf;
        }
        const float pdf = caustic_guide_pdf(env, texels, dist, casters, count, &c, pdf_b, wi, true, &d);
        if (!(pdf > 0.0f)) continue;
        const float x = fv.x * fabs(wl.z) / pdf;
        sum += x;
        sum2 += x * x;
    }
    out[i] = (float4)(sum, sum2, guided, 0.0f);
}
