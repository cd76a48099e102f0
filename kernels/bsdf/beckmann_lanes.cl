/* Lane-generic body (kernels/lanes/lanes.cl): the Beckmann distribution's D, Smith's Lambda,
 * the projected area, the visible normals' density and the visible-normal sampler, with the
 * erf approximations they rest on; kernels/bsdf/beckmann.cl gives the formulas, their sources
 * and the numerical policy (its scalar functions are these at W = 1). Roughness ax, ay per
 * lane; local frame, n = +z. The sampler's Newton iterations run until every lane's has
 * stopped, a lane that has stopped keeping its value, so that each lane takes the steps it
 * takes alone. e^x is exp_lanes.cl's, the same bits at every width. Needs vec3_lanes.cl,
 * trig_lanes.cl and exp_lanes.cl of the same width. */
#ifndef FACET_BSDF_BECKMANN_LANES_PASS
#define FACET_BSDF_BECKMANN_LANES_PASS

#ifndef FC_INV_SQRT_PI
#define FC_INV_SQRT_PI 0.56418958354775628695f
#endif

/* erf^-1(x) for x in (-1, 1) (Giles 2010, single precision), the argument kept one float
 * away from +-1. Each branch runs where some lane takes it. */
inline LFLOAT LNAME(erfinv_giles)(LFLOAT x) {
    x = clamp(x, -FC_ONE_MINUS_EPSILON, FC_ONE_MINUS_EPSILON);
    const LFLOAT w0 = -log((1.0f - x) * (1.0f + x));
    const LINT central = w0 < 5.0f;
    LFLOAT p = (LFLOAT)(0.0f), q = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(central)) {
        const LFLOAT w = w0 - 2.5f;
        p = 2.81022636e-08f;
        p = 3.43273939e-07f + p * w;
        p = -3.5233877e-06f + p * w;
        p = -4.39150654e-06f + p * w;
        p = 0.00021858087f + p * w;
        p = -0.00125372503f + p * w;
        p = -0.00417768164f + p * w;
        p = 0.246640727f + p * w;
        p = 1.50140941f + p * w;
    }
    if (LNAME(lanes_any)((w0 >= 5.0f) | isnan(w0))) { /* not central (no vector NOT: lanes.cl) */
        const LFLOAT w = sqrt(w0) - 3.0f;
        q = -0.000200214257f;
        q = 0.000100950558f + q * w;
        q = 0.00134934322f + q * w;
        q = -0.00367342844f + q * w;
        q = 0.00573950773f + q * w;
        q = -0.0076224613f + q * w;
        q = 0.00943887047f + q * w;
        q = 1.00167406f + q * w;
        q = 2.83297682f + q * w;
    }
    return select(q, p, central) * x;
}

/* erfc(x) by Chebyshev fitting (Press et al. 2007, section 6.2.2, "erfcc"). */
inline LFLOAT LNAME(erfc_fast)(LFLOAT x) {
    const LFLOAT z = fabs(x);
    const LFLOAT t = 1.0f / (1.0f + 0.5f * z);
    LFLOAT p = 0.17087277f;
    p = -0.82215223f + t * p;
    p = 1.48851587f + t * p;
    p = -1.13520398f + t * p;
    p = 0.27886807f + t * p;
    p = -0.18628806f + t * p;
    p = 0.09678418f + t * p;
    p = 0.37409196f + t * p;
    p = 1.00002368f + t * p;
    const LFLOAT r = t * LNAME(exp_poly)(-z * z - 1.26551223f + t * p);
    return select(2.0f - r, r, x >= 0.0f);
}

/* erfc(x) from e = exp(-x^2) (Abramowitz & Stegun 1964, eq. 7.1.26). */
inline LFLOAT LNAME(erfc_from_gaussian)(LFLOAT x, LFLOAT e) {
    const LFLOAT t = 1.0f / (1.0f + 0.3275911f * fabs(x));
    LFLOAT p = 1.061405429f;
    p = -1.453152027f + t * p;
    p = 1.421413741f + t * p;
    p = -0.284496736f + t * p;
    p = 0.254829592f + t * p;
    const LFLOAT r = t * p * e;
    return select(2.0f - r, r, x >= 0.0f);
}

