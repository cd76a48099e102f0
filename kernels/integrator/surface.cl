/* The surface at a ray hit: position from the triangle's barycentrics (more precise
 * than o + t d), geometric and shading normals, and the material. */
#ifndef FACET_INTEGRATOR_SURFACE_CL
#define FACET_INTEGRATOR_SURFACE_CL

#include "kernels/shared/all.h"
#include "kernels/trace/bvh_traverse.cl"
#include "kernels/util/frame.cl"

typedef struct {
    float3 p;  /* hit point */
    float3 ng; /* geometric normal, on the side the shading normals face */
    float3 ns; /* interpolated shading normal */
    int prim;  /* scene triangle index */
    int material;
    int light; /* light index, or -1 */
} Surface;

inline Surface surface_at(__global const FcTriangle* tris, __global const FcTriShading* shading, const Hit* hit) {
    __global const FcTriangle* tri = &tris[hit->tri];
    float3 v0 = load3(tri->v0);
    float3 e1 = load3(tri->v1) - v0;
    float3 e2 = load3(tri->v2) - v0;
    __global const FcTriShading* sh = &shading[hit->prim];
    Surface s;
    s.p = v0 + hit->u * e1 + hit->v * e2;
    s.ng = normalize_scaled_or(cross(e1, e2), (float3)(0.0f, 0.0f, 1.0f));
    float w = 1.0f - hit->u - hit->v;
    s.ns = normalize_or(w * load3(sh->n0) + hit->u * load3(sh->n1) + hit->v * load3(sh->n2), s.ng);
    if (dot(s.ng, s.ns) < 0.0f) s.ng = -s.ng;
    s.prim = hit->prim;
    s.material = sh->material;
    s.light = sh->light;
    return s;
}

#endif
