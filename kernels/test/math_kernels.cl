/* Test entry points for kernels/util/math.cl (tests/math_test.cpp): one value per work-item. */
#include "kernels/util/math.cl"

/* pow_positive(x, y) of each (x, y). */
__kernel void math_pow_positive(__global const float2* xy, __global float* out) {
    uint i = get_global_id(0);
    out[i] = pow_positive(xy[i].x, xy[i].y);
}
