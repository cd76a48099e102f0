/* Orthonormal shading frames. The local frame has the normal along +z; `wo` (toward
 * the viewer) and `wi` (toward the light) both point away from the surface
 * (docs/conventions.md). */
#ifndef FACET_UTIL_FRAME_CL
#define FACET_UTIL_FRAME_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/util/math.cl"

typedef struct {
    float3 s;
    float3 t;
    float3 n;
} Frame;

/* A frame around unit vector n without branches on its orientation (Duff et al. 2017,
 * "Building an Orthonormal Basis, Revisited", JCGT 6(1)). */
inline Frame frame_from_normal(float3 n) {
    Frame f;
    frame_from_normal_l1(n, &f.s, &f.t); /* kernels/util/frame_lanes.cl */
    f.n = n;
    return f;
}

inline float3 frame_to_local(const Frame* f, float3 v) { return (float3)(dot(v, f->s), dot(v, f->t), dot(v, f->n)); }

inline float3 frame_to_world(const Frame* f, float3 v) { return v.x * f->s + v.y * f->t + v.z * f->n; }

#endif
