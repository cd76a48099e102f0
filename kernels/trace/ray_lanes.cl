/* Lane-generic body (kernels/lanes/lanes.cl): the offset of a new ray's origin off the
 * surface it leaves (kernels/trace/ray.cl). */
#ifndef FACET_TRACE_RAY_LANES_PASS
#define FACET_TRACE_RAY_LANES_PASS

/* Wächter & Binder 2019, "A Fast and Robust Method for Avoiding Self-Intersection" (Ray
 * Tracing Gems ch. 6): a number of ULPs along the geometric normal, or near the origin,
 * where ULPs are tiny, a small fixed float offset. */
#ifndef FC_OFFSET_ORIGIN
#define FC_OFFSET_ORIGIN (1.0f / 32.0f)
#define FC_OFFSET_FLOAT_SCALE (1.0f / 65536.0f)
#define FC_OFFSET_INT_SCALE 256.0f
#endif

/* One coordinate p moved along normal component n. */
inline LFLOAT LNAME(offset_ulps)(LFLOAT p, LFLOAT n) {
    LINT of_i = LCONVERT_INT(FC_OFFSET_INT_SCALE * n);
    LFLOAT p_i = LAS_FLOAT(LAS_INT(p) + select(of_i, -of_i, p < 0.0f));
    return select(p_i, p + FC_OFFSET_FLOAT_SCALE * n, fabs(p) < FC_OFFSET_ORIGIN);
}

/* Point p moved off its surface along ng, which points to the side the ray leaves from. */
inline LVEC3 LNAME(offset_ray_origin)(LVEC3 p, LVEC3 ng) {
    return LNAME(vec3)(LNAME(offset_ulps)(p.x, ng.x), LNAME(offset_ulps)(p.y, ng.y), LNAME(offset_ulps)(p.z, ng.z));
}

#undef FACET_TRACE_RAY_LANES_PASS
#endif
