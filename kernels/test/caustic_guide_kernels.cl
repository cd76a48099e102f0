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
                          float fraction, uint seed, uint per_item, __global float4* out) {
    const uint i = (uint)get_global_id(0);
    Rng rng = rng_init(seed, i, 0x6367u);
    const float3 nn = normalize(n.xyz);
    const CausticGuide c = caustic_guide_of_receiver(casters, count, fraction, true, p.xyz, nn);
    const Frame f = frame_from_normal(nn);
    float sum = 0.0f, sum2 = 0.0f, gap = 0.0f, lens = 0.0f;
    for (uint k = 0; k < per_item; ++k) {
        const float2 u = rng_float2(&rng);
        const float v = rng_float(&rng);
        float3 wi;
        GuideDraw d = {-1, 0.0f};
        if (c.g > 0.0f && v < c.g) {
            if (!caustic_guide_sample(env, texels, dist, casters, count, &c, v / c.g, u, &wi, &d)) continue;
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
    const CausticGuide c = caustic_guide_of_receiver(casters, count, fraction, true, p.xyz, normalize(n.xyz));
    out[0] = (float4)(c.g, c.h, c.total, (float)c.lenses);
}
