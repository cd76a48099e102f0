/* Lane-generic body (kernels/lanes/lanes.cl): the casters' cones (the bounding spheres of the
 * scene's glass) seen from FC_LW vertices at once, for the sampling toward glass of
 * kernels/integrator/caustic_guide.cl, which instantiates it at W = 1 (caustic_guide_of_receiver,
 * caustic_guide_density); kernels/integrator/packet_caustic_guide.cl instantiates it at the
 * packets' width. The loops run over the casters, the same for every lane, so a packet tests
 * each caster's cone in all its lanes at once. Needs vec3_lanes.cl of the same width and
 * kernels/lights/sphere_light.cl. */
#ifndef FACET_INTEGRATOR_CAUSTIC_CONES_LANES_PASS
#define FACET_INTEGRATOR_CAUSTIC_CONES_LANES_PASS

/* 1 - cos(theta_max) of caster c's cone from a point at squared distance dc2 from its centre,
 * outside it: sphere_cone_one_minus_cos's two forms. */
inline LFLOAT LNAME(caustic_cone_omc)(float4 c, LFLOAT dc2) {
    const LFLOAT sin2_max = c.w * c.w / dc2;
    return select(1.0f - sqrt(fmax(1.0f - sin2_max, 0.0f)), 0.5f * sin2_max, sin2_max < FC_SPHERE_SMALL_CONE_SIN2);
}

/* The casters that count at p (shading normal n): p outside the sphere (by more than a
 * thousandth of r^2, as sphere lights take it) and part of its cone above the plane of n (the
 * axis less than 90 degrees + theta_max from n, sin(theta_max) = r / dc), as bit i of
 * *counting; the lenses among them (smooth glass balls, a relative index above 1) in *lens_bits
 * where `env` (the environment can be sampled); returns the cones' total solid angle, each
 * 2 pi (1 - cos(theta_max)), summed in the casters' order. */
inline LFLOAT LNAME(caustic_cones)(__global const float4* casters, uint count, bool env, LVEC3 p, LVEC3 n,
                                   LUINT* counting, LUINT* lens_bits) {
    LFLOAT total = (LFLOAT)(0.0f);
    LUINT bits = (LUINT)(0u), lens = (LUINT)(0u);
    for (uint i = 0; i < count; ++i) {
        const float4 c = casters[2u * i];
        const LVEC3 pc = LNAME(vec3)(c.x - p.x, c.y - p.y, c.z - p.z);
        const LFLOAT dc2 = LNAME(vec3_dot)(pc, pc);
        const LINT counts = (dc2 > c.w * c.w * (1.0f + 1e-3f)) & (LNAME(vec3_dot)(pc, n) > -c.w);
        const LFLOAT w = 2.0f * FC_PI * LNAME(caustic_cone_omc)(c, dc2);
        const LINT held = counts & (w > 0.0f);
        total += select((LFLOAT)(0.0f), w, held);
        bits |= select((LUINT)(0u), (LUINT)(1u << i), held);
        if (env && casters[2u * i + 1u].x > 1.0f) lens |= select((LUINT)(0u), (LUINT)(1u << i), held);
    }
    *counting = bits;
    *lens_bits = lens;
    return total;
}

/* How many of the casters in `counting` (caustic_cones's bits) hold the unit wi inside their
 * cones seen from p, each by the sine of wi's angle from the axis, |wi x pc| <= r, on pc's side
 * (no 1 - cos cancellation for small cones); the lenses among those that hold it as bit i of
 * *inside. */
inline LUINT LNAME(caustic_cones_holding)(__global const float4* casters, uint count, LUINT counting, LVEC3 p, LVEC3 wi,
                                          LUINT* inside) {
    LUINT held = (LUINT)(0u), in = (LUINT)(0u);
    for (uint i = 0; i < count; ++i) {
        const LINT here = ((counting >> i) & 1u) != 0u;
        if (!LNAME(lanes_any)(here)) continue;
        const float4 c = casters[2u * i];
        const LVEC3 pc = LNAME(vec3)(c.x - p.x, c.y - p.y, c.z - p.z);
        const LVEC3 x = LNAME(vec3)(wi.y * pc.z - wi.z * pc.y, wi.z * pc.x - wi.x * pc.z, wi.x * pc.y - wi.y * pc.x);
        const LINT holds = here & (LNAME(vec3_dot)(wi, pc) > 0.0f) & (LNAME(vec3_dot)(x, x) <= c.w * c.w);
        held += select((LUINT)(0u), (LUINT)(1u), holds);
        if (casters[2u * i + 1u].x > 1.0f) in |= select((LUINT)(0u), (LUINT)(1u << i), holds);
    }
    *inside = in;
    return held;
}

#undef FACET_INTEGRATOR_CAUSTIC_CONES_LANES_PASS
#endif
