/* Test entry points for the light pick (pick_light, kernels/lights/light.cl, and its lane
 * forms, kernels/lights/light_pick_lanes.cl; tests/lights_test.cpp). */
#include "kernels/lights/light.cl"

/* out[i]: the light picked at u[i] from the `count` lights of `cdf` (count + 1 entries). */
__kernel void light_pick_batch(__global const float* cdf, uint count, __global const float* u, __global int* out) {
    const uint i = get_global_id(0);
    out[i] = pick_light(cdf, count, u[i]);
}

/* The lane forms at the packets' widths, 8 and 16, each with its gather (gathered from the
 * cdf on AVX2 and AVX-512 CPUs, lane by lane elsewhere). */
#define FC_LW 8
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/light_pick_lanes.cl"
#include "kernels/lanes/lanes_close.cl"
#define FC_LW 16
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/light_pick_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

/* Work-item i picks for u[16 i .. 16 i + 15]: out8 at W = 8 (two vectors), out16 at W = 16. */
__kernel void light_pick_lanes(__global const float* cdf, uint count, __global const float* u, __global int* out8,
                               __global int* out16) {
    const uint i = get_global_id(0);
    vstore8(as_int8(pick_light_l8(cdf, count, vload8(2 * i, u))), 2 * i, out8);
    vstore8(as_int8(pick_light_l8(cdf, count, vload8(2 * i + 1, u))), 2 * i + 1, out8);
    vstore16(as_int16(pick_light_l16(cdf, count, vload16(i, u))), i, out16);
}