/* D(m) = exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay z^4); 0 for m.z <= 0 and where the
 * exponent passes 88. */
inline LFLOAT LNAME(beckmann_D)(LFLOAT ax, LFLOAT ay, LVEC3 m) {
    const LFLOAT z2 = m.z * m.z;
    const LFLOAT sx = m.x / ax, sy = m.y / ay;
    const LFLOAT e = (sx * sx + sy * sy) / z2;
    const LINT some = (m.z > 0.0f) & (e < 88.0f);
    if (!LNAME(lanes_any)(some)) return (LFLOAT)(0.0f); /* every lane's D is 0 */
    return select((LFLOAT)(0.0f), LNAME(exp_poly)(-e) / (FC_PI * ax * ay * z2 * z2), some);
}

/* Lambda(w) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = |z| / s, s = |(ax x, ay y)|: 0
 * where s = 0 or a >= 6, infinite at z = 0. */
inline LFLOAT LNAME(beckmann_lambda)(LFLOAT ax, LFLOAT ay, LVEC3 w) {
    const LFLOAT tx = ax * w.x, ty = ay * w.y;
    const LFLOAT s = sqrt(tx * tx + ty * ty);
    const LFLOAT z = fabs(w.z);
    const LFLOAT a = z / s;
    /* every lane's Lambda is 0 where no lane has a < 6 and s != 0 (built without a vector NOT) */
    if (!LNAME(lanes_any)(((a < 6.0f) | isnan(a)) & (s != 0.0f))) return (LFLOAT)(0.0f);
    LFLOAT l = fmax(0.5f * (LNAME(exp_poly)(-a * a) * FC_INV_SQRT_PI / a - LNAME(erfc_fast)(a)), 0.0f);
    l = select(l, (LFLOAT)(0.0f), a >= 6.0f);
    l = select(l, (LFLOAT)(INFINITY), z == 0.0f);
    return select(l, (LFLOAT)(0.0f), s == 0.0f);
}

/* w.z (1 + Lambda(w)) for w.z >= 0: (z (1 + erf(a)) + s exp(-a^2) / sqrt(pi)) / 2, erf from the
 * same exp(-a^2) (erfc_from_gaussian: an absolute error suffices in 1 + erf); z itself where
 * s = 0 or a >= 6. */
inline LFLOAT LNAME(beckmann_projected_area)(LFLOAT ax, LFLOAT ay, LVEC3 w) {
    const LFLOAT tx = ax * w.x, ty = ay * w.y;
    const LFLOAT s = sqrt(tx * tx + ty * ty);
    const LFLOAT z = fmax(w.z, 0.0f);
    const LFLOAT a = z / s;
    const LINT cut = (s == 0.0f) | (a >= 6.0f);
    /* every lane's area is z where no lane escapes the cut (built without a vector NOT) */
    if (!LNAME(lanes_any)((s != 0.0f) & ((a < 6.0f) | isnan(a)))) return z;
    const LFLOAT e = LNAME(exp_poly)(-a * a);
    const LFLOAT area = 0.5f * (z * (2.0f - LNAME(erfc_from_gaussian)(a, e)) + s * e * FC_INV_SQRT_PI);
    return select(area, z, cut);
}

/* D_wo(m) = max(0, wo.m) D(m) / (wo.z (1 + Lambda(wo))); 0 where wo.z or wo.m is not > 0. */
inline LFLOAT LNAME(beckmann_pdf_visible)(LFLOAT ax, LFLOAT ay, LVEC3 wo, LVEC3 m) {
    const LFLOAT wm = LNAME(vec3_dot)(wo, m);
    const LFLOAT p = LNAME(beckmann_D)(ax, ay, m) * wm / LNAME(beckmann_projected_area)(ax, ay, wo);
    return select((LFLOAT)(0.0f), p, (wo.z > 0.0f) & (wm > 0.0f));
}

/* The x slope of a visible normal for unit roughness, the view at angle theta in the xz plane
 * (tan_t, cot_t = tan and cot theta): C(x) = u C(cot_t) solved by Newton-Raphson safeguarded
 * by bisection, from Jakob's fitted guess, to a CDF within 1e-6 of its target
 * (kernels/bsdf/beckmann.cl). */
