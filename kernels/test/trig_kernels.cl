/* Test entry points for kernels/util/trig.cl (tests/trig_test.cpp): one value per work-item. */
#include "kernels/util/trig.cl"

/* (sin 2 pi t, cos 2 pi t) by sincos_turns. */
__kernel void trig_sincos_turns(__global const float* t, __global float2* out) {
    uint i = get_global_id(0);
    out[i] = sincos_turns(t[i]);
}

/* atan2_fast(y, x) of each (y, x). */
__kernel void trig_atan2(__global const float2* yx, __global float* out) {
    uint i = get_global_id(0);
    out[i] = atan2_fast(yx[i].x, yx[i].y);
}

/* exp_poly (kernels/util/exp_lanes.cl) at W = 1. */
__kernel void trig_exp_poly(__global const float* x, __global float* out) {
    uint i = get_global_id(0);
    out[i] = exp_poly_l1(x[i]);
}

/* Beckmann's projected area and Lambda (kernels/bsdf/beckmann_lanes.cl) at W = 1, for the
 * direction (x, y, z) and the isotropic roughness w of each element. */
__kernel void trig_beckmann_area(__global const float4* in, __global float2* out) {
    uint i = get_global_id(0);
    const float3 w = in[i].xyz;
    out[i] = (float2)(beckmann_projected_area_l1(in[i].w, in[i].w, w), beckmann_lambda_l1(in[i].w, in[i].w, w));
}
