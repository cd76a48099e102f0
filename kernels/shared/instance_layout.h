/* Instancing (kernels/trace/instance.cl), uploaded by the host (host/bvh/instance_bvh.hpp):
 * a mesh used by several glTF nodes is stored once, in object space, with its own bottom-level
 * tree (BLAS: an ordinary FcBvhNode tree of bvh_layout.h, appended to the scene's node buffer
 * with its leaf blocks, and its triangles appended to the FcTriangle array); each use is an
 * FcInstance, and a binary top-level tree over the instances' world boxes finds the instances a
 * ray meets. Programs built without FC_HAS_INSTANCES never look at them.
 *
 * Matrices are 3x4 affine transforms, row-major: row r gives coordinate r of the image,
 * x'_r = m[r][0] x + m[r][1] y + m[r][2] z + m[r][3]. The BLAS `root` counts 128-byte units
 * (FcBvhNode) from the start of the node buffer: the BLAS's own node and row indices count
 * from there, so its buffer is laid out exactly as a tree built alone. `tri_offset` is the
 * index of its first FcTriangle; their FcTriangle.prim index the shading arrays (FcTriShading,
 * FcTriTexcoords), which hold each shared mesh's triangles once, after the world triangles'.
 *
 * The top-level tree is a small tree (float wide nodes of bvh_layout.h as wide as the world
 * tree, traversed by kernels/trace/small_tree_traverse.cl), its leaves indexing the FcInstance
 * array. */
#ifndef FACET_SHARED_INSTANCE_LAYOUT_H
#define FACET_SHARED_INSTANCE_LAYOUT_H

#include "kernels/shared/bvh_layout.h"
#include "kernels/shared/types.h"

typedef struct FcInstance {
    float world_to_object[3][4];
    float object_to_world[3][4];
    float lo[3]; /* world bounds of the instance */
    fc_int root; /* its mesh's BLAS, in FcBvhNode units into the node buffer */
    float hi[3];
    fc_int tri_offset; /* its mesh's first FcTriangle */
} FcInstance;

FC_STATIC_ASSERT(sizeof(FcInstance) == 128, "FcInstance is 128 bytes");
FC_STATIC_ASSERT(offsetof(FcInstance, object_to_world) == 48 && offsetof(FcInstance, lo) == 96 &&
                     offsetof(FcInstance, root) == 108 && offsetof(FcInstance, tri_offset) == 124,
                 "FcInstance offsets");

#endif