inline LFLOAT LNAME(beckmann_visible_slope_x)(LFLOAT tan_t, LFLOAT cot_t, LFLOAT theta, LFLOAT u) {
    const LINT near = cot_t < 6.0f; /* else C(cot_t) = 2 and c = 1 in float */
    LFLOAT total = (LFLOAT)(2.0f), c = (LFLOAT)(1.0f);
    if (LNAME(lanes_any)(near)) {
        const LFLOAT r = LNAME(erfc_fast)(cot_t);
        total = select(total, (2.0f - r) + tan_t * LNAME(exp_poly)(-cot_t * cot_t) * FC_INV_SQRT_PI, near);
        c = select(c, 1.0f - r, near);
    }
    const LFLOAT target = u * total;
    LFLOAT lo = (LFLOAT)(-8.0f);
    LFLOAT hi = fmin(cot_t, 8.0f);
    const LFLOAT fit = 1.0f + theta * (-0.876f + theta * (0.4265f - 0.0594f * theta));
    LFLOAT x = LNAME(erfinv_giles)(c - (1.0f + c) * LNAME(exp_poly)(fit * log(1.0f - u)));
    x = select(0.5f * (lo + hi), x, (x > lo) & (x < hi));
    LINT going = lo == lo; /* every lane */
    for (int it = 0; it < 24 && LNAME(lanes_any)(going); ++it) {
        const LFLOAT e = LNAME(exp_poly)(-x * x);
        const LFLOAT g = LNAME(erfc_from_gaussian)(-x, e) + tan_t * e * FC_INV_SQRT_PI - target;
        going = select(going, (LINT)(0), fabs(g) <= 1e-6f * total);
        if (!LNAME(lanes_any)(going)) break; /* every lane within the tolerance */
        const LINT above = g > 0.0f;
        hi = select(hi, select(hi, x, above), going);
        lo = select(lo, select(x, lo, above), going);
        const LFLOAT dg = 2.0f * FC_INV_SQRT_PI * e * (1.0f - x * tan_t); /* >= 0 below cot_t */
        const LFLOAT next = x - g / dg;
        x = select(x, select(0.5f * (lo + hi), next, (next > lo) & (next < hi)), going);
        going = select(going, (LINT)(0), hi - lo <= 1e-7f * (1.0f + fabs(x)));
    }
    return x;
}

/* A visible normal seen from wo (wo.z > 0; Heitz & d'Eon 2014, algorithm 1), from (ux, uy)
 * uniform in [0, 1)^2: stretch, the slopes of the isotropic configuration, rotate, unstretch. */
inline LVEC3 LNAME(beckmann_sample_visible)(LFLOAT ax, LFLOAT ay, LVEC3 wo, LFLOAT ux, LFLOAT uy) {
    const LFLOAT sx = ax * wo.x, sy = ay * wo.y;
    const LFLOAT s = sqrt(sx * sx + sy * sy);
    const LFLOAT z = fmax(wo.z, 0.0f);
    const LINT tilted = s > 0.0f;
    const LFLOAT cos_phi = select((LFLOAT)(1.0f), sx / s, tilted), sin_phi = select((LFLOAT)(0.0f), sy / s, tilted);
    /* z = 0 (grazing): tan_t = 1e30, cot_t = 0; s = 0 (normal incidence): cot_t infinite */
    const LINT above = z > 0.0f;
    const LFLOAT tan_t = select((LFLOAT)(1e30f), s / z, above), cot_t = select((LFLOAT)(0.0f), z / s, above);
    const LFLOAT x = LNAME(beckmann_visible_slope_x)(tan_t, cot_t, LNAME(atan2_fast)(s, z), ux);
    const LFLOAT y = LNAME(erfinv_giles)(2.0f * uy - 1.0f);
    const LFLOAT mx = ax * (cos_phi * x - sin_phi * y), my = ay * (sin_phi * x + cos_phi * y);
    const LFLOAT il = rsqrt(mx * mx + my * my + 1.0f);
    return LNAME(vec3)(-mx * il, -my * il, il);
}

#undef FACET_BSDF_BECKMANN_LANES_PASS
#endif
