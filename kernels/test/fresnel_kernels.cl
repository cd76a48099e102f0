/* Test entry point for kernels/bsdf/fresnel.cl (tests/fresnel_test.cpp). */
#include "kernels/bsdf/fresnel.cl"

/* fresnel_conductor at cosine c[i].w for index eta c[i].xyz + i k[i].xyz. */
__kernel void fresnel_conductor_batch(__global const float4* c, __global const float4* k, __global float4* out) {
    uint i = get_global_id(0);
    out[i] = (float4)(fresnel_conductor(c[i].w, c[i].xyz, k[i].xyz), 0.0f);
}
