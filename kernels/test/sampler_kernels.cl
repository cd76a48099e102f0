/* Test entry points for the path tracer's sample generator (kernels/util/sampler.cl).
 * Work-item g is sample (g % samples) of pixel (first_pixel + g / samples); it writes the
 * point of dimension set `set`. */
#include "kernels/util/sampler.cl"

__kernel void sampler_points(uint kind, uint seed, uint first_pixel, uint samples, uint set, __global float4* out) {
    uint g = get_global_id(0);
    Sampler s = sampler_init(kind, seed, first_pixel + g / samples, g % samples);
    out[g] = sampler_get4(&s, set);
}
