/* Analytic spheres (kernels/trace/sphere.cl), uploaded by the host (host/scene/sphere_bvh.hpp):
 * the spheres in tree order and a binary BVH over their boxes, apart from the triangles'
 * tree so that a scene without spheres pays nothing (kernels built without FC_HAS_SPHERES
 * never look at them).
 *
 * A node stores both children's boxes (as host/bvh's binary SAH tree does): a child is an
 * inner node (count == 0, index = node index), a leaf (count > 0 spheres from index
 * `index` of the FcSphere array) or empty (count == 0, index == 0, inverted box lo = +inf,
 * hi = -inf, never hit; index 0 is the root, never a child). A scene without spheres has a
 * root with two empty children. */
#ifndef FACET_SHARED_SPHERE_LAYOUT_H
#define FACET_SHARED_SPHERE_LAYOUT_H

#include "kernels/shared/types.h"

/* FcSphere.flags: the surface faces into the sphere (normals and emission point inward,
 * e.g. a furnace enclosure). */
#define FC_SPHERE_INWARD 1

/* A sphere: centre, radius > 0, its material, its light (index in the FcLight array, or -1
 * when it does not emit), FC_SPHERE_* flags and its index in the scene's sphere list. */
typedef struct FcSphere {
    float center[3];
    float radius;
    fc_int material;
    fc_int light;
    fc_int flags;
    fc_int prim;
} FcSphere;

/* A binary node: children a and b, each a box and a reference. */
typedef struct FcSphereNode {
    float a_lo[3];
    fc_int a_index;
    float a_hi[3];
    fc_int a_count;
    float b_lo[3];
    fc_int b_index;
    float b_hi[3];
    fc_int b_count;
} FcSphereNode;

/* Entries of the sphere traversal's stack: one push per node, and the host keeps the tree
 * at most this deep. */
#define FC_SPHERE_STACK_SIZE 48

FC_STATIC_ASSERT(sizeof(FcSphere) == 32, "FcSphere is 32 bytes");
FC_STATIC_ASSERT(offsetof(FcSphere, material) == 16 && offsetof(FcSphere, prim) == 28, "FcSphere offsets");
FC_STATIC_ASSERT(sizeof(FcSphereNode) == 64, "FcSphereNode is 64 bytes");
FC_STATIC_ASSERT(offsetof(FcSphereNode, b_lo) == 32 && offsetof(FcSphereNode, b_count) == 60, "FcSphereNode offsets");

#endif
