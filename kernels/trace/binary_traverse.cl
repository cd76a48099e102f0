/* The traversal of a binary BVH (kernels/shared/binary_node_layout.h), written once for
 * every tree of that layout: the spheres' (sphere.cl) and the instances' top level
 * (instance.cl). The leaf test is a parameter, as pbrt-v4's BVHAggregate takes any
 * primitive: OpenCL C has no function pointers, so the loop is a macro expanded in each
 * caller with the caller's leaf test. */
#ifndef FACET_TRACE_BINARY_TRAVERSE_CL
#define FACET_TRACE_BINARY_TRAVERSE_CL

#include "kernels/shared/binary_node_layout.h"
#include "kernels/trace/bvh_traverse.cl"

/* box_hit()'s slab along one axis for both children at once (lane 0 = a, lane 1 = b), the
 * same operations lane by lane, so the same entry distances and answers bit for bit. */
#define FC_SLAB2(lo, hi, o, inv, neg, tn, tf)     \
    do {                                          \
        float2 t0_ = ((neg) ? (hi) : (lo)) - (o); \
        float2 t1_ = ((neg) ? (lo) : (hi)) - (o); \
        t0_ *= (inv);                             \
        t1_ *= (inv);                             \
        t1_ *= FC_SLAB_SCALE;                     \
        tn = select(tn, t0_, t0_ > tn);           \
        tf = select(tf, t1_, t1_ < tf);           \
    } while (0)

/* Whether the ray meets each child box of node `n` within [0, tmax] (lanes a, b: -1 where
 * hit), the entry distances in *tnear. The node is read as four float4 rows (a_lo, a_hi,
 * b_lo, b_hi, each with its index or count in w) and the two boxes tested as float2 lanes:
 * PoCL's LLVM vectorised the two scalar box_hit() calls only in part (docs/performance.md,
 * "Where a sample's time goes"). */
inline int2 box2_hit(const BoxRay* r, __global const FcBinaryNode* n, float tmax, float2* tnear) {
    __global const float* f = (__global const float*)n;
    const float4 alo = vload4(0, f), ahi = vload4(1, f), blo = vload4(2, f), bhi = vload4(3, f);
    float2 tn = (float2)(0.0f), tf = (float2)(tmax);
    FC_SLAB2((float2)(alo.x, blo.x), (float2)(ahi.x, bhi.x), r->o.x, r->inv_d.x, r->neg.x, tn, tf);
    FC_SLAB2((float2)(alo.y, blo.y), (float2)(ahi.y, bhi.y), r->o.y, r->inv_d.y, r->neg.y, tn, tf);
    FC_SLAB2((float2)(alo.z, blo.z), (float2)(ahi.z, bhi.z), r->o.z, r->inv_d.z, r->neg.z, tn, tf);
    *tnear = tn;
    return tn <= tf;
}

/* Traverses tree `NODES` (__global const FcBinaryNode*, root at 0) for the ray o + t d with
 * 0 < t < HIT->t: at each node both children's boxes, leaves first (LEAF_HIT(first, count),
 * an expression that tests the leaf's primitives [first, first + count), shortens HIT->t and
 * says whether it hit), then the nearer inner child, the farther on the stack; a stack entry
 * farther than the nearest hit is skipped when popped. Sets FOUND (a bool lvalue) when a
 * leaf test hit; with ANY_HIT true, the first hit returns true from the enclosing function. */
#define FC_BINARY_TRAVERSE(NODES, O, D, HIT, ANY_HIT, FOUND, LEAF_HIT)                         \
    do {                                                                                       \
        const BoxRay fc_br = box_ray_setup((O), (D));                                          \
        int fc_stack_node[FC_BINARY_STACK_SIZE];                                               \
        float fc_stack_t[FC_BINARY_STACK_SIZE];                                                \
        int fc_sp = 0, fc_node = 0;                                                            \
        while (fc_node >= 0) {                                                                 \
            __global const FcBinaryNode* fc_n = &(NODES)[fc_node];                             \
            float2 fc_t;                                                                       \
            const int2 fc_h = box2_hit(&fc_br, fc_n, (HIT)->t, &fc_t);                         \
            const float fc_ta = fc_t.x, fc_tb = fc_t.y;                                        \
            bool fc_ha = fc_h.x != 0, fc_hb = fc_h.y != 0;                                     \
            if (fc_ha && fc_n->a_count > 0) {                                                  \
                fc_ha = false;                                                                 \
                if (LEAF_HIT(fc_n->a_index, fc_n->a_count)) {                                  \
                    if (ANY_HIT) return true;                                                  \
                    (FOUND) = true;                                                            \
                }                                                                              \
            }                                                                                  \
            if (fc_hb && fc_n->b_count > 0) {                                                  \
                fc_hb = false;                                                                 \
                if (LEAF_HIT(fc_n->b_index, fc_n->b_count)) {                                  \
                    if (ANY_HIT) return true;                                                  \
                    (FOUND) = true;                                                            \
                }                                                                              \
            }                                                                                  \
            if (fc_ha && fc_hb) {                                                              \
                const bool fc_b_first = fc_tb < fc_ta;                                         \
                if (fc_sp < FC_BINARY_STACK_SIZE) { /* always, by the builder's depth limit */ \
                    fc_stack_node[fc_sp] = fc_b_first ? fc_n->a_index : fc_n->b_index;         \
                    fc_stack_t[fc_sp] = fc_b_first ? fc_ta : fc_tb;                            \
                    ++fc_sp;                                                                   \
                }                                                                              \
                fc_node = fc_b_first ? fc_n->b_index : fc_n->a_index;                          \
            } else if (fc_ha) {                                                                \
                fc_node = fc_n->a_index;                                                       \
            } else if (fc_hb) {                                                                \
                fc_node = fc_n->b_index;                                                       \
            } else {                                                                           \
                /* Pop the next entry still nearer than the nearest hit; none left ends it. */ \
                fc_node = -1;                                                                  \
                while (fc_sp > 0) {                                                            \
                    --fc_sp;                                                                   \
                    if (fc_stack_t[fc_sp] <= (HIT)->t) {                                       \
                        fc_node = fc_stack_node[fc_sp];                                        \
                        break;                                                                 \
                    }                                                                          \
                }                                                                              \
            }                                                                                  \
        }                                                                                      \
    } while (0)

#endif
