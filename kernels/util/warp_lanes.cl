/* Lane-generic body (kernels/lanes/lanes.cl): warps of the unit square
 * (kernels/util/warp.cl, kernels/bsdf/lambert.cl, kernels/lights/area.cl). Needs
 * trig_lanes.cl of the same width. */
#ifndef FACET_UTIL_WARP_LANES_PASS
#define FACET_UTIL_WARP_LANES_PASS

/* Concentric map of the unit square onto the unit disk (Shirley & Chiu 1997). */
inline LVEC2 LNAME(square_to_disk_concentric)(LFLOAT ux, LFLOAT uy) {
    LFLOAT px = 2.0f * ux - 1.0f;
    LFLOAT py = 2.0f * uy - 1.0f;
    /* r and phi in turns: phi = (pi / 4) (y / x) or pi / 2 - (pi / 4) (x / y) */
    LINT x_major = fabs(px) > fabs(py);
    LFLOAT r = select(py, px, x_major);
    LFLOAT q = select(px, py, x_major) / r;
    LFLOAT turns = select(0.25f - 0.125f * q, 0.125f * q, x_major);
    LVEC2 sc = LNAME(sincos_turns)(turns);
    LINT centre = r == 0.0f; /* p = 0 (with p != 0 the larger |p| is not 0): q is 0 / 0 */
    return LNAME(vec2)(select(r * sc.y, (LFLOAT)(0.0f), centre), select(r * sc.x, (LFLOAT)(0.0f), centre));
}

/* A cosine-distributed direction on the upper hemisphere (Malley's method); z may be 0 on
 * the rim. */
inline LVEC3 LNAME(square_to_cosine_hemisphere)(LFLOAT ux, LFLOAT uy) {
    LVEC2 d = LNAME(square_to_disk_concentric)(ux, uy);
    return LNAME(vec3)(d.x, d.y, sqrt(fmax(1.0f - d.x * d.x - d.y * d.y, 0.0f)));
}

/* Its density per solid angle, for wo and wi in the local frame (n = +z). */
inline LFLOAT LNAME(cosine_hemisphere_pdf)(LFLOAT wo_z, LFLOAT wi_z) {
    return select((LFLOAT)(0.0f), wi_z * FC_INV_PI, (wo_z > 0.0f) & (wi_z > 0.0f));
}

/* A uniform point on a triangle (the square-root parameterisation, Turk 1990): the
 * barycentrics of v1 and v2. */
inline LVEC2 LNAME(square_to_triangle)(LFLOAT u0, LFLOAT u1) {
    LFLOAT su = sqrt(u0);
    return LNAME(vec2)(su * (1.0f - u1), su * u1);
}

#undef FACET_UTIL_WARP_LANES_PASS
#endif
