/* Watertight ray/triangle intersection (Woop, Benthin & Wald 2013, "Watertight
 * Ray/Triangle Intersection", JCGT 2(1)), four triangles at once: each float4 lane runs
 * the paper's scalar operations on its own triangle, so a lane's answer is the scalar
 * test's, bit for bit (Embree's triangle4 leaves do the same with SSE/AVX lanes). The
 * vertices are translated to the ray origin and sheared so the ray runs along +z; the
 * 2D edge functions of a shared edge are then computed from identical values in both
 * triangles, so a ray through an edge or a vertex cannot slip between neighbours. A hit
 * nearer than the rounding error of its distance is no hit (pbrt-v3 section 3.9.6). No
 * backface culling. */
#ifndef FACET_TRACE_TRIANGLE_CL
#define FACET_TRACE_TRIANGLE_CL

#include "kernels/shared/bvh_layout.h"
#include "kernels/util/math.cl"

/* Per-ray part of the test (section 3 of the paper). */
typedef struct {
    int kx, ky, kz;   /* kz: dominant axis of d; (kx, ky) keep the winding */
    float sx, sy, sz; /* shear constants */
    float ox, oy, oz; /* the origin along kx, ky, kz */
} TriRay;

inline float axis_of(float3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }

inline TriRay tri_ray_setup(float3 o, float3 d) {
    TriRay r;
    float3 a = fabs(d);
    r.kz = (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    r.kx = r.kz == 2 ? 0 : r.kz + 1;
    r.ky = r.kx == 2 ? 0 : r.kx + 1;
    float dz = axis_of(d, r.kz);
    if (dz < 0.0f) {
        int k = r.kx;
        r.kx = r.ky;
        r.ky = k;
    }
    r.sx = axis_of(d, r.kx) / dz;
    r.sy = axis_of(d, r.ky) / dz;
    r.sz = 1.0f / dz;
    r.ox = axis_of(o, r.kx);
    r.oy = axis_of(o, r.ky);
    r.oz = axis_of(o, r.kz);
    return r;
}

/* Four triangles' vertices (a, b, c) along the ray's axes kx, ky, kz, in world space. */
typedef struct {
    float4 ax, ay, az, bx, by, bz, cx, cy, cz;
} Tri4;

/* The lanes of a leaf block (FcTriBlock, rows of float4: x0 y0 z0 x1 y1 z1 x2 y2 z2)
 * picked by the ray's axes: the permutation is a row index, no shuffle. */
inline Tri4 tri4_load(__global const float4* rows, const TriRay* r) {
    Tri4 p;
    p.ax = rows[r->kx], p.ay = rows[r->ky], p.az = rows[r->kz];
    p.bx = rows[3 + r->kx], p.by = rows[3 + r->ky], p.bz = rows[3 + r->kz];
    p.cx = rows[6 + r->kx], p.cy = rows[6 + r->ky], p.cz = rows[6 + r->kz];
    return p;
}

/* The test's body, written once over lanes (kernels/trace/triangle_lanes.cl): tri_hit_l4
 * here, at the packet's width in kernels/lanes/packet.cl. */
#include "kernels/lanes/scalar.cl"

/* Lanes hit with t < tmax and t above its rounding error: -1 in the mask; their distance in
 * *t and their scaled barycentrics (edge functions v, w of vertices b and c, and their sum
 * det) for tri4_weights(). Lanes whose three vertices are equal (a block's padding) never
 * hit. */
__attribute__((always_inline)) inline int4 tri4_hit(const TriRay* r, const Tri4* p, float tmax, float4* t_out,
                                                    float4* v_out, float4* w_out, float4* det_out) {
    return tri_hit_l4((float4)(r->ox), (float4)(r->oy), (float4)(r->oz), (float4)(r->sx), (float4)(r->sy),
                      (float4)(r->sz), p->ax, p->ay, p->az, p->bx, p->by, p->bz, p->cx, p->cy, p->cz, (float4)(tmax),
                      t_out, v_out, w_out, det_out);
}

/* The barycentric weights u (of vertex b) and v (of c) of lane `lane`. */
inline void tri4_weights(float4 v, float4 w, float4 det, uint lane, float* u_out, float* v_out) {
    const float vs[4] = {v.x, v.y, v.z, v.w}, ws[4] = {w.x, w.y, w.z, w.w}, ds[4] = {det.x, det.y, det.z, det.w};
    const float inv = 1.0f / ds[lane];
    *u_out = vs[lane] * inv;
    *v_out = ws[lane] * inv;
}

/* A 4-bit mask from an int4 of 0 / -1 lanes: bit c set where lane c is. */
inline uint lane_bits(int4 m) { return (uint)((m.x & 1) | (m.y & 2) | (m.z & 4) | (m.w & 8)); }

/* The nearest of the hit lanes (mask non-zero), the lowest lane among equal distances:
 * the one a loop over the lanes in order keeping only strictly nearer hits would keep. */
inline uint tri4_nearest(int4 mask, float4 t) {
    const float4 tm = select((float4)(INFINITY), t, mask);
    const float m = fmin(fmin(tm.x, tm.y), fmin(tm.z, tm.w));
    return lowest_bit(lane_bits(mask & (tm == m)));
}

#endif
