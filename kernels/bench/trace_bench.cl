/* Ray batches for bench/: the traversal kernels alone, on rays made by the host, so
 * that the same rays can be traced by other ray tracers in the same run. */
#ifndef FACET_BENCH_TRACE_BENCH_CL
#define FACET_BENCH_TRACE_BENCH_CL

#include "kernels/trace/bvh_traverse.cl"

/* n rays (the global size may be padded past n); origins[i].xyz, dirs[i].xyz (unit), dirs[i].w = tmax. Writes t (or -1
 * on a miss) and the hit triangle's scene index. */
__kernel void trace_closest_batch(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                                  __global const float4* origins, __global const float4* dirs, __global float* t_out,
                                  __global int* prim_out, int n) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    float4 o = origins[i];
    float4 d = dirs[i];
    Hit hit;
    bool found = trace_closest(nodes, tris, o.xyz, d.xyz, d.w, &hit);
    t_out[i] = found ? hit.t : -1.0f;
    prim_out[i] = found ? hit.prim : -1;
}

__kernel void trace_any_batch(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                              __global const float4* origins, __global const float4* dirs, __global int* hit_out,
                              int n) {
    int i = (int)get_global_id(0);
    if (i >= n) return;
    float4 o = origins[i];
    float4 d = dirs[i];
    hit_out[i] = trace_any(nodes, tris, o.xyz, d.xyz, d.w) ? 1 : 0;
}

#endif
