/* BSDF throughput for bench/: every work-item evaluates, or samples, one material
 * `iterations` times at pseudo-random directions and writes a checksum so nothing is
 * optimised away. */
#include "kernels/bsdf/bsdf.cl"
#include "kernels/util/rng.cl"

__kernel void bsdf_eval_bench(__global const FcMaterial* material, uint iterations, __global float* out) {
    uint gid = get_global_id(0);
    Rng rng = rng_init(7u, gid, 0u);
    const FcMaterial m = *material;
    float acc = 0.0f;
    for (uint i = 0; i < iterations; ++i) {
        float3 wo = square_to_cosine_hemisphere(rng_float2(&rng));
        float3 wi = square_to_cosine_hemisphere(rng_float2(&rng));
        float3 f = bsdf_eval(&m, wo, wi);
        acc += f.x + bsdf_pdf(&m, wo, wi);
    }
    out[gid] = acc;
}

__kernel void bsdf_sample_bench(__global const FcMaterial* material, uint iterations, __global float* out) {
    uint gid = get_global_id(0);
    Rng rng = rng_init(9u, gid, 0u);
    const FcMaterial m = *material;
    float acc = 0.0f;
    for (uint i = 0; i < iterations; ++i) {
        float3 wo = square_to_cosine_hemisphere(rng_float2(&rng));
        float3 u = (float3)(rng_float2(&rng), rng_float(&rng));
        BsdfSample s;
        if (bsdf_sample(&m, wo, u, &s)) acc += s.weight.x;
    }
    out[gid] = acc;
}

/* The microfacet normal samplers alone (FcMaterial.sampling) from a fixed wo: each
 * work-item draws `iterations` normals, reflects wo about them and counts the reflections
 * at or below the horizon (the samples a path would lose) in rejected[gid]. */
__kernel void ndf_sampler_bench(__global const FcMaterial* material, float4 wo4, uint iterations, __global float* out,
                                __global uint* rejected) {
    uint gid = get_global_id(0);
    Rng rng = rng_init(11u, gid, 0u);
    const FcMaterial m = *material;
    float3 wo = wo4.xyz;
    float acc = 0.0f;
    uint lost = 0u;
    for (uint i = 0; i < iterations; ++i) {
        float3 h = ndf_sample(&m, wo, rng_float2(&rng));
        float3 wi;
        if (reflect_about(wo, h, &wi)) acc += wi.z;
        else ++lost;
    }
    out[gid] = acc;
    rejected[gid] = lost;
}
