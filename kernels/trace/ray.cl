/* Ray helpers. Rays are passed as (origin o, direction d, tmax); hits count for
 * 0 < t < tmax. Directions need not be unit length. */
#ifndef FACET_TRACE_RAY_CL
#define FACET_TRACE_RAY_CL

/* Moves a surface point off its surface before a new ray leaves it, so the ray does
 * not hit the surface it starts on (Wächter & Binder 2019, "A Fast and Robust Method
 * for Avoiding Self-Intersection", Ray Tracing Gems ch. 6). The offset is a number of
 * ULPs along the geometric normal `ng`, which the caller has flipped to the side the
 * ray leaves from; near the origin, where ULPs are tiny, a small fixed float offset is
 * used instead. */
#define FC_OFFSET_ORIGIN (1.0f / 32.0f)
#define FC_OFFSET_FLOAT_SCALE (1.0f / 65536.0f)
#define FC_OFFSET_INT_SCALE 256.0f

inline float offset_ulps(float p, float n) {
    int of_i = (int)(FC_OFFSET_INT_SCALE * n);
    float p_i = as_float(as_int(p) + (p < 0.0f ? -of_i : of_i));
    return fabs(p) < FC_OFFSET_ORIGIN ? p + FC_OFFSET_FLOAT_SCALE * n : p_i;
}

inline float3 offset_ray_origin(float3 p, float3 ng) {
    return (float3)(offset_ulps(p.x, ng.x), offset_ulps(p.y, ng.y), offset_ulps(p.z, ng.z));
}

#endif
