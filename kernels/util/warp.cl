/* Warps of the unit square onto other domains, shared by the camera's lens and the
 * BSDFs' cosine sampling. */
#ifndef FACET_UTIL_WARP_CL
#define FACET_UTIL_WARP_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

/* Concentric map of the unit square onto the unit disk (Shirley & Chiu 1997;
 * kernels/util/warp_lanes.cl). */
inline float2 square_to_disk_concentric(float2 u) { return square_to_disk_concentric_l1(u.x, u.y); }

#endif
