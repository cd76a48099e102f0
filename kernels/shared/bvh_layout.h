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

/* The 8-wide node (Embree's BVH8 idea, for devices with 256-bit vectors: the traversal
 * tests all eight boxes with float8 arithmetic): the same fields as FcBvhNode, eight
 * lanes each. The host collapses the binary tree by opening, while a slot is free, the
 * inner child of largest surface area (host/bvh/bvh.cpp); child references, leaves and
 * empty slots are as in FcBvhNode. An 8-wide tree's node buffer holds FcBvhNode8, then
 * the leaf blocks (still FcTriBlock, rows counted from the start of the buffer); node
 * indices count FcBvhNode8. Which layout a program reads is FC_BVH_WIDTH (4 when not
 * defined), set by the host from the Bvh it uploads. */
typedef struct FcBvhNode8 {
    float lo_x[8];
    float lo_y[8];
    float lo_z[8];
    float hi_x[8];
    float hi_y[8];
    float hi_z[8];
    fc_int index[8];
    fc_int count[8];
} FcBvhNode8;

/* The quantised 8-wide node (Ylitie, Karras & Laine 2017, "Efficient Incoherent Ray
 * Traversal on GPUs Through Compressed Wide BVHs"): 80 bytes against FcBvhNode8's 256, the
 * same tree. Each child box plane is a byte q on a grid of the node, plane = origin[a] +
 * q * 2^(e_a - 127) per axis a (q * scale is exact; the sum is rounded once, the same on
 * host and device), rounded outward by the host (host/bvh/quantise.cpp): every decoded box
 * contains its child's exact box, so the traversal may visit more but misses nothing and
 * returns the float layout's hits. Children are referred to by rank, not index: a node's
 * inner children are consecutive nodes from child_base, its leaves' blocks consecutive
 * rows from leaf_base, both in slot order. Per slot c:
 *  - inner child: bit c of exps' byte 3; node child_base + (inner slots before c);
 *  - leaf: byte c of meta (byte c % 4 of meta[c / 4]) = blocks | first << 3: its blocks
 *    (1-7) of FcTriBlock start at row leaf_base + 10 * first (first 0-31);
 *  - empty slot: not inner, meta byte 0, planes inverted (lo 255, hi 0); should rounding
 *    report it hit anyway, it is a leaf of no blocks.
 * Planes: byte c of q_lo_x (memory order) is slot c's low x plane, and so on; the six
 * planes in FcBvhNode8's row order (lo x, y, z, hi x, y, z), 8 bytes each from byte 32.
 * The node buffer of a quantised tree holds FcBvhNodeQ (node indices count them), then
 * the leaf blocks; FC_BVH_QUANTISED (with FC_BVH_WIDTH 8) selects it in a program. */
typedef struct FcBvhNodeQ {
    float origin[3];
    fc_uint exps; /* bytes 0-2: biased exponents of the x, y, z scales (1-254); byte 3: inner-child bits */
    fc_int child_base;
    fc_int leaf_base;
    fc_uint meta[2];
    fc_uint q_lo_x[2];
    fc_uint q_lo_y[2];
    fc_uint q_lo_z[2];
    fc_uint q_hi_x[2];
    fc_uint q_hi_y[2];
    fc_uint q_hi_z[2];
} FcBvhNodeQ;

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

/* Entries of the traversal stack. A 4-wide node pushes at most three children, and the
 * host keeps the 4-wide tree at most FC_BVH_STACK_SIZE / 3 nodes deep. An 8-wide node
 * pushes at most seven; the host checks that no root-to-leaf path of an 8-wide tree
 * pushes more than FC_BVH8_STACK_SIZE entries (the sum of its nodes' inner children
 * less one) and collapses level by level (3 binary levels a node) when one would. */
#define FC_BVH_STACK_SIZE 64
#define FC_BVH8_STACK_SIZE 100

FC_STATIC_ASSERT(sizeof(FcBvhNode) == 128, "FcBvhNode is 128 bytes");
FC_STATIC_ASSERT(offsetof(FcBvhNode, hi_x) == 48 && offsetof(FcBvhNode, index) == 96, "FcBvhNode offsets");
FC_STATIC_ASSERT(sizeof(FcBvhNode8) == 256, "FcBvhNode8 is 256 bytes");
FC_STATIC_ASSERT(offsetof(FcBvhNode8, hi_x) == 96 && offsetof(FcBvhNode8, index) == 192, "FcBvhNode8 offsets");
FC_STATIC_ASSERT(sizeof(FcBvhNodeQ) == 80, "FcBvhNodeQ is 80 bytes");
FC_STATIC_ASSERT(offsetof(FcBvhNodeQ, meta) == 24 && offsetof(FcBvhNodeQ, q_lo_x) == 32 &&
                     offsetof(FcBvhNodeQ, q_hi_z) == 72,
                 "FcBvhNodeQ offsets");
FC_STATIC_ASSERT(sizeof(FcTriBlock) == 160 && offsetof(FcTriBlock, tri) == 144, "FcTriBlock is 10 rows of 16 bytes");
FC_STATIC_ASSERT(sizeof(FcTriangle) == 48, "FcTriangle is 48 bytes");
FC_STATIC_ASSERT(offsetof(FcTriangle, v1) == 16 && offsetof(FcTriangle, v2) == 32, "FcTriangle offsets");

#endif
