/* Test entry points for the environment map's direction <-> (u, v) mapping
 * (kernels/lights/environment.cl; tests/environment_lookup_test.cpp). */
#include "kernels/lights/environment.cl"

/* (u, v) of each map-frame direction (xyz). */
__kernel void env_lookup_dir_to_uv(__global const float4* m, __global float2* uv) {
    uint i = get_global_id(0);
    uv[i] = env_map_dir_to_uv(m[i].xyz);
}

/* The map-frame direction of each (u, v). */
__kernel void env_lookup_uv_to_dir(__global const float2* uv, __global float4* m) {
    uint i = get_global_id(0);
    m[i] = (float4)(env_uv_to_map_dir(uv[i]), 0.0f);
}
