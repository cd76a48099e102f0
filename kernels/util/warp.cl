/* Warps of the unit square onto other domains, shared by the camera's lens and the
 * BSDFs' cosine sampling. */
#ifndef FACET_UTIL_WARP_CL
#define FACET_UTIL_WARP_CL

#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

/* Concentric map of the unit square onto the unit disk (Shirley & Chiu 1997). */
inline float2 square_to_disk_concentric(float2 u) {
    float2 p = 2.0f * u - (float2)(1.0f);
    if (p.x == 0.0f && p.y == 0.0f) return (float2)(0.0f);
    /* r and phi in turns: phi = (pi / 4) (y / x) or pi / 2 - (pi / 4) (x / y) */
    float r, turns;
    if (fabs(p.x) > fabs(p.y)) {
        r = p.x;
        turns = 0.125f * (p.y / p.x);
    } else {
        r = p.y;
        turns = 0.25f - 0.125f * (p.x / p.y);
    }
    float2 sc = sincos_turns(turns);
    return r * (float2)(sc.y, sc.x);
}

#endif
