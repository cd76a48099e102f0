/* Test kernels for tests/bvh_test.cpp: the BVH traversal, and a brute-force loop over
 * every triangle with the same ray/triangle test to compare it against. */
#include "kernels/trace/bvh_traverse.cl"

/* origins[i].xyz, dirs[i].xyz, dirs[i].w = tmax. out[i] = (t, u, v, as_float(prim)),
 * prim = -1 and t = tmax on a miss; any_out[i] = trace_any's answer. */
__kernel void trace_rays_bvh(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                             __global const float4* origins, __global const float4* dirs, __global float4* out,
                             __global int* any_out) {
    size_t i = get_global_id(0);
    float3 o = origins[i].xyz;
    float4 d = dirs[i];
    Hit hit;
    trace_closest(nodes, tris, o, d.xyz, d.w, &hit);
    out[i] = (float4)(hit.t, hit.u, hit.v, as_float(hit.prim));
    any_out[i] = trace_any(nodes, tris, o, d.xyz, d.w) ? 1 : 0;
}

__kernel void trace_rays_brute(__global const FcTriangle* tris, int count, __global const float4* origins,
                               __global const float4* dirs, __global float4* out, __global int* any_out) {
    size_t i = get_global_id(0);
    float3 o = origins[i].xyz;
    float4 d = dirs[i];
    const TriRay tr = tri_ray_setup(d.xyz);
    Hit hit;
    hit.t = d.w;
    hit.u = hit.v = 0.0f;
    hit.prim = -1;
    leaf_hit(tris, 0, count, &tr, o, &hit, false);
    out[i] = (float4)(hit.t, hit.u, hit.v, as_float(hit.prim));
    any_out[i] = hit.prim >= 0 ? 1 : 0;
}

/* Ray origins moved off surface points by offset_ray_origin (p.xyz, ng.xyz). */
__kernel void offset_origins(__global const float4* p, __global const float4* ng, __global float4* out) {
    size_t i = get_global_id(0);
    out[i] = (float4)(offset_ray_origin(p[i].xyz, ng[i].xyz), 0.0f);
}
