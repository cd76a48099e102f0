/* Shading-side scene layouts: per-triangle shading data, materials and lights.
 * Indexed by FcTriangle.prim (the scene's own triangle order, not BVH order). */
#ifndef FACET_SHARED_SCENE_H
#define FACET_SHARED_SCENE_H

#include "kernels/shared/types.h"
#include "kernels/shared/material_layout.h"

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
#define FC_LIGHT_POINT 1
#define FC_LIGHT_SPOT 2
#define FC_LIGHT_DIRECTIONAL 3
#define FC_LIGHT_ENVIRONMENT 4
#define FC_LIGHT_SPHERE 5

/* A light (docs/lights.md gives the units).
 * - Area light: one emitting triangle: `p0` a vertex, `e1`, `e2` its edges, ordered so
 *   that cross(e1, e2) points to the emitting side (the side its shading normals
 *   face); `prim` is the triangle's scene index, `area` its area; `color` its material's
 *   emission and `flags` that material's FC_MAT_TWO_SIDED_EMISSION bit, `n` the unit
 *   normal of cross(e1, e2): copied here so that a light sample reads one record
 *   (kernels/lights/light.cl).
 * - Point and spot lights: position `p0`; spot axis `e1` (unit), cone cosines
 *   cos_inner >= cos_outer with a smoothstep falloff between. `color` is Hoffman's
 *   c_light at distance 1: the radiance of a white Lambertian surface facing the light
 *   there, so the irradiance is pi * color / d^2.
 * - Directional light: `e1` is the unit direction the light travels; `color` is
 *   c_light (irradiance pi * color at normal incidence).
 * - Sphere light: an emitting analytic sphere (kernels/lights/sphere_light.cl): centre `p0`,
 *   radius e1[0], e1[1] = +1 (emits outward) or -1 (FC_SPHERE_INWARD), e1[2] = 1 when
 *   two-sided; `color` its radiance, `area` 4 pi r^2, `prim` its scene sphere index.
 * - Environment: the one FcEnvironment of the scene (kernels/shared/environment_layout.h).
 * `pick_pdf` is the probability that light selection picks this light, in proportion to
 * an estimate of its power (host/scene/lights.cpp). */
typedef struct FcLight {
    float p0[3];
    fc_int type;
    float e1[3];
    fc_int prim;
    float e2[3];
    float area;
    float color[3];
    float pick_pdf;
    float cos_inner;
    float cos_outer;
    fc_uint flags;
    float pad0;
    float n[3];
    float pad1;
} FcLight;

FC_STATIC_ASSERT(sizeof(FcTriShading) == 48, "FcTriShading is 48 bytes");
FC_STATIC_ASSERT(offsetof(FcTriShading, n1) == 16 && offsetof(FcTriShading, n2) == 32, "FcTriShading offsets");
FC_STATIC_ASSERT(sizeof(FcLight) == 96, "FcLight is 96 bytes");
FC_STATIC_ASSERT(offsetof(FcLight, e1) == 16 && offsetof(FcLight, pick_pdf) == 60, "FcLight offsets");

#endif
