/* Warps of the unit square onto other domains, shared by the camera's lens and the
 * BSDFs' cosine sampling. */
#ifndef FACET_UTIL_WARP_CL
#define FACET_UTIL_WARP_CL

#include "kernels/util/math.cl"

/* Concentric map of the unit square onto the unit disk (Shirley & Chiu 1997). */
inline float2 square_to_disk_concentric(float2 u) {
    float2 p = 2.0f * u - (float2)(1.0f);
    if (p.x == 0.0f && p.y == 0.0f) return (float2)(0.0f);
    float r, phi;
    if (fabs(p.x) > fabs(p.y)) {
        r = p.x;
        phi = (FC_PI / 4.0f) * (p.y / p.x);
    } else {
        r = p.y;
        phi = (FC_PI / 2.0f) - (FC_PI / 4.0f) * (p.x / p.y);
    }
    return r * (float2)(cos(phi), sin(phi));
}

#endif
