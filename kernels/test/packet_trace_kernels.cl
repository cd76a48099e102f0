/* Test kernels for tests/packet_trace_test.cpp: the packet traversal
 * (kernels/trace/packet_trace.cl) at FC_PACKET_WIDTH over the 8-wide nodes the includer sets
 * (float, or quantised with FC_BVH_QUANTISED). */
#ifndef FACET_TEST_PACKET_TRACE_KERNELS_CL
#define FACET_TEST_PACKET_TRACE_KERNELS_CL

#define FC_BVH_WIDTH 8
#include "kernels/lanes/packet.cl"
#include "kernels/trace/bvh_traverse.cl"

#define FC_PACKET_W FC_PACKET_WIDTH
#define FC_LW FC_PACKET_W
#include "kernels/lanes/lanes_open.cl"
#include "kernels/trace/packet_trace.cl"

/* Work-item g traces rays [g W, g W + W) as one packet, those whose traced[i] is non-zero:
 * origins[i].xyz, dirs[i].xyz, dirs[i].w = tmax. out[i] = (t, u, v, as_float(prim)) as
 * trace_rays_bvh writes it (prim = -1 and t = tmax on a miss, and for rays not traced);
 * met[i] = whether packet_trace_bvh reported lane i hit. With `any` non-zero, as shadow rays:
 * met[i] only (out is then not the hits). */
__kernel void trace_rays_packet(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                                __global const float4* origins, __global const float4* dirs, __global const int* traced,
                                __global float4* out, __global int* met, int any) {
    const size_t first = get_global_id(0) * FC_PACKET_W;
    float o[3 * FC_PACKET_W], d[3 * FC_PACKET_W];
    Hit hits[FC_PACKET_W];
    float tmax[FC_PACKET_W];
    uint bits = 0u;
    for (int j = 0; j < FC_PACKET_W; ++j) {
        const float4 oj = origins[first + j], dj = dirs[first + j];
        o[j] = oj.x;
        o[FC_PACKET_W + j] = oj.y;
        o[2 * FC_PACKET_W + j] = oj.z;
        d[j] = dj.x;
        d[FC_PACKET_W + j] = dj.y;
        d[2 * FC_PACKET_W + j] = dj.z;
        hits[j].t = dj.w;
        tmax[j] = dj.w;
        hits[j].u = 0.0f;
        hits[j].v = 0.0f;
        hits[j].prim = -1;
        hits[j].tri = -1;
        hits[j].inst = -1;
        if (traced[first + j]) bits |= 1u << j;
    }
    const uint hit = packet_trace_bvh(nodes, o, d, bits, any != 0, LLOAD(tmax), hits);
    for (int j = 0; j < FC_PACKET_W; ++j) {
        const int prim = ((hit >> j) & 1u) && !any ? tris[hits[j].tri].prim : -1;
        out[first + j] = (float4)(hits[j].t, hits[j].u, hits[j].v, as_float(prim));
        met[first + j] = (int)((hit >> j) & 1u);
    }
}

#include "kernels/lanes/lanes_close.cl"

#endif
