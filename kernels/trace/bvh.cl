/* BVH traversal over the two-children nodes of shared/bvh.h: one node fetch tests
 * both child boxes, leaves are intersected at once and the nearer inner child is
 * visited first, the farther one pushed on a small private stack (Aila & Laine 2009,
 * "Understanding the efficiency of ray traversal on GPUs"). The host builder keeps the
 * tree shallower than FC_BVH_STACK_SIZE. An empty child is an inner reference with an
 * inverted box (min = +inf, max = -inf), which box_hit() never reports. */
#ifndef FACET_TRACE_BVH_CL
#define FACET_TRACE_BVH_CL

#include "../shared/bvh.h"
#include "ray.cl"
#include "triangle.cl"

typedef struct {
    float t;
    float u;     /* barycentric weight of v1 */
    float v;     /* barycentric weight of v2 */
    int prim;    /* FcTriangle.prim of the hit triangle (its scene index); -1 on a miss */
    int tri;     /* index of the hit triangle in BVH order (the FcTriangle array) */
} Hit;

/* 1 + 2 * gamma(3), gamma(n) = n*eps / (1 - n*eps), eps = 2^-24: scaling the exit
 * distance by it makes the slab test conservative under rounding (Ize 2013, "Robust
 * BVH Ray Traversal"; pbrt-v3 section 3.9.2). */
#define FC_SLAB_SCALE 1.0000003576279f

/* Per-ray constants of the slab test. inv_d may hold infinities (zero components). */
typedef struct {
    float3 o;
    float3 inv_d;
    int3 neg;    /* 1 where the direction is negative (the near plane is max) */
} BoxRay;

