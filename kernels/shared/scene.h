/* Shading-side scene layouts: per-triangle shading data, materials and lights.
 * Indexed by FcTriangle.prim (the scene's own triangle order, not BVH order). */
#ifndef FACET_SHARED_SCENE_H
#define FACET_SHARED_SCENE_H

#include "types.h"
#include "material.h"

/* Per-triangle shading data: vertex normals (equal to the face normal for flat
 * meshes), the material, and the triangle's index in the light array (-1 if the
 * triangle does not emit). */
typedef struct FcTriShading {
    float n0[3];
    fc_int material;
    float n1[3];
    fc_int light;
    float n2[3];
    fc_int pad0;
} FcTriShading;

/* Light types (FcLight.type). */
#define FC_LIGHT_AREA_TRIANGLE 0

/* A light. An area light is one emitting triangle: `p0` a vertex, `e1`, `e2` its
 * edges, ordered so that cross(e1, e2) points to the emitting side (the side its
 * shading normals face); `prim` is the triangle's scene index and `area` its area.
 * `pick_pdf` is the probability that light selection picks this light, in
 * proportion to emitted power (host/scene/scene.cpp, build_lights). */
typedef struct FcLight {
    float p0[3];
    fc_int type;
    float e1[3];
    fc_int prim;
    float e2[3];
    float area;
    float pick_pdf;
    float pad0[3];
} FcLight;

FC_STATIC_ASSERT(sizeof(FcTriShading) == 48, "FcTriShading is 48 bytes");
FC_STATIC_ASSERT(sizeof(FcLight) == 64, "FcLight is 64 bytes");

#endif
