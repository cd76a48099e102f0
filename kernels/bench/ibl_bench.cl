/* Environment sampling throughput for bench/: every work-item draws `per_item`
 * directions from the map's distribution (env_sample) and writes a checksum so none is
 * optimised away. */
#ifndef FACET_BENCH_IBL_BENCH_CL
#define FACET_BENCH_IBL_BENCH_CL

#include "kernels/lights/environment.cl"
#include "kernels/util/rng.cl"

__kernel void env_sample_throughput(__constant const FcEnvironment* env, __global const float4* texels,
                                    __global const float* dist, uint seed, uint per_item, __global float* out) {
    uint g = (uint)get_global_id(0);
    Rng rng = rng_init(seed, g, 0x7470u);
    float sum = 0.0f;
    for (uint k = 0; k < per_item; ++k) {
        float3 dir;
        float pdf;
        float3 L = env_sample(env, texels, dist, rng_float2(&rng), &dir, &pdf);
        sum += (pdf > 0.0f) ? luminance(L) / pdf + dir.x : 0.0f;
    }
    out[g] = sum;
}

#endif
