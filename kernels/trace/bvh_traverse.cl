/* BVH traversal over the 4- or 8-wide nodes of shared/bvh_layout.h (FC_BVH_WIDTH; with
 * FC_BVH_QUANTISED the 8-wide nodes' boxes are bytes, decoded to float8 per node): one
 * node fetch tests all its child boxes with float4 or float8 arithmetic, leaves are
 * intersected four triangles a block (kernels/trace/triangle.cl) and the nearest inner
 * child is visited next, the others pushed farthest first on a small private stack
 * (Aila & Laine 2009, "Understanding the efficiency of ray traversal on GPUs"; Wald et
 * al. 2008 for the wide node; Embree's BVH8 for the 8-wide one). The host keeps every
 * path's pushes within FC_BVH_STACK_SIZE (4-wide) or FC_BVH8_STACK_SIZE (8-wide). An
 * empty slot has an inverted box (min = +inf, max = -inf), which the slab test never
 * reports. */
#ifndef FACET_TRACE_BVH_CL
#define FACET_TRACE_BVH_CL

#include "kernels/shared/bvh_layout.h"
#include "kernels/trace/alpha_test.cl"
#include "kernels/trace/ray.cl"
#include "kernels/trace/triangle.cl"

typedef struct {
    float t;
    float u;  /* barycentric weight of v1 */
    float v;  /* barycentric weight of v2 */
    int prim; /* FcTriangle.prim of the hit triangle (its scene index); -1 on a miss */
    int tri;  /* index of the hit triangle in BVH order (the FcTriangle array) */
    int inst; /* the instance the triangle was met in (kernels/trace/instance.cl), or -1 */
} Hit;

/* 1 + 2 * gamma(3), gamma(n) = n*eps / (1 - n*eps), eps = 2^-24: scaling the exit
 * distance by it makes the slab test conservative under rounding (Ize 2013, "Robust
 * BVH Ray Traversal"; pbrt-v3 section 3.9.2). */
#define FC_SLAB_SCALE 1.0000003576279f

