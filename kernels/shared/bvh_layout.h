/* BVH and triangle layouts uploaded by the host (host/bvh/) and traversed by
 * kernels/trace/bvh_traverse.cl.
 *
 * The tree is 4-wide: the host builds a binary SAH tree and collapses every node with
 * its children's children into one node of up to four children (depth halves). A node
 * stores its children's boxes as structure-of-arrays, so the traversal tests all four
 * with float4 arithmetic in one work-item and visits them nearest first (Wald et al.
 * 2008, "Getting rid of packets"; Ernst & Greiner 2008, "Multi bounding volume
 * hierarchies"). A child reference is an inner node (count == 0, index = node index),
 * a leaf (count > 0, index = first triangle in the reordered triangle array), or an
 * empty slot (count == 0, index == 0, inverted box lo = +inf, hi = -inf, which the slab
 * test never reports as hit; index 0 is the root, never a child). */
#ifndef FACET_SHARED_BVH_LAYOUT_H
#define FACET_SHARED_BVH_LAYOUT_H

#include "kernels/shared/types.h"

typedef struct FcBvhNode {
    float lo_x[4];
    float lo_y[4];
    float lo_z[4];
    float hi_x[4];
    float hi_y[4];
    float hi_z[4];
    fc_int index[4];
    fc_int count[4];
} FcBvhNode;

/* A triangle as the traversal sees it, in BVH order: three vertices and the index
 * of the triangle in the scene's shading arrays (FcTriShading). */
typedef struct FcTriangle {
    float v0[3];
    fc_int prim;
    float v1[3];
    fc_int pad0;
    float v2[3];
    fc_int pad1;
} FcTriangle;

/* Entries of the traversal stack. A node pushes at most three children, and the host
 * keeps the 4-wide tree at most FC_BVH_STACK_SIZE / 3 nodes deep. */
#define FC_BVH_STACK_SIZE 64

FC_STATIC_ASSERT(sizeof(FcBvhNode) == 128, "FcBvhNode is 128 bytes");
FC_STATIC_ASSERT(offsetof(FcBvhNode, hi_x) == 48 && offsetof(FcBvhNode, index) == 96, "FcBvhNode offsets");
FC_STATIC_ASSERT(sizeof(FcTriangle) == 48, "FcTriangle is 48 bytes");
FC_STATIC_ASSERT(offsetof(FcTriangle, v1) == 16 && offsetof(FcTriangle, v2) == 32, "FcTriangle offsets");

#endif
