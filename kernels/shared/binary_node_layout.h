/* The node of facet's small binary BVHs: the analytic spheres' tree (sphere_layout.h) and
 * the instances' top-level tree (instance_layout.h), both built by host/bvh/binary_tree.hpp
 * and traversed by kernels/trace/binary_traverse.cl.
 *
 * A node stores both children's boxes (as host/bvh's binary SAH tree does): a child is an
 * inner node (count == 0, index = node index), a leaf (count > 0 primitives from index
 * `index` of the tree's primitive array) or empty (count == 0, index == 0, inverted box
 * lo = +inf, hi = -inf, never hit; index 0 is the root, never a child). A tree over no
 * primitives is a root with two empty children. */
#ifndef FACET_SHARED_BINARY_NODE_LAYOUT_H
#define FACET_SHARED_BINARY_NODE_LAYOUT_H

#include "kernels/shared/types.h"

/* A binary node: children a and b, each a box and a reference. */
typedef struct FcBinaryNode {
    float a_lo[3];
    fc_int a_index;
    float a_hi[3];
    fc_int a_count;
    float b_lo[3];
    fc_int b_index;
    float b_hi[3];
    fc_int b_count;
} FcBinaryNode;

/* Entries of the traversal's stack: one push per binary level, and the builder keeps the
 * tree at most this deep. */
#define FC_BINARY_STACK_SIZE 48

FC_STATIC_ASSERT(sizeof(FcBinaryNode) == 64, "FcBinaryNode is 64 bytes");
FC_STATIC_ASSERT(offsetof(FcBinaryNode, b_lo) == 32 && offsetof(FcBinaryNode, b_count) == 60, "FcBinaryNode offsets");

#endif
