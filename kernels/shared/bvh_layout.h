/* BVH and triangle layouts uploaded by the host (host/bvh/) and traversed by
 * kernels/trace/bvh_traverse.cl.
 *
 * The tree is 4-wide: the host builds a binary SAH tree and collapses every node with
 * its children's children into one node of up to four children (depth halves). A node
 * stores its children's boxes as structure-of-arrays, so the traversal tests all four
 * with float4 arithmetic in one work-item and visits them nearest first (Wald et al.
 * 2008, "Getting rid of packets"; Ernst & Greiner 2008, "Multi bounding volume
 * hierarchies"). A child reference is an inner node (count == 0, index = node index),
 * a leaf (count > 0 triangles, index = its first FcTriBlock, counted in 16-byte rows
 * from the start of the node buffer), or an empty slot (count == 0, index == 0,
 * inverted box lo = +inf, hi = -inf, which the slab test never reports as hit; index 0
 * is the root, never a child).
 *
 * The node buffer holds the nodes, then the leaves' triangles in blocks of four
 * (FcTriBlock), structure-of-arrays, tested four at once with float4 lanes (Embree's
 * triangle4 leaves); a leaf of n triangles has ceil(n / 4) consecutive blocks. */
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

/* Four triangles of a leaf, each coordinate a row of four lanes (one per triangle):
 * vertex 0 in x0 y0 z0, 1 in x1 y1 z1, 2 in x2 y2 z2, and the triangles' indices in
 * the FcTriangle array (BVH order). Unused lanes have all vertices at 0 (they never
 * hit) and index -1. */
typedef struct FcTriBlock {
    float x0[4];
    float y0[4];
    float z0[4];
    float x1[4];
    float y1[4];
    float z1[4];
    float x2[4];
    float y2[4];
    float z2[4];
    fc_int tri[4];
} FcTriBlock;

/* A triangle in BVH order, as the shading reads it (kernels/integrator/surface.cl):
 * three vertices and the index of the triangle in the scene's shading arrays
 * (FcTriShading). */
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
FC_STATIC_ASSERT(sizeof(FcTriBlock) == 160 && offsetof(FcTriBlock, tri) == 144, "FcTriBlock is 10 rows of 16 bytes");
FC_STATIC_ASSERT(sizeof(FcTriangle) == 48, "FcTriangle is 48 bytes");
FC_STATIC_ASSERT(offsetof(FcTriangle, v1) == 16 && offsetof(FcTriangle, v2) == 32, "FcTriangle offsets");

#endif
