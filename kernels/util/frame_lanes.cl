/* Lane-generic body (kernels/lanes/lanes.cl): the orthonormal frame of a unit normal
 * (kernels/util/frame.cl). */
#ifndef FACET_UTIL_FRAME_LANES_PASS
#define FACET_UTIL_FRAME_LANES_PASS

/* Tangents s and t with (s, t, n) right-handed orthonormal (Duff et al. 2017, "Building an
 * Orthonormal Basis, Revisited"). */
inline void LNAME(frame_from_normal)(LVEC3 n, LVEC3* s, LVEC3* t) {
    LFLOAT sign = copysign((LFLOAT)(1.0f), n.z);
    LFLOAT a = -1.0f / (sign + n.z);
    LFLOAT b = n.x * n.y * a;
    *s = LNAME(vec3)(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *t = LNAME(vec3)(b, sign + n.y * n.y * a, -n.y);
}

#undef FACET_UTIL_FRAME_LANES_PASS
#endif