inline BoxRay box_ray_setup(float3 o, float3 d) {
    BoxRay r;
    r.o = o;
    r.inv_d = (float3)(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
    r.neg = (int3)(r.inv_d.x < 0.0f, r.inv_d.y < 0.0f, r.inv_d.z < 0.0f);
    return r;
}

/* Entry and exit along one axis; 0 * inf (origin on a slab plane of a parallel ray)
 * gives NaN, which the comparisons in box_hit() ignore, so such a plane counts as
 * inside. */
#define FC_SLAB(lo, hi, o, inv, neg, tn, tf)                       \
    do {                                                           \
        float t0_ = ((neg) ? (hi) : (lo)) - (o);                   \
        float t1_ = ((neg) ? (lo) : (hi)) - (o);                   \
        t0_ *= (inv);                                              \
        t1_ *= (inv);                                              \
        t1_ *= FC_SLAB_SCALE;                                      \
        tn = t0_ > tn ? t0_ : tn;                                  \
        tf = t1_ < tf ? t1_ : tf;                                  \
    } while (0)

/* Whether the ray meets box [lo, hi] within [0, tmax]; the entry distance in *tnear. */
inline bool box_hit(const BoxRay* r, __global const float* lo, __global const float* hi,
                    float tmax, float* tnear) {
    float tn = 0.0f, tf = tmax;
    FC_SLAB(lo[0], hi[0], r->o.x, r->inv_d.x, r->neg.x, tn, tf);
    FC_SLAB(lo[1], hi[1], r->o.y, r->inv_d.y, r->neg.y, tn, tf);
    FC_SLAB(lo[2], hi[2], r->o.z, r->inv_d.z, r->neg.z, tn, tf);
    *tnear = tn;
    return tn <= tf;
}

/* Intersects leaf [first, first + count); with `any`, stops at the first hit. */
inline bool leaf_hit(__global const FcTriangle* tris, int first, int count, const TriRay* tr,
                     float3 o, Hit* hit, bool any) {
    bool found = false;
    for (int i = first; i < first + count; ++i) {
        float t, u, v;
        if (intersect_fc_triangle(tr, o, &tris[i], hit->t, &t, &u, &v)) {
            hit->t = t;
            hit->u = u;
            hit->v = v;
            hit->prim = tris[i].prim;
            hit->tri = i;
            found = true;
            if (any) return true;
        }
    }
    return found;
}

/* Both children of a node at once: the node is read as four float4 (a child's min
 * with its index in .w, its max with its count in .w), and each box's near and far
 * planes are chosen by the direction's signs with one vector select. The arithmetic
 * is box_hit()'s, operation for operation: (plane - o) * inv_d, the exit scaled by
 * FC_SLAB_SCALE, NaN entries and exits ignored by the comparisons. */
inline float fc_slab_max(float a, float b) { return b > a ? b : a; }   /* NaN b: a */
inline float fc_slab_min(float a, float b) { return b < a ? b : a; }

inline bool child_hit(float3 lo, float3 hi, float3 o, float3 inv_d, int3 negm, float tmax, float* tnear) {
    float3 t0 = (select(lo, hi, negm) - o) * inv_d;
    float3 t1 = (select(hi, lo, negm) - o) * inv_d;
    t1 *= FC_SLAB_SCALE;
    float tn = fc_slab_max(fc_slab_max(fc_slab_max(0.0f, t0.x), t0.y), t0.z);
    float tf = fc_slab_min(fc_slab_min(fc_slab_min(tmax, t1.x), t1.y), t1.z);
    *tnear = tn;
    return tn <= tf;
}

/* The traversal shared by trace_closest and trace_any. */
inline bool trace_bvh(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o,
                      float3 d, Hit* hit, bool any) {
    const float3 inv_d = (float3)(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
    const int3 negm = inv_d < (float3)(0.0f);   /* -1 where the near plane is max */
    const TriRay tr = tri_ray_setup(d);
    __global const float4* nodes4 = (__global const float4*)nodes;
    int stack[FC_BVH_STACK_SIZE];
    int sp = 0;
    int node = 0;
    bool found = false;
    for (;;) {
        __global const float4* n = nodes4 + 4 * node;
        const float4 amin = n[0], amax = n[1], bmin = n[2], bmax = n[3];
        const int a_index = as_int(amin.w), a_count = as_int(amax.w);
        const int b_index = as_int(bmin.w), b_count = as_int(bmax.w);
        float ta, tb;
        bool ha = child_hit(amin.xyz, amax.xyz, o, inv_d, negm, hit->t, &ta);
        bool hb = child_hit(bmin.xyz, bmax.xyz, o, inv_d, negm, hit->t, &tb);
        /* Leaves first: their hits shorten the ray before the inner children. */
        if (ha && a_count > 0) {
            if (leaf_hit(tris, a_index, a_count, &tr, o, hit, any)) {
                found = true;
                if (any) return true;
            }
            ha = false;
        }
        if (hb && b_count > 0) {
            if (leaf_hit(tris, b_index, b_count, &tr, o, hit, any)) {
                found = true;
                if (any) return true;
            }
            hb = false;
        }
        if (ha && hb) {
            int near_child = ta <= tb ? a_index : b_index;
            int far_child = ta <= tb ? b_index : a_index;
            if (sp < FC_BVH_STACK_SIZE) stack[sp++] = far_child;   /* always, by the builder */
            node = near_child;
        } else if (ha) {
            node = a_index;
        } else if (hb) {
            node = b_index;
        } else {
            if (sp == 0) break;
            node = stack[--sp];
        }
    }
    return found;
}

/* Nearest hit with 0 < t < tmax. */
inline bool trace_closest(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                          float3 o, float3 d, float tmax, Hit* hit) {
    hit->t = tmax;
    hit->u = 0.0f;
    hit->v = 0.0f;
    hit->prim = -1;
    hit->tri = -1;
    return trace_bvh(nodes, tris, o, d, hit, false);
}

/* Whether anything is hit with 0 < t < tmax (shadow rays). */
inline bool trace_any(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o,
                      float3 d, float tmax) {
    Hit hit;
    hit.t = tmax;
    hit.prim = -1;
    hit.tri = -1;
    return trace_bvh(nodes, tris, o, d, &hit, true);
}

#endif
