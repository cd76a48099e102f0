/* Lane-generic body (kernels/lanes/lanes.cl): the GGX distribution's D, Smith's Lambda, the
 * projected area, the visible normals' density and Heitz's visible-normal sampler, whose
 * formulas, sources and numerical policy kernels/bsdf/ggx.cl gives (its scalar functions are
 * these at W = 1). Roughness ax, ay per lane; local frame, n = +z. Needs vec3_lanes.cl and
 * trig_lanes.cl of the same width. */
#ifndef FACET_BSDF_GGX_LANES_PASS
#define FACET_BSDF_GGX_LANES_PASS

/* D(m) = 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) for m.z > 0, else 0. */
inline LFLOAT LNAME(ggx_D)(LFLOAT ax, LFLOAT ay, LVEC3 m) {
    const LFLOAT sx = m.x / ax;
    const LFLOAT sy = m.y / ay;
    const LFLOAT t = sx * sx + sy * sy + m.z * m.z;
    return select((LFLOAT)(0.0f), (1.0f / (FC_PI * ax * ay)) / (t * t), m.z > 0.0f);
}

/* Lambda(w) = s2 / (2 |z| (|z| + sqrt(z^2 + s2))), s2 = ax^2 x^2 + ay^2 y^2: 0 where s2 = 0,
 * else infinite at z = 0. */
inline LFLOAT LNAME(ggx_lambda)(LFLOAT ax, LFLOAT ay, LVEC3 w) {
    const LFLOAT tx = ax * w.x, ty = ay * w.y;
    const LFLOAT s2 = tx * tx + ty * ty;
    const LFLOAT z = fabs(w.z);
    LFLOAT l = s2 / (2.0f * z * (z + sqrt(z * z + s2)));
    l = select(l, (LFLOAT)(INFINITY), z == 0.0f);
    return select(l, (LFLOAT)(0.0f), s2 == 0.0f);
}

/* w.z (1 + Lambda(w)) = (w.z + sqrt(w.z^2 + s2)) / 2 for w.z > 0. */
inline LFLOAT LNAME(ggx_projected_area)(LFLOAT ax, LFLOAT ay, LVEC3 w) {
    const LFLOAT tx = ax * w.x, ty = ay * w.y;
    const LFLOAT s2 = tx * tx + ty * ty;
    return 0.5f * (w.z + sqrt(w.z * w.z + s2));
}

/* D_wo(m) = max(0, wo.m) D(m) / (wo.z (1 + Lambda(wo))); 0 where wo.z or wo.m is not > 0. */
inline LFLOAT LNAME(ggx_pdf_visible)(LFLOAT ax, LFLOAT ay, LVEC3 wo, LVEC3 m) {
    const LFLOAT wm = LNAME(vec3_dot)(wo, m);
    const LFLOAT p = LNAME(ggx_D)(ax, ay, m) * wm / LNAME(ggx_projected_area)(ax, ay, wo);
    return select((LFLOAT)(0.0f), p, (wo.z > 0.0f) & (wm > 0.0f));
}

/* A visible normal seen from wo (Heitz 2018, listing 1), from (ux, uy) uniform in [0, 1)^2. */
inline LVEC3 LNAME(ggx_sample_visible)(LFLOAT ax, LFLOAT ay, LVEC3 wo, LFLOAT ux, LFLOAT uy) {
    /* section 3.2: the view direction in the hemisphere configuration */
    LFLOAT vx = ax * wo.x, vy = ay * wo.y, vz = wo.z;
    const LFLOAT iv = rsqrt(vx * vx + vy * vy + vz * vz);
    vx *= iv;
    vy *= iv;
    vz *= iv;
    /* section 4.1: an orthonormal basis (t1 = x at normal incidence) */
    const LFLOAT lensq = vx * vx + vy * vy;
    const LFLOAT il = rsqrt(lensq);
    const LINT tilted = lensq > 0.0f;
    const LFLOAT t1x = select((LFLOAT)(1.0f), -vy * il, tilted), t1y = select((LFLOAT)(0.0f), vx * il, tilted);
    const LFLOAT t2x = vy * 0.0f - vz * t1y, t2y = vz * t1x - vx * 0.0f, t2z = vx * t1y - vy * t1x; /* vh x t1 */
    /* section 4.2: a point on the projected area, a disk warped toward vh */
    const LFLOAT r = sqrt(ux);
    const LVEC2 sc = LNAME(sincos_turns)(uy); /* phi = 2 pi uy */
    const LFLOAT p1 = r * sc.y;
    const LFLOAT s = 0.5f * (1.0f + vz);
    const LFLOAT p2 = (1.0f - s) * sqrt(fmax(1.0f - p1 * p1, 0.0f)) + s * (r * sc.x);
    /* sections 4.3 and 3.4: onto the hemisphere, then back to the ellipsoid configuration */
    const LFLOAT n3 = sqrt(fmax(1.0f - p1 * p1 - p2 * p2, 0.0f));
    const LFLOAT nx = p1 * t1x + p2 * t2x + n3 * vx, ny = p1 * t1y + p2 * t2y + n3 * vy, nz = p2 * t2z + n3 * vz;
    const LFLOAT mx = ax * nx, my = ay * ny, mz = fmax(nz, 0.0f);
    const LFLOAT len2 = mx * mx + my * my + mz * mz;
    const LFLOAT il2 = rsqrt(len2);
    const LINT ok = (len2 > 0.0f) & isfinite(len2);
    return LNAME(vec3)(select((LFLOAT)(0.0f), mx * il2, ok), select((LFLOAT)(0.0f), my * il2, ok),
                       select((LFLOAT)(1.0f), mz * il2, ok));
}

#undef FACET_BSDF_GGX_LANES_PASS
#endif
