/* Test entry point for the light pick (pick_light, kernels/lights/light.cl;
 * tests/lights_test.cpp). */
#include "kernels/lights/light.cl"

/* out[i]: the light picked at u[i] from the `count` lights of `cdf` (count + 1 entries). */
__kernel void light_pick_batch(__global const float* cdf, uint count, __global const float* u, __global int* out) {
    const uint i = get_global_id(0);
    out[i] = pick_light(cdf, count, u[i]);
}
