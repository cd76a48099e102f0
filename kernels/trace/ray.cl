/* Ray helpers. Rays are passed as (origin o, direction d, tmax); hits count for
 * 0 < t < tmax. Directions need not be unit length. */
#ifndef FACET_TRACE_RAY_CL
#define FACET_TRACE_RAY_CL

#include "kernels/lanes/scalar.cl"

/* Moves a surface point off its surface before a new ray leaves it, so the ray does
 * not hit the surface it starts on (Wächter & Binder 2019, "A Fast and Robust Method
 * for Avoiding Self-Intersection", Ray Tracing Gems ch. 6). The offset is a number of
 * ULPs along the geometric normal `ng`, which the caller has flipped to the side the
 * ray leaves from; near the origin, where ULPs are tiny, a small fixed float offset is
 * used instead (kernels/trace/ray_lanes.cl). */
inline float3 offset_ray_origin(float3 p, float3 ng) { return offset_ray_origin_l1(p, ng); }

#endif
