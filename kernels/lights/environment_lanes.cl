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

/* A comparison's lanes as every bit set where true: a scalar comparison gives 1, a vector
 * one -1. */
#if FC_LW == 1
#define FC_ENV_ALL_BITS(m) (-(m))
#else
#define FC_ENV_ALL_BITS(m) (m)
#endif

/* For each lane, the interval i of the cdf at base[off .. off + n] (non-decreasing, from 0 to 1)
 * with cdf[i] <= u < cdf[i + 1], from its guide table at base[goff .. goff + g] (entry k the
 * interval holding k / g, as uint bits; Chen & Asau 1974): the answer lies between entries k =
 * floor(u g) and k + 1, and bisection finds it there, the lanes in step, each reading its
 * entries by a gather (a lane whose interval is found adds 0). Any bisection that keeps cdf[lo]
 * <= u finds the same i, the largest with cdf[i] <= u. */
inline LINT LNAME(env_find_interval)(__global const float* base, LUINT off, LUINT goff, uint g, LFLOAT u) {
    const LUINT k = min(LCONVERT_UINT(u * (float)g), (LUINT)(g - 1u));
    LINT lo = LAS_INT(LNAME(gather)(base, goff + k));
    LINT n = LAS_INT(LNAME(gather)(base, goff + k + 1u)) + 1 - lo; /* i in [lo, lo + n) */
    while (LNAME(lanes_any)(n > 1)) {
        const LINT step = n / 2;
        lo += step & FC_ENV_ALL_BITS(LNAME(gather)(base, off + LCONVERT_UINT(lo + step)) <= u);
        n -= step;
    }
    return lo;
}

/* u's position inside interval i of the cdf at base[off ..], in [0, 1). */
inline LFLOAT LNAME(env_remap)(__global const float* base, LUINT off, LINT i, LFLOAT u) {
    const LFLOAT c0 = LNAME(gather)(base, off + LCONVERT_UINT(i)), c1 = LNAME(gather)(base, off + LCONVERT_UINT(i + 1));
    const LFLOAT w = c1 - c0;
    return clamp(select((LFLOAT)(0.5f), (u - c0) / w, w > 0.0f), 0.0f, FC_ONE_MINUS_EPSILON);
}

/* The texel (x, y) of a w x h map that env_sample takes at (ux, uy) of the square, and the point
 * (du, dv) in [0, 1)^2 across it: the row from the marginal cdf, the column from the row's
 * conditional, both through their guide tables (dist's layout: host/scene/environment_map.cpp). */
inline void LNAME(env_sample_texel)(int w, int h, __global const float* dist, LFLOAT ux, LFLOAT uy, LINT* x, LINT* y,
                                    LFLOAT* du, LFLOAT* dv) {
    ux = clamp(ux, 0.0f, FC_ONE_MINUS_EPSILON);
    uy = clamp(uy, 0.0f, FC_ONE_MINUS_EPSILON);
    const uint gm = env_guide_size((uint)h), gc = env_guide_size((uint)w);
    const uint guides = (uint)(h + 1) + (uint)h * (uint)(w + 1);
    *y = LNAME(env_find_interval)(dist, (LUINT)(0u), (LUINT)(guides), gm, uy);
    *dv = LNAME(env_remap)(dist, (LUINT)(0u), *y, uy);
    const LUINT row = LCONVERT_UINT(*y);
    const LUINT cond = (uint)(h + 1) + row * (uint)(w + 1);
    *x = LNAME(env_find_interval)(dist, cond, guides + (gm + 1u) + row * (gc + 1u), gc, ux);
    *du = LNAME(env_remap)(dist, cond, *x, ux);
}

#undef FC_ENV_ALL_BITS
#undef FACET_LIGHTS_ENVIRONMENT_LANES_PASS
#endif
