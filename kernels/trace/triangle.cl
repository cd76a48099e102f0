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

/* gamma(n) = n eps / (1 - n eps), eps = 2^-24: bounds of n roundings (pbrt-v3 3.9.1). */
#define FC_GAMMA2 1.1920930376163766e-07f
#define FC_GAMMA3 1.788139663006007e-07f
#define FC_GAMMA5 2.9802331269482156e-07f

/* a*b - c*d with an error under 1.5 ulps, so its sign is exact (Kahan's algorithm
 * with fma); the paper falls back to double precision instead, which OpenCL C 1.2
 * devices need not have. */
inline float4 diff_of_products4(float4 a, float4 b, float4 c, float4 d) {
    float4 cd = c * d;
    float4 err = fma(-c, d, cd);
    return fma(a, b, -cd) + err;
}

/* Lanes hit with t < tmax and t above its rounding error (below): -1 in the mask; their distance in *t and their scaled
 * barycentrics (edge functions v, w of vertices b and c, and their sum det) for
 * tri4_weights(). Lanes whose three vertices are equal (a block's padding) never hit. */
__attribute__((always_inline)) inline int4 tri4_hit(const TriRay* r, const Tri4* p, float tmax, float4* t_out,
                                                    float4* v_out, float4* w_out, float4* det_out) {
    /* No fma contraction: the edge functions of a shared edge must be exact negatives
     * of each other in the two triangles (OpenCL C contracts by default). */
#pragma OPENCL FP_CONTRACT OFF
    /* Translate to the origin, then shear. */
    float4 az = p->az - r->oz, bz = p->bz - r->oz, cz = p->cz - r->oz;
    float4 ax = (p->ax - r->ox) - r->sx * az, ay = (p->ay - r->oy) - r->sy * az;
    float4 bx = (p->bx - r->ox) - r->sx * bz, by = (p->by - r->oy) - r->sy * bz;
    float4 cx = (p->cx - r->ox) - r->sx * cz, cy = (p->cy - r->oy) - r->sy * cz;

    /* Scaled barycentrics: the edge functions. */
    float4 u = cx * by - cy * bx;
    float4 v = ax * cy - ay * cx;
    float4 w = bx * ay - by * ax;
    const int4 on_edge = (u == 0.0f) | (v == 0.0f) | (w == 0.0f);
    if (any(on_edge)) { /* recompute those lanes exactly-signed */
        u = select(u, diff_of_products4(cx, by, cy, bx), on_edge);
        v = select(v, diff_of_products4(ax, cy, ay, cx), on_edge);
        w = select(w, diff_of_products4(bx, ay, by, ax), on_edge);
    }
    /* Inside: the three edge functions of one sign (zero counts as either). The masks
     * are built without a vector NOT: Oclgrind 21.10 evaluates `xor <4 x i1> m, true`,
     * which LLVM makes of ~mask, to lanes of 1 or -2 instead of -1 and 0. */
    const float4 det = u + v + w;
    const int4 inside = ((u >= 0.0f) & (v >= 0.0f) & (w >= 0.0f)) | ((u <= 0.0f) & (v <= 0.0f) & (w <= 0.0f));

    /* Scaled distance, divided by det (no lane traps on a zero det: it is a miss). */
    az *= r->sz;
    bz *= r->sz;
    cz *= r->sz;
    const float4 tt = u * az + v * bz + w * cz;
    float4 t = tt / det;
    /* Edge functions ~ size^2 times distances ~ size overflow past ~5e12 (the scene
     * format allows 1e18): then weight the distances by the barycentrics instead. */
    const int4 overflow = isinf(tt) | isnan(tt);
    if (any(overflow)) t = select(t, (u / det) * az + (v / det) * bz + (w / det) * cz, overflow);
    /* A hit nearer than the rounding error of t is no hit (pbrt-v3 section 3.9.6, its
     * deltaT, with the error of the edge functions and of the sheared coordinates): a ray
     * leaving a surface whose origin offset (ray.cl) is below the rounding of the other
     * triangles' coordinates cannot hit that surface again. The edge function terms are
     * divided by det before they meet the distances, so that the bound does not overflow
     * at the scene format's 1e18. Only blocks with a hit pay for it (most have none). */
    int4 hit = inside & (det != 0.0f) & (t > 0.0f) & (t < tmax);
    if (any(hit)) {
        const float4 max_x = fmax(fmax(fabs(ax), fabs(bx)), fabs(cx));
        const float4 max_y = fmax(fmax(fabs(ay), fabs(by)), fabs(cy));
        const float4 max_z = fmax(fmax(fabs(az), fabs(bz)), fabs(cz));
        const float4 inv_det = fabs(1.0f / det);
        const float4 delta_x = FC_GAMMA5 * (max_x + max_z), delta_y = FC_GAMMA5 * (max_y + max_z);
        const float4 delta_e = 2.0f * (FC_GAMMA2 * max_x * max_y + delta_y * max_x + delta_x * max_y) * inv_det;
        const float4 max_e = fmax(fmax(fabs(u), fabs(v)), fabs(w)) * inv_det;
        const float4 delta_t = 3.0f * (FC_GAMMA3 * max_e * max_z + delta_e * max_z + FC_GAMMA3 * max_z * max_e);
        hit &= t > delta_t;
    }
    *t_out = t;
    *v_out = v;
    *w_out = w;
    *det_out = det;
    return hit;
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

/* Index of the lowest set bit of a non-zero mask (OpenCL C 1.2 has clz, not ctz). */
inline uint lowest_bit(uint bits) { return 31u - clz(bits & (0u - bits)); }

/* The nearest of the hit lanes (mask non-zero), the lowest lane among equal distances:
 * the one a loop over the lanes in order keeping only strictly nearer hits would keep. */
inline uint tri4_nearest(int4 mask, float4 t) {
    const float4 tm = select((float4)(INFINITY), t, mask);
    const float m = fmin(fmin(tm.x, tm.y), fmin(tm.z, tm.w));
    return lowest_bit(lane_bits(mask & (tm == m)));
}

#endif
