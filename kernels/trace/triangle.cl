/* Watertight ray/triangle intersection (Woop, Benthin & Wald 2013, "Watertight
 * Ray/Triangle Intersection", JCGT 2(1)). The vertices are translated to the ray
 * origin and sheared so the ray runs along +z; the 2D edge functions of a shared edge
 * are then computed from identical values in both triangles, so a ray through an edge
 * or a vertex cannot slip between neighbours. No backface culling. */
#ifndef FACET_TRACE_TRIANGLE_CL
#define FACET_TRACE_TRIANGLE_CL

#include "kernels/shared/bvh_layout.h"
#include "kernels/util/math.cl"

/* Per-ray part of the test (section 3 of the paper). */
typedef struct {
    int kx, ky, kz;   /* kz: dominant axis of d; (kx, ky) keep the winding */
    float sx, sy, sz; /* shear constants */
} TriRay;

inline float axis_of(float3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }

inline TriRay tri_ray_setup(float3 d) {
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
    return r;
}

/* a*b - c*d with an error under 1.5 ulps, so its sign is exact (Kahan's algorithm
 * with fma); the paper falls back to double precision instead, which OpenCL C 1.2
 * devices need not have. */
inline float diff_of_products(float a, float b, float c, float d) {
    float cd = c * d;
    float err = fma(-c, d, cd);
    return fma(a, b, -cd) + err;
}

/* Intersects the ray with triangle (p0, p1, p2). On a hit with 0 < t < tmax returns
 * true with t and the barycentric weights u (of p1) and v (of p2). */
inline bool intersect_triangle(const TriRay* r, float3 o, float3 p0, float3 p1, float3 p2, float tmax, float* t_out,
                               float* u_out, float* v_out) {
    /* No fma contraction: the edge functions of a shared edge must be exact negatives
     * of each other in the two triangles (OpenCL C contracts by default). */
#pragma OPENCL FP_CONTRACT OFF
    /* Translate to the origin, then shear. */
    float3 a3 = p0 - o, b3 = p1 - o, c3 = p2 - o;
    float az = axis_of(a3, r->kz), bz = axis_of(b3, r->kz), cz = axis_of(c3, r->kz);
    float ax = axis_of(a3, r->kx) - r->sx * az, ay = axis_of(a3, r->ky) - r->sy * az;
    float bx = axis_of(b3, r->kx) - r->sx * bz, by = axis_of(b3, r->ky) - r->sy * bz;
    float cx = axis_of(c3, r->kx) - r->sx * cz, cy = axis_of(c3, r->ky) - r->sy * cz;

    /* Scaled barycentrics: the edge functions. */
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) { /* on an edge: recompute exactly-signed */
        u = diff_of_products(cx, by, cy, bx);
        v = diff_of_products(ax, cy, ay, cx);
        w = diff_of_products(bx, ay, by, ax);
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    float det = u + v + w;
    if (det == 0.0f) return false;

    /* Scaled distance, compared before the division. */
    az *= r->sz;
    bz *= r->sz;
    cz *= r->sz;
    float tt = u * az + v * bz + w * cz;
    float t = tt / det;
    /* Edge functions ~ size^2 times distances ~ size overflow past ~5e12 (the scene
     * format allows 1e18): then weight the distances by the barycentrics instead. */
    if (!isfinite(tt)) t = (u / det) * az + (v / det) * bz + (w / det) * cz;
    if (!(t > 0.0f && t < tmax)) return false;
    float inv = 1.0f / det;
    *t_out = t;
    *u_out = v * inv;
    *v_out = w * inv;
    return true;
}

inline bool intersect_fc_triangle(const TriRay* r, float3 o, __global const FcTriangle* tri, float tmax, float* t,
                                  float* u, float* v) {
    float3 p0 = load3(tri->v0);
    float3 p1 = load3(tri->v1);
    float3 p2 = load3(tri->v2);
    return intersect_triangle(r, o, p0, p1, p2, tmax, t, u, v);
}

#endif
