/* The traversal of a binary BVH (kernels/shared/binary_node_layout.h), written once for
 * every tree of that layout: the spheres' (sphere.cl) and the instances' top level
 * (instance.cl). The leaf test is a parameter, as pbrt-v4's BVHAggregate takes any
 * primitive: OpenCL C has no function pointers, so the loop is a macro expanded in each
 * caller with the caller's leaf test. */
#ifndef FACET_TRACE_BINARY_TRAVERSE_CL
#define FACET_TRACE_BINARY_TRAVERSE_CL

#include "kernels/shared/binary_node_layout.h"
#include "kernels/trace/bvh_traverse.cl"

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
            float fc_ta, fc_tb;                                                                \
            bool fc_ha = box_hit(&fc_br, fc_n->a_lo, fc_n->a_hi, (HIT)->t, &fc_ta);            \
            bool fc_hb = box_hit(&fc_br, fc_n->b_lo, fc_n->b_hi, (HIT)->t, &fc_tb);            \
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
