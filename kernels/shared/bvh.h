/* BVH and triangle layouts uploaded by the host (host/bvh/) and traversed by
 * kernels/trace/bvh.cl.
 *
 * The tree is binary. Each node stores the bounds of its two children so that the
 * traversal tests both boxes with one node fetch and visits the nearer first
 * (Aila & Laine 2009, "Understanding the efficiency of ray traversal on GPUs").
 * A child reference is either an inner node (count == 0, index = node index) or a
 * leaf (count > 0, index = first triangle in the reordered triangle array). */
#ifndef FACET_SHARED_BVH_H
#define FACET_SHARED_BVH_H

#include "types.h"

typedef struct FcBvhNode {
    float a_min[3];
    fc_int a_index;
    float a_max[3];
    fc_int a_count;
    float b_min[3];
    fc_int b_index;
    float b_max[3];
    fc_int b_count;
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

/* Maximum depth of the traversal stack; the builder guarantees the tree is no deeper. */
#define FC_BVH_STACK_SIZE 64

FC_STATIC_ASSERT(sizeof(FcBvhNode) == 64, "FcBvhNode is 64 bytes");
FC_STATIC_ASSERT(sizeof(FcTriangle) == 48, "FcTriangle is 48 bytes");

#endif
