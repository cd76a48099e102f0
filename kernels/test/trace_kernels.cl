/* Test kernels for tests/bvh_test.cpp: the BVH traversal, and a brute-force loop over
 * every triangle with the same ray/triangle test to compare it against. */
#ifndef FACET_TEST_TRACE_KERNELS_CL
#define FACET_TEST_TRACE_KERNELS_CL

#include "kernels/trace/bvh_traverse.cl"

/* Four consecutive triangles of the FcTriangle array (from `first`; lanes past `count`
 * get all vertices at 0, which never hit) along the ray's axes. */
inline Tri4 tri4_gather(__global const FcTriangle* tris, int first, int count, const TriRay* r) {
    float a[3][4], b[3][4], c[3][4];
    for (int lane = 0; lane < 4; ++lane) {
        const bool used = first + lane < count;
        const float3 p0 = used ? load3(tris[first + lane].v0) : (float3)(0.0f);
        const float3 p1 = used ? load3(tris[first + lane].v1) : (float3)(0.0f);
        const float3 p2 = used ? load3(tris[first + lane].v2) : (float3)(0.0f);
        const int k[3] = {r->kx, r->ky, r->kz};
        for (int j = 0; j < 3; ++j) {
            a[j][lane] = axis_of(p0, k[j]);
            b[j][lane] = axis_of(p1, k[j]);
            c[j][lane] = axis_of(p2, k[j]);
        }
    }
    Tri4 p;
    p.ax = vload4(0, a[0]), p.ay = vload4(0, a[1]), p.az = vload4(0, a[2]);
    p.bx = vload4(0, b[0]), p.by = vload4(0, b[1]), p.bz = vload4(0, b[2]);
    p.cx = vload4(0, c[0]), p.cy = vload4(0, c[1]), p.cz = vload4(0, c[2]);
    return p;
}

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
    const TriRay tr = tri_ray_setup(o, d.xyz);
    Hit hit;
    hit.t = d.w;
    hit.u = hit.v = 0.0f;
    hit.prim = -1;
    for (int first = 0; first < count; first += 4) {
        const Tri4 p = tri4_gather(tris, first, count, &tr);
        float4 t, v, w, det;
        const int4 mask = tri4_hit(&tr, &p, hit.t, &t, &v, &w, &det);
        if (!any(mask)) continue;
        const uint lane = tri4_nearest(mask, t);
        const float ts[4] = {t.x, t.y, t.z, t.w};
        hit.t = ts[lane];
        hit.prim = tris[first + (int)lane].prim;
        tri4_weights(v, w, det, lane, &hit.u, &hit.v);
    }
    out[i] = (float4)(hit.t, hit.u, hit.v, as_float(hit.prim));
    any_out[i] = hit.prim >= 0 ? 1 : 0;
}

/* Ray origins moved off surface points by offset_ray_origin (p.xyz, ng.xyz). */
__kernel void offset_origins(__global const float4* p, __global const float4* ng, __global float4* out) {
    size_t i = get_global_id(0);
    out[i] = (float4)(offset_ray_origin(p[i].xyz, ng[i].xyz), 0.0f);
}

#endif
