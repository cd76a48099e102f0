/* The traversal of facet's small trees, written once for both: the analytic spheres'
 * (sphere.cl) and the instances' top level (instance.cl). Their nodes are the float wide
 * nodes of the program's width (FcFloatNode, bvh_traverse.cl: eight child boxes a node on
 * AVX CPUs, four on GPUs), built by host/bvh/small_tree.hpp, each leaf a range of the
 * tree's primitives. The leaf test is a parameter, as pbrt-v4's BVHAggregate takes any
 * primitive: OpenCL C has no function pointers, so the loop is a macro expanded in each
 * caller with the caller's leaf test. */
#ifndef FACET_TRACE_SMALL_TREE_TRAVERSE_CL
#define FACET_TRACE_SMALL_TREE_TRAVERSE_CL

#include "kernels/trace/bvh_traverse.cl"

/* Inner child c of the small tree's node (FC_SMALL_TREE_TRAVERSE's child index row). */
#define FC_SMALL_TREE_CHILD(c) (fc_idx[c])

/* Traverses tree NODES (__global const FcBvhNode*, the buffer of FcFloatNode, root at 0) for
 * the ray o + t d with 0 < t < HIT->t: at each node all child boxes at once, the hit leaves
 * first (LEAF_HIT(first, count), an expression that tests the leaf's primitives [first,
 * first + count), shortens HIT->t and says whether it hit), then the hit inner children
 * nearest first (FC_WIDE_NEXT); a stack entry farther than the nearest hit is skipped when
 * popped. Sets FOUND (a bool lvalue) when a leaf test hit; with ANY_HIT true the first hit
 * returns true from the enclosing function, and the traversal ends by returning FOUND from
 * it (so nothing may follow the macro in that function). */
#define FC_SMALL_TREE_TRAVERSE(NODES, O, D, HIT, ANY_HIT, FOUND, LEAF_HIT)                                           \
    do {                                                                                                             \
        const BoxRay fc_br = box_ray_setup((O), (D));                                                                \
        const int3 fc_near = (int3)(0, 1, 2) + 3 * fc_br.neg;                                                        \
        const int3 fc_far = (int3)(3, 4, 5) - 3 * fc_br.neg;                                                         \
        __global const FcFloatNode* fc_nodes = (__global const FcFloatNode*)(NODES);                                 \
        int fc_stack_node[FC_STACK];                                                                                 \
        float fc_stack_t[FC_STACK];                                                                                  \
        int fc_sp = 0, fc_node = 0;                                                                                  \
        for (;;) {                                                                                                   \
            __global const FcFloatNode* fc_n = &fc_nodes[fc_node];                                                   \
            floatW fc_tnw;                                                                                           \
            const intW fc_mask = float_children_hit(fc_n, fc_br.o, fc_br.inv_d, fc_near, fc_far, (HIT)->t, &fc_tnw); \
            const intW fc_count = FC_VLOADW(0, fc_n->count);                                                         \
            uint fc_leaves = lane_bits_w(fc_mask & (fc_count > 0));                                                  \
            uint fc_inner = lane_bits_w(fc_mask & (fc_count <= 0)); /* empty slots are never hit */                  \
            int fc_idx[FC_W];                                                                                        \
            FC_VSTOREW(FC_VLOADW(0, fc_n->index), 0, fc_idx);                                                        \
            if (fc_leaves) {                                                                                         \
                int fc_cnt[FC_W];                                                                                    \
                FC_VSTOREW(fc_count, 0, fc_cnt);                                                                     \
                do {                                                                                                 \
                    const uint fc_c = lowest_bit(fc_leaves);                                                         \
                    fc_leaves &= fc_leaves - 1u;                                                                     \
                    if (LEAF_HIT(fc_idx[fc_c], fc_cnt[fc_c])) {                                                      \
                        if (ANY_HIT) return true;                                                                    \
                        (FOUND) = true;                                                                              \
                    }                                                                                                \
                } while (fc_leaves);                                                                                 \
            }                                                                                                        \
            FC_WIDE_NEXT(fc_inner, fc_tnw, fc_stack_node, fc_stack_t, fc_sp, fc_node, (HIT)->t, FC_SMALL_TREE_CHILD, \
                         return (FOUND));                                                                            \
        }                                                                                                            \
    } while (0)

#endif
