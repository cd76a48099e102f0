/* Analytic spheres (kernels/trace/sphere.cl), uploaded by the host (host/bvh/sphere_bvh.hpp):
 * the spheres in tree order and a small tree over their boxes (float wide nodes of bvh_layout.h
 * as wide as the triangles' tree, its leaves indexing the FcSphere array), apart from the triangles'
 * tree so that a scene without spheres pays nothing (kernels built without FC_HAS_SPHERES
 * never look at them). A scene without spheres has a root whose slots are all empty. */
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

FC_STATIC_ASSERT(sizeof(FcSphere) == 32, "FcSphere is 32 bytes");
FC_STATIC_ASSERT(offsetof(FcSphere, material) == 16 && offsetof(FcSphere, prim) == 28, "FcSphere offsets");

#endif
