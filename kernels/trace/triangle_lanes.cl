/* Lane-generic body (kernels/lanes/lanes.cl): the watertight ray/triangle test of
 * kernels/trace/triangle.cl (Woop, Benthin & Wald 2013), one ray against one triangle a lane.
 * tri4_hit runs it at W = 4, one ray against a leaf block's four triangles (the ray's values
 * the same in every lane); the packet traversal (kernels/trace/packet_trace.cl) at the packet's
 * width, a packet's rays against one triangle (the triangle's the same in every lane). Either
 * way a lane runs the paper's scalar operations, so its answer is the scalar test's, bit for
 * bit. */
#ifndef FACET_TRACE_TRIANGLE_LANES_PASS
#define FACET_TRACE_TRIANGLE_LANES_PASS

#ifndef FC_GAMMA2
/* gamma(n) = n eps / (1 - n eps), eps = 2^-24: bounds of n roundings (pbrt-v3 3.9.1). */
#define FC_GAMMA2 1.1920930376163766e-07f
#define FC_GAMMA3 1.788139663006007e-07f
#define FC_GAMMA5 2.9802331269482156e-07f
#endif

/* a*b - c*d with an error under 1.5 ulps, so its sign is exact (Kahan's algorithm with fma);
 * the paper falls back to double precision instead, which OpenCL C 1.2 devices need not have. */
inline LFLOAT LNAME(diff_of_products)(LFLOAT a, LFLOAT b, LFLOAT c, LFLOAT d) {
    LFLOAT cd = c * d;
    LFLOAT err = fma(-c, d, cd);
    return fma(a, b, -cd) + err;
}

/* The ray (origin along its axes kx, ky, kz: ox, oy, oz; shear sx, sy, sz: TriRay's) against
 * the triangle (a, b, c) along the same axes: lanes hit with t < tmax and t above its rounding
 * error, -1 in the mask; their distance in *t_out and their scaled barycentrics (the edge
 * functions v, w of vertices b and c, and their sum det). A triangle whose three vertices are
 * equal (a block's padding) is never hit. */
__attribute__((always_inline)) inline LINT LNAME(tri_hit)(LFLOAT ox, LFLOAT oy, LFLOAT oz, LFLOAT sx, LFLOAT sy,
                                                          LFLOAT sz, LFLOAT pax, LFLOAT pay, LFLOAT paz, LFLOAT pbx,
                                                          LFLOAT pby, LFLOAT pbz, LFLOAT pcx, LFLOAT pcy, LFLOAT pcz,
                                                          LFLOAT tmax, LFLOAT* t_out, LFLOAT* v_out, LFLOAT* w_out,
                                                          LFLOAT* det_out) {
    /* No fma contraction: the edge functions of a shared edge must be exact negatives
     * of each other in the two triangles (OpenCL C contracts by default). */
#pragma OPENCL FP_CONTRACT OFF
    /* Translate to the origin, then shear. */
    LFLOAT az = paz - oz, bz = pbz - oz, cz = pcz - oz;
    LFLOAT ax = (pax - ox) - sx * az, ay = (pay - oy) - sy * az;
    LFLOAT bx = (pbx - ox) - sx * bz, by = (pby - oy) - sy * bz;
    LFLOAT cx = (pcx - ox) - sx * cz, cy = (pcy - oy) - sy * cz;

    /* Scaled barycentrics: the edge functions. */
    LFLOAT u = cx * by - cy * bx;
    LFLOAT v = ax * cy - ay * cx;
    LFLOAT w = bx * ay - by * ax;
    const LINT on_edge = (u == 0.0f) | (v == 0.0f) | (w == 0.0f);
    if (LNAME(lanes_any)(on_edge)) { /* recompute those lanes exactly-signed */
        u = select(u, LNAME(diff_of_products)(cx, by, cy, bx), on_edge);
        v = select(v, LNAME(diff_of_products)(ax, cy, ay, cx), on_edge);
        w = select(w, LNAME(diff_of_products)(bx, ay, by, ax), on_edge);
    }
    /* Inside: the three edge functions of one sign (zero counts as either). The masks
     * are built without a vector NOT: Oclgrind 21.10 evaluates `xor <4 x i1> m, true`,
     * which LLVM makes of ~mask, to lanes of 1 or -2 instead of -1 and 0. */
    const LFLOAT det = u + v + w;
    const LINT inside = ((u >= 0.0f) & (v >= 0.0f) & (w >= 0.0f)) | ((u <= 0.0f) & (v <= 0.0f) & (w <= 0.0f));

    /* Scaled distance, divided by det (no lane traps on a zero det: it is a miss). */
    az *= sz;
    bz *= sz;
    cz *= sz;
    const LFLOAT tt = u * az + v * bz + w * cz;
    LFLOAT t = tt / det;
    /* Edge functions ~ size^2 times distances ~ size overflow past ~5e12 (the scene
     * format allows 1e18): then weight the distances by the barycentrics instead. */
    const LINT overflow = isinf(tt) | isnan(tt);
    if (LNAME(lanes_any)(overflow)) t = select(t, (u / det) * az + (v / det) * bz + (w / det) * cz, overflow);
    /* A hit nearer than the rounding error of t is no hit (pbrt-v3 section 3.9.6, its
     * deltaT, with the error of the edge functions and of the sheared coordinates): a ray
     * leaving a surface whose origin offset (ray.cl) is below the rounding of the other
     * triangles' coordinates cannot hit that surface again. The edge function terms are
     * divided by det before they meet the distances, so that the bound does not overflow
     * at the scene format's 1e18. Only tests with a hit pay for it (most have none). */
    LINT hit = inside & (det != 0.0f) & (t > 0.0f) & (t < tmax);
    if (LNAME(lanes_any)(hit)) {
        const LFLOAT max_x = fmax(fmax(fabs(ax), fabs(bx)), fabs(cx));
        const LFLOAT max_y = fmax(fmax(fabs(ay), fabs(by)), fabs(cy));
        const LFLOAT max_z = fmax(fmax(fabs(az), fabs(bz)), fabs(cz));
        const LFLOAT inv_det = fabs(1.0f / det);
        const LFLOAT delta_x = FC_GAMMA5 * (max_x + max_z), delta_y = FC_GAMMA5 * (max_y + max_z);
        const LFLOAT delta_e = 2.0f * (FC_GAMMA2 * max_x * max_y + delta_y * max_x + delta_x * max_y) * inv_det;
        const LFLOAT max_e = fmax(fmax(fabs(u), fabs(v)), fabs(w)) * inv_det;
        const LFLOAT delta_t = 3.0f * (FC_GAMMA3 * max_e * max_z + delta_e * max_z + FC_GAMMA3 * max_z * max_e);
        hit &= t > delta_t;
    }
    *t_out = t;
    *v_out = v;
    *w_out = w;
    *det_out = det;
    return hit;
}

#undef FACET_TRACE_TRIANGLE_LANES_PASS
#endif
