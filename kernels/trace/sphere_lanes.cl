/* Lane-generic body (kernels/lanes/lanes.cl): the ray/sphere test of kernels/trace/sphere.cl,
 * one ray against one sphere a lane. The scalar kernels run it at W = 1 (sphere_roots and
 * sphere_hit are these); the packet traversal of the spheres' tree
 * (kernels/trace/packet_sphere.cl) at the packet's width, a packet's rays against one sphere
 * (the sphere the same in every lane). A lane runs the scalar operations in the same order,
 * so its roots are the scalar test's, bit for bit (tests/lanes_test.cpp). */
#ifndef FACET_TRACE_SPHERE_LANES_PASS
#define FACET_TRACE_SPHERE_LANES_PASS

/* The two roots t0 <= t1 of |o + t d - c| = r (d need not be unit), lanes whose line meets
 * the sphere set in the mask (Haines et al. 2019's quadratic: sphere.cl's header). */
inline LINT LNAME(sphere_roots)(LFLOAT cx, LFLOAT cy, LFLOAT cz, LFLOAT r, LFLOAT ox, LFLOAT oy, LFLOAT oz, LFLOAT dx,
                                LFLOAT dy, LFLOAT dz, LFLOAT* t0, LFLOAT* t1) {
    const LFLOAT fx = ox - cx, fy = oy - cy, fz = oz - cz;
    const LFLOAT a = dx * dx + dy * dy + dz * dz;
    /* 1 / a depends on the ray alone: a caller testing many spheres computes it once */
    const LFLOAT inv_a = 1.0f / a;
    const LFLOAT b = fx * dx + fy * dy + fz * dz; /* half the quadratic's b */
    /* The centre to the line's closest point, and the discriminant from it. */
    const LFLOAT s = b * inv_a;
    const LFLOAT lx = fx - s * dx, ly = fy - s * dy, lz = fz - s * dz;
    const LFLOAT ll = sqrt(lx * lx + ly * ly + lz * lz);
    const LFLOAT disc = (r - ll) * (r + ll);
    /* c = |f|^2 - r^2 as pbrt-v4 forms it, r^2 subtracted in one rounding: its sign is exact
     * once |f| - r is beyond rounding, which the spawn offset ensures (sphere.cl) */
    const LFLOAT cc = fma(-r, r, fx * fx + fy * fy + fz * fz);
    /* a lane that misses takes the square root of a negative: its roots are not used */
    const LFLOAT q = -(b + copysign(sqrt(a * disc), b));
    const LFLOAT n0 = cc / q, n1 = q * inv_a;
    *t0 = fmin(n0, n1);
    *t1 = fmax(n0, n1);
    return disc >= 0.0f;
}

/* Lanes with an intersection at 0 < t < tmax: the nearest such in *t. */
inline LINT LNAME(sphere_hit)(LFLOAT cx, LFLOAT cy, LFLOAT cz, LFLOAT r, LFLOAT ox, LFLOAT oy, LFLOAT oz, LFLOAT dx,
                              LFLOAT dy, LFLOAT dz, LFLOAT tmax, LFLOAT* t) {
    LFLOAT t0, t1;
    const LINT meets = LNAME(sphere_roots)(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, &t0, &t1);
    const LINT near = (t0 > 0.0f) & (t0 < tmax);
    const LINT far = (t1 > 0.0f) & (t1 < tmax);
    *t = select(t1, t0, near);
    return meets & (near | far);
}

#undef FACET_TRACE_SPHERE_LANES_PASS
#endif
