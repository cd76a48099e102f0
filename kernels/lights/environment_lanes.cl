/* Lane-generic body (kernels/lanes/lanes.cl): the environment map's directions, world to the
 * map's frame to (u, v) and back (kernels/lights/environment.cl has the conventions). The
 * scalar lookups and samples run these at W = 1; the packet paths at their width, for every
 * escaped ray and every environment sample of a packet at once (issue 29). The rotation
 * to_map comes as its three rows r0, r1, r2, the same for every lane. */
#ifndef FACET_LIGHTS_ENVIRONMENT_LANES_PASS
#define FACET_LIGHTS_ENVIRONMENT_LANES_PASS

/* World direction d to the map's frame (to_map d). */
inline LVEC3 LNAME(env_dir_to_map)(float3 r0, float3 r1, float3 r2, LVEC3 d) {
    return LNAME(vec3)(r0.x * d.x + r0.y * d.y + r0.z * d.z, r1.x * d.x + r1.y * d.y + r1.z * d.z,
                       r2.x * d.x + r2.y * d.y + r2.z * d.z);
}

/* The map's frame back to world (the transpose: to_map is a rotation). */
inline LVEC3 LNAME(env_map_to_dir)(float3 r0, float3 r1, float3 r2, LVEC3 m) {
    return LNAME(vec3)(m.x * r0.x + m.y * r1.x + m.z * r2.x, m.x * r0.y + m.y * r1.y + m.z * r2.y,
                       m.x * r0.z + m.y * r1.z + m.z * r2.z);
}

/* Map-frame direction to (u, v) in [0, 1]^2, and sin(theta) in *sin_theta:
 * d = (sin theta sin phi, cos theta, -sin theta cos phi), u = phi / 2pi, v = theta / pi.
 * Both angles by atan2_fast, theta from the horizontal length (accurate near the poles,
 * where acos is not). */
inline LVEC2 LNAME(env_map_dir_to_uv)(LVEC3 m, LFLOAT* sin_theta) {
    const LFLOAT st = sqrt(m.x * m.x + m.z * m.z);
    LFLOAT phi = LNAME(atan2_fast)(m.x, -m.z);
    phi = select(phi, phi + 2.0f * FC_PI, phi < 0.0f);
    const LFLOAT theta = LNAME(atan2_fast)(st, m.y);
    *sin_theta = st;
    return LNAME(vec2)(phi * FC_INV_2PI, theta * FC_INV_PI);
}

/* (u, v) to the map-frame direction: phi = 2 pi u and theta = pi v in turns. */
inline LVEC3 LNAME(env_uv_to_map_dir)(LVEC2 uv) {
    const LVEC2 sc_phi = LNAME(sincos_turns)(uv.x);
    const LVEC2 sc_theta = LNAME(sincos_turns)(0.5f * uv.y);
    return LNAME(vec3)(sc_theta.x * sc_phi.x, sc_theta.y, -sc_theta.x * sc_phi.y);
}

/* (u, v) to the unit world direction, +y where the rotated direction has no length (it
 * always has, but for a broken rotation). */
inline LVEC3 LNAME(env_uv_to_dir)(float3 r0, float3 r1, float3 r2, LVEC2 uv) {
    const LVEC3 v = LNAME(env_map_to_dir)(r0, r1, r2, LNAME(env_uv_to_map_dir)(uv));
    const LFLOAT len2 = v.x * v.x + v.y * v.y + v.z * v.z;
    const LINT ok = (len2 > 0.0f) & isfinite(len2);
    const LFLOAT inv = 1.0f / sqrt(len2);
    return LNAME(vec3)(select((LFLOAT)(0.0f), v.x * inv, ok), select((LFLOAT)(1.0f), v.y * inv, ok),
                       select((LFLOAT)(0.0f), v.z * inv, ok));
}

#undef FACET_LIGHTS_ENVIRONMENT_LANES_PASS
#endif
