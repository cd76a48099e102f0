/* Test entry points for area-light sampling: directions from sample_spherical_triangle
 * (kernels/lights/spherical_triangle.cl) toward the triangle (v0, v1, v2) seen from p,
 * and the triangle's solid angle. out[i] = (w, 1) for a sample, (0, 0, 0, 0) when the
 * sampler refused. */
#include "kernels/lights/spherical_triangle.cl"
#include "kernels/util/rng.cl"

__kernel void spherical_triangle_samples(float4 p, float4 v0, float4 v1, float4 v2, uint seed, __global float4* out,
                                         __global float* omega) {
    uint i = get_global_id(0);
    Rng rng = rng_init(seed, i, 0x5717u);
    float3 a = normalize(v0.xyz - p.xyz), b = normalize(v1.xyz - p.xyz), c = normalize(v2.xyz - p.xyz);
    float3 w;
    bool ok = sample_spherical_triangle(a, b, c, rng_float2(&rng), &w);
    out[i] = ok ? (float4)(w, 1.0f) : (float4)(0.0f);
    if (i == 0u) *omega = triangle_solid_angle(p.xyz, v0.xyz, v1.xyz, v2.xyz);
}