/* Per-ray constants of the slab test. inv_d may hold infinities (zero components). */
typedef struct {
    float3 o;
    float3 inv_d;
    int3 neg; /* 1 where the direction is negative (the near plane is max) */
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
#define FC_SLAB(lo, hi, o, inv, neg, tn, tf)     \
    do {                                         \
        float t0_ = ((neg) ? (hi) : (lo)) - (o); \
        float t1_ = ((neg) ? (lo) : (hi)) - (o); \
        t0_ *= (inv);                            \
        t1_ *= (inv);                            \
        t1_ *= FC_SLAB_SCALE;                    \
        tn = t0_ > tn ? t0_ : tn;                \
        tf = t1_ < tf ? t1_ : tf;                \
    } while (0)

/* Whether the ray meets box [lo, hi] within [0, tmax]; the entry distance in *tnear. */
inline bool box_hit(const BoxRay* r, __global const float* lo, __global const float* hi, float tmax, float* tnear) {
    float tn = 0.0f, tf = tmax;
    FC_SLAB(lo[0], hi[0], r->o.x, r->inv_d.x, r->neg.x, tn, tf);
    FC_SLAB(lo[1], hi[1], r->o.y, r->inv_d.y, r->neg.y, tn, tf);
    FC_SLAB(lo[2], hi[2], r->o.z, r->inv_d.z, r->neg.z, tn, tf);
    *tnear = tn;
    return tn <= tf;
}

#if FC_HAS_ALPHA
/* The hit lanes of a block whose triangles' alpha tests keep them. */
inline int4 alpha_lanes(const AlphaTest* alpha, int4 mask, int4 tri, float4 t, float4 v, float4 w, float4 det) {
    const int ms[4] = {mask.x, mask.y, mask.z, mask.w}, tris[4] = {tri.x, tri.y, tri.z, tri.w};
    const float ts[4] = {t.x, t.y, t.z, t.w};
    int keep[4];
    for (uint lane = 0; lane < 4u; ++lane) {
        keep[lane] = 0;
        if (!ms[lane]) continue;
        float b1, b2;
        tri4_weights(v, w, det, lane, &b1, &b2);
        keep[lane] = alpha_keeps(alpha, tris[lane], ts[lane], b1, b2) ? -1 : 0;
    }
    return (int4)(keep[0], keep[1], keep[2], keep[3]);
}
#endif

/* Intersects the leaf of `blocks` blocks from row `row` of the node buffer, a block of
 * four lanes at a time; with `any_hit`, stops at the first hit. Within a block the
 * nearest hit lane wins (the lowest on a tie), and a later block's hit must be strictly
 * nearer: the hit a loop over the triangles in order would keep. With `alpha` (programs
 * with FC_HAS_ALPHA), hit lanes whose alpha test fails (alpha_test.cl) are dropped first. */
/* Inlined by force, with tri4_hit: PoCL's LLVM called both out of line, the block's nine
 * rows spilled between them (docs/performance.md: 7-9% fewer trace instructions inlined). */
__attribute__((always_inline)) inline bool leaf_hit(__global const float4* rows, int row, int blocks, const TriRay* tr,
                                                    Hit* hit, bool any_hit, const AlphaTest* alpha) {
    bool found = false;
    for (; blocks > 0; --blocks, row += 10) {
        __global const float4* b = rows + row;
        const Tri4 p = tri4_load(b, tr);
        float4 t, v, w, det;
        int4 mask = tri4_hit(tr, &p, hit->t, &t, &v, &w, &det);
        if (!any(mask)) continue;
#if FC_HAS_ALPHA
        if (alpha) {
            mask = alpha_lanes(alpha, mask, vload4(0, (__global const int*)(b + 9)), t, v, w, det);
            if (!any(mask)) continue;
        }
#else
        (void)alpha;
#endif
        if (any_hit) return true;
        const uint lane = tri4_nearest(mask, t);
        const int4 tri = vload4(0, (__global const int*)(b + 9));
        const float ts[4] = {t.x, t.y, t.z, t.w};
        const int tris[4] = {tri.x, tri.y, tri.z, tri.w};
        hit->t = ts[lane];
        hit->tri = tris[lane];
        tri4_weights(v, w, det, lane, &hit->u, &hit->v);
        found = true;
    }
    return found;
}

/* The node layout the program reads (FcBvhNode, FcBvhNode8 or, with FC_BVH_QUANTISED,
 * FcBvhNodeQ), set by the host from the tree it uploads (bvh_prelude); the children's
 * masks and distances are FC_W-lane vectors. */
#ifndef FC_BVH_WIDTH
#define FC_BVH_WIDTH 4
#endif
#ifndef FC_BVH_QUANTISED
#define FC_BVH_QUANTISED 0
#endif
#if FC_BVH_QUANTISED && FC_BVH_WIDTH != 8
#error "FC_BVH_QUANTISED needs FC_BVH_WIDTH 8"
#endif
#if FC_BVH_WIDTH == 8
#define FC_W 8
#define FC_STACK FC_BVH8_STACK_SIZE
#if FC_BVH_QUANTISED
typedef FcBvhNodeQ FcNode;
#else
typedef FcBvhNode8 FcNode;
#endif
typedef float8 floatW;
typedef int8 intW;
#define FC_VLOADW vload8
#define FC_VSTOREW vstore8
/* An 8-bit mask from an int8 of 0 / -1 lanes: bit c set where lane c is. With AVX (PoCL
 * on x86 CPUs) one vmovmskps of the lanes' sign bits; lane by lane, PoCL's code extracted
 * and or-reduced the halves (about 17 instructions: the movmskps form took 6-7% off the
 * trace kernels' instructions, docs/performance.md). Elsewhere (GPUs, Oclgrind) lane by lane. */
#if defined(__AVX__) && defined(__clang__)
typedef float fc_v8sf __attribute__((__vector_size__(32)));
inline uint lane_bits_w(int8 m) {
    return (uint)__builtin_ia32_movmskps256(__builtin_convertvector(as_float8(m), fc_v8sf));
}
#else
inline uint lane_bits_w(int8 m) { return lane_bits(m.lo) | (lane_bits(m.hi) << 4); }
#endif
#elif FC_BVH_WIDTH == 4
#define FC_W 4
#define FC_STACK FC_BVH_STACK_SIZE
typedef FcBvhNode FcNode;
typedef float4 floatW;
typedef int4 intW;
#define FC_VLOADW vload4
#define FC_VSTOREW vstore4
inline uint lane_bits_w(int4 m) { return lane_bits(m); }
#else
#error "FC_BVH_WIDTH must be 4 or 8"
#endif

/* The entry and exit distances tn, tf of a box test narrowed by one axis' entry t0 and exit
 * t1, in lanes (children, or a packet's rays): NaN entries and exits are ignored (select
 * keeps the running value where the comparison is false). */
#define FC_SLAB_NARROW(tn, tf, t0, t1) \
    do {                               \
        tn = select(tn, t0, t0 > tn);  \
        tf = select(tf, t1, t1 < tf);  \
    } while (0)

/* All children of a node at once: the node's boxes are structure-of-arrays, so each
 * slab is one FC_W-lane operation over the children. The near and far planes are
 * picked by the direction's signs through row indices set up once per ray (near[a],
 * far[a]: which vector of the node holds axis a's entry and exit planes), so the
 * choice costs no branch per node; the arithmetic is box_hit()'s, operation for
 * operation: (plane - o) * inv_d, the exit scaled by FC_SLAB_SCALE, NaN entries and
 * exits ignored by the comparisons (select keeps the running value where the
 * comparison is false). Returns a mask (-1 where hit) and the entry distances in
 * *tnear. */
inline intW slabs_hit(floatW nx, floatW fx, floatW ny, floatW fy, floatW nz, floatW fz, float3 o, float3 inv_d,
                      float tmax, floatW* tnear) {
    floatW t0x = (nx - o.x) * inv_d.x;
    floatW t1x = (fx - o.x) * inv_d.x;
    floatW t0y = (ny - o.y) * inv_d.y;
    floatW t1y = (fy - o.y) * inv_d.y;
    floatW t0z = (nz - o.z) * inv_d.z;
    floatW t1z = (fz - o.z) * inv_d.z;
    t1x *= FC_SLAB_SCALE;
    t1y *= FC_SLAB_SCALE;
    t1z *= FC_SLAB_SCALE;
    floatW tn = (floatW)(0.0f), tf = (floatW)(tmax);
    FC_SLAB_NARROW(tn, tf, t0x, t1x);
    FC_SLAB_NARROW(tn, tf, t0y, t1y);
    FC_SLAB_NARROW(tn, tf, t0z, t1z);
    *tnear = tn;
    return tn <= tf;
}

#if FC_BVH_QUANTISED
/* The quantised node's planes decoded as the host rounded them, origin + q * scale
 * (q * scale is exact, so contraction into an fma changes nothing), then the slabs.
 * `head` is the node's first row: the origin and the exponents. */
inline int8 children_hit(__global const FcNode* n, float4 head, float3 o, float3 inv_d, int3 near, int3 far, float tmax,
                         float8* tnear) {
    __global const uchar8* q = (__global const uchar8*)n->q_lo_x;
    const uint e = as_uint(head.w);
    const float sx = as_float((e & 0xffu) << 23), sy = as_float(((e >> 8) & 0xffu) << 23),
                sz = as_float(((e >> 16) & 0xffu) << 23);
    return slabs_hit(head.x + convert_float8(q[near.x]) * sx, head.x + convert_float8(q[far.x]) * sx,
                     head.y + convert_float8(q[near.y]) * sy, head.y + convert_float8(q[far.y]) * sy,
                     head.z + convert_float8(q[near.z]) * sz, head.z + convert_float8(q[far.z]) * sz, o, inv_d, tmax,
                     tnear);
}
#endif

/* The float node of the program's width: the triangles' tree unless it is quantised, and
 * always the small trees of the spheres and the instances (small_tree_traverse.cl). */
#if FC_W == 8
typedef FcBvhNode8 FcFloatNode;
#else
typedef FcBvhNode FcFloatNode;
#endif

inline intW float_children_hit(__global const FcFloatNode* n, float3 o, float3 inv_d, int3 near, int3 far, float tmax,
                               floatW* tnear) {
    /* Whole-vector loads (nodes are aligned to their size): vload8 became two 16-byte
     * loads and an insert in PoCL's code. */
    __global const floatW* v = (__global const floatW*)n;
    return slabs_hit(v[near.x], v[far.x], v[near.y], v[far.y], v[near.z], v[far.z], o, inv_d, tmax, tnear);
}

/* The step after a node's leaves, shared by every wide traversal: with no hit inner child,
 * the next stack entry still nearer than HIT_T (none left: EXIT); with one, that child;
 * with two, the nearer, the other pushed; with more, insertion by entry distance, the
 * nearest entered and the rest pushed farthest first. INNER (a uint of lanes) and TNW (the
 * entry distances) are the node's; CHILD(c) gives inner child c's node index. Used inside
 * the traversal's loop (its `continue`s are the loop's); the host keeps the pushes within
 * FC_STACK. */
#define FC_WIDE_NEXT(INNER, TNW, STACK_NODE, STACK_T, SP, NODE, HIT_T, CHILD, EXIT) \
    {                                                                               \
        if (!(INNER)) {                                                             \
            /* Pop the next entry still nearer than the nearest hit. */             \
            for (;;) {                                                              \
                if ((SP) == 0) EXIT;                                                \
                --(SP);                                                             \
                if ((STACK_T)[SP] <= (HIT_T)) break;                                \
            }                                                                       \
            (NODE) = (STACK_NODE)[SP];                                              \
            continue;                                                               \
        }                                                                           \
        const uint fc_c0 = lowest_bit(INNER);                                       \
        (INNER) &= (INNER)-1u;                                                      \
        if (!(INNER)) {                                                             \
            (NODE) = CHILD(fc_c0);                                                  \
            continue;                                                               \
        }                                                                           \
        float fc_tn[FC_W];                                                          \
        FC_VSTOREW(TNW, 0, fc_tn);                                                  \
        const uint fc_c1 = lowest_bit(INNER);                                       \
        (INNER) &= (INNER)-1u;                                                      \
        if (!(INNER)) {                                                             \
            const bool fc_swap = fc_tn[fc_c1] < fc_tn[fc_c0];                       \
            const uint fc_nearer = fc_swap ? fc_c1 : fc_c0;                         \
            const uint fc_farther = fc_swap ? fc_c0 : fc_c1;                        \
            if ((SP) < FC_STACK) { /* always, by the builder */                     \
                (STACK_NODE)[SP] = CHILD(fc_farther);                               \
                (STACK_T)[SP] = fc_tn[fc_farther];                                  \
                ++(SP);                                                             \
            }                                                                       \
            (NODE) = CHILD(fc_nearer);                                              \
            continue;                                                               \
        }                                                                           \
        /* Three or more: insertion by entry distance, farthest at 0. */            \
        int fc_order[FC_W];                                                         \
        float fc_dist[FC_W];                                                        \
        fc_order[0] = (int)fc_c0;                                                   \
        fc_dist[0] = fc_tn[fc_c0];                                                  \
        int fc_k = 1;                                                               \
        (INNER) |= 1u << fc_c1;                                                     \
        do {                                                                        \
            const uint fc_c = lowest_bit(INNER);                                    \
            (INNER) &= (INNER)-1u;                                                  \
            int fc_j = fc_k++;                                                      \
            for (; fc_j > 0 && fc_dist[fc_j - 1] < fc_tn[fc_c]; --fc_j) {           \
                fc_dist[fc_j] = fc_dist[fc_j - 1];                                  \
                fc_order[fc_j] = fc_order[fc_j - 1];                                \
            }                                                                       \
            fc_dist[fc_j] = fc_tn[fc_c];                                            \
            fc_order[fc_j] = (int)fc_c;                                             \
        } while (INNER);                                                            \
        for (int fc_j = 0; fc_j + 1 < fc_k; ++fc_j)                                 \
            if ((SP) < FC_STACK) { /* always, by the builder */                     \
                (STACK_NODE)[SP] = CHILD((uint)fc_order[fc_j]);                     \
                (STACK_T)[SP] = fc_dist[fc_j];                                      \
                ++(SP);                                                             \
            }                                                                       \
        (NODE) = CHILD((uint)fc_order[fc_k - 1]);                                   \
    }

/* The node index of hit inner child c: from the float node's index row, or, quantised,
 * by its rank among the node's inner children. */
#if FC_BVH_QUANTISED
#define FC_CHILD(c) (child_base + (int)popcount(inner_slots & ((1u << (c)) - 1u)))
#else
#define FC_CHILD(c) (idx[c])
#endif

/* The traversal shared by trace_closest and trace_any, from node `start` (the root: 0; a
 * packet's traversal, kernels/trace/packet_trace.cl, hands a subtree to single rays). Per node: all boxes in one go,
 * then the hit leaves (their hits shorten the ray before any inner child is entered),
 * then the hit inner children, nearest first: with one there is nothing to sort, with
 * two one comparison, with more an insertion sort. The others go on the stack with
 * their entry distance, and an entry farther than the nearest hit found since is
 * dropped when popped, without fetching its node. */
inline bool trace_bvh_at(__global const FcBvhNode* buffer, int start, float3 o, float3 d, Hit* hit, bool any,
                         const AlphaTest* alpha) {
    const BoxRay br = box_ray_setup(o, d);
    const TriRay tr = tri_ray_setup(o, d);
    __global const FcNode* nodes = (__global const FcNode*)buffer;
    __global const float4* rows = (__global const float4*)buffer;
    /* Vectors of the node: lo_x lo_y lo_z hi_x hi_y hi_z. */
    const int3 near_row = (int3)(0, 1, 2) + 3 * br.neg;
    const int3 far_row = (int3)(3, 4, 5) - 3 * br.neg;
    int stack_node[FC_STACK];
    float stack_t[FC_STACK];
    int sp = 0;
    int node = start;
    bool found = false;
    for (;;) {
        __global const FcNode* n = &nodes[node];
        floatW tnw;
#if FC_BVH_QUANTISED
        /* Leaves and inner children from one mask: the node marks its inner slots. An
         * empty slot reported hit by rounding is a leaf of no blocks. */
        const float4 head = *(__global const float4*)n;
        const uint inner_slots = as_uint(head.w) >> 24;
        const uint hits = lane_bits_w(children_hit(n, head, o, br.inv_d, near_row, far_row, hit->t, &tnw));
        uint leaves = hits & ~inner_slots;
        uint inner = hits & inner_slots;
#else
        const intW mask = float_children_hit(n, o, br.inv_d, near_row, far_row, hit->t, &tnw);
        const intW count = FC_VLOADW(0, n->count);
        const intW index = FC_VLOADW(0, n->index);
        uint leaves = lane_bits_w(mask & (count > 0));
        uint inner = lane_bits_w(mask & (count <= 0)); /* empty slots are never hit */
        int idx[FC_W];
        FC_VSTOREW(index, 0, idx);
#endif
        if (leaves) {
#if FC_BVH_QUANTISED
            const ulong meta = as_ulong(vload2(0, n->meta));
            const int leaf_base = n->leaf_base;
#else
            int cnt[FC_W];
            FC_VSTOREW(count, 0, cnt);
#endif
            do {
                const uint c = lowest_bit(leaves);
                leaves &= leaves - 1u;
#if FC_BVH_QUANTISED
                const uint m = (uint)(meta >> (8u * c)) & 0xffu; /* blocks | first << 3 */
                const int row = leaf_base + 10 * (int)(m >> 3), blocks = (int)(m & 7u);
#else
                const int row = idx[c], blocks = (cnt[c] + 3) >> 2;
#endif
                if (leaf_hit(rows, row, blocks, &tr, hit, any, alpha)) {
                    found = true;
                    if (any) return true;
                }
            } while (leaves);
        }
#if FC_BVH_QUANTISED
        const int child_base = n->child_base;
#endif
        FC_WIDE_NEXT(inner, tnw, stack_node, stack_t, sp, node, hit->t, FC_CHILD, return found);
    }
}
#undef FC_CHILD

/* The traversal from the root. */
inline bool trace_bvh(__global const FcBvhNode* buffer, float3 o, float3 d, Hit* hit, bool any,
                      const AlphaTest* alpha) {
    return trace_bvh_at(buffer, 0, o, d, hit, any, alpha);
}

/* trace_bvh on the tree whose buffer starts `root` FcBvhNode units into `buffer` (an
 * instanced mesh's BLAS, kernels/shared/instance_layout.h): its node and row indices count
 * from there; hit->tri is then its own triangle index. */
inline bool trace_bvh_from(__global const FcBvhNode* buffer, int root, float3 o, float3 d, Hit* hit, bool any,
                           const AlphaTest* alpha) {
    return trace_bvh(buffer + root, o, d, hit, any, alpha);
}

/* Nearest hit with 0 < t < tmax whose alpha test (if any) keeps it. */
inline bool trace_closest_alpha(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o, float3 d,
                                float tmax, Hit* hit, const AlphaTest* alpha) {
    hit->t = tmax;
    hit->u = 0.0f;
    hit->v = 0.0f;
    hit->prim = -1;
    hit->tri = -1;
    hit->inst = -1;
    if (!trace_bvh(nodes, o, d, hit, false, alpha)) return false;
    hit->prim = tris[hit->tri].prim;
    return true;
}

/* Nearest hit with 0 < t < tmax. */
inline bool trace_closest(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o, float3 d,
                          float tmax, Hit* hit) {
    return trace_closest_alpha(nodes, tris, o, d, tmax, hit, 0);
}

/* Whether anything that the alpha test (if any) keeps is hit with 0 < t < tmax (shadow rays). */
inline bool trace_any_alpha(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o, float3 d,
                            float tmax, const AlphaTest* alpha) {
    (void)tris; /* the leaves' blocks hold the vertices */
    Hit hit;
    hit.t = tmax;
    hit.prim = -1;
    hit.tri = -1;
    hit.inst = -1;
    return trace_bvh(nodes, o, d, &hit, true, alpha);
}

/* Whether anything is hit with 0 < t < tmax (shadow rays). */
inline bool trace_any(__global const FcBvhNode* nodes, __global const FcTriangle* tris, float3 o, float3 d,
                      float tmax) {
    return trace_any_alpha(nodes, tris, o, d, tmax, 0);
}

#endif
