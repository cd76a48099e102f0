/* The Beckmann normal distribution, anisotropic (Beckmann & Spizzichino 1963; Walter
 * et al. 2007, eqs. 25-28; anisotropic form from Heitz 2014, "Understanding the
 * Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2), eqs. 80-84).
 *
 * Parameters: roughness ax along the tangent (x), ay along the bitangent (y), each in
 * [1e-7, 1] with ax/ay within 1e4 (below FC_ALPHA_MIRROR the caller treats the lobe as
 * a mirror). Its slope distribution is a Gaussian of standard deviations ax/sqrt(2),
 * ay/sqrt(2), which every sampler below uses. Local frame, n = +z. */
#ifndef FACET_BSDF_BECKMANN_CL
#define FACET_BSDF_BECKMANN_CL

#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

#define FC_INV_SQRT_PI 0.56418958354775628695f

/* erf^-1(x) for x in (-1, 1): Giles 2010, "Approximating the erfinv function", GPU
 * Computing Gems Jade, single-precision version (a few ulp). The argument is kept one
 * float away from +-1 so that the result stays finite (|result| <= 3.9). */
inline float erfinv_giles(float x) {
    x = clamp(x, -FC_ONE_MINUS_EPSILON, FC_ONE_MINUS_EPSILON);
    float w = -log((1.0f - x) * (1.0f + x));
    float p;
    if (w < 5.0f) {
        w = w - 2.5f;
        p = 2.81022636e-08f;
        p = 3.43273939e-07f + p * w;
        p = -3.5233877e-06f + p * w;
        p = -4.39150654e-06f + p * w;
        p = 0.00021858087f + p * w;
        p = -0.00125372503f + p * w;
        p = -0.00417768164f + p * w;
        p = 0.246640727f + p * w;
        p = 1.50140941f + p * w;
    } else {
        w = sqrt(w) - 3.0f;
        p = -0.000200214257f;
        p = 0.000100950558f + p * w;
        p = 0.00134934322f + p * w;
        p = -0.00367342844f + p * w;
        p = 0.00573950773f + p * w;
        p = -0.0076224613f + p * w;
        p = 0.00943887047f + p * w;
        p = 1.00167406f + p * w;
        p = 2.83297682f + p * w;
    }
    return p * x;
}

/* erfc(x) by Chebyshev fitting (Press et al. 2007, Numerical Recipes 3rd ed., section
 * 6.2.2, "erfcc"): relative error below 1.2e-7 everywhere, a few ulp more in float. Used
 * by Smith's Lambda, the projected area and the visible-normal sampler's inversion: PoCL's
 * erfc (SLEEF's scalar erfcf) took 14 % of the render time of the bench's material_grid,
 * whose spheres are mostly Beckmann (docs/performance.md, "Beckmann's erfc"). */
inline float erfc_fast(float x) {
    float z = fabs(x);
    float t = 1.0f / (1.0f + 0.5f * z);
    float p = 0.17087277f;
    p = -0.82215223f + t * p;
    p = 1.48851587f + t * p;
    p = -1.13520398f + t * p;
    p = 0.27886807f + t * p;
    p = -0.18628806f + t * p;
    p = 0.09678418f + t * p;
    p = 0.37409196f + t * p;
    p = 1.00002368f + t * p;
    float r = t * exp(-z * z - 1.26551223f + t * p);
    return (x >= 0.0f) ? r : 2.0f - r;
}

/* erfc(x) from e = exp(-x^2), which the caller has: Abramowitz & Stegun 1964, eq. 7.1.26,
 * absolute error below 1.5e-7 (7e-7 in float, near x = 0, where erfc is near 1), no
 * relative precision in the far tail. Enough where only an absolute error counts: the
 * visible-slope inversion's CDF. */
inline float erfc_from_gaussian(float x, float e) {
    float t = 1.0f / (1.0f + 0.3275911f * fabs(x));
    float p = 1.061405429f;
    p = -1.453152027f + t * p;
    p = 1.421413741f + t * p;
    p = -0.284496736f + t * p;
    p = 0.254829592f + t * p;
    float r = t * p * e;
    return (x >= 0.0f) ? r : 2.0f - r;
}

/* D(m) = exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay z^4) (Heitz 2014, eq. 80). The
 * exponent is tested first: past 88 the value is below the float range, which also
 * keeps z^4 away from 0. */
inline float beckmann_D(float ax, float ay, float3 m) {
    if (!(m.z > 0.0f)) return 0.0f;
    float z2 = m.z * m.z;
    float e = (sqr(m.x / ax) + sqr(m.y / ay)) / z2;
    if (!(e < 88.0f)) return 0.0f;
    return exp(-e) / (FC_PI * ax * ay * z2 * z2);
}

/* Smith's Lambda (Heitz 2014, eq. 83), with a = 1 / (alpha_w tan theta) =
 * |z| / sqrt(ax^2 x^2 + ay^2 y^2): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2,
 * the erfc form avoiding the cancellation of (erf(a) - 1). Below 1e-16 past a = 6. */
inline float beckmann_lambda(float ax, float ay, float3 w) {
    float s = sqrt(sqr(ax * w.x) + sqr(ay * w.y));
    float z = fabs(w.z);
    if (s == 0.0f) return 0.0f;
    if (z == 0.0f) return INFINITY;
    float a = z / s;
    if (a >= 6.0f) return 0.0f;
    return fmax(0.5f * (exp(-a * a) * FC_INV_SQRT_PI / a - erfc_fast(a)), 0.0f);
}

/* w.z (1 + Lambda(w)) for w.z >= 0, the projected area of the microsurface, as a sum of
 * positive terms: (z (1 + erf(a)) + s exp(-a^2) / sqrt(pi)) / 2. From a = 6 on, both of
 * Lambda's terms are below 1e-16 of z, far below z's rounding: the area is z, without the
 * two exponentials (a smooth surface seen away from grazing; as beckmann_lambda cuts off). */
inline float beckmann_projected_area(float ax, float ay, float3 w) {
    float s = sqrt(sqr(ax * w.x) + sqr(ay * w.y));
    float z = fmax(w.z, 0.0f);
    if (s == 0.0f) return z;
    float a = z / s;
    if (a >= 6.0f) return z;
    return 0.5f * (z * (2.0f - erfc_fast(a)) + s * exp(-a * a) * FC_INV_SQRT_PI);
}

/* A normal drawn from D(m) cos(theta_m): slopes (ax r cos phi, ay r sin phi) with
 * r^2 = -log(1 - u) (Walter 2007, eqs. 28-29, stretched). */
inline float3 beckmann_sample_all(float ax, float ay, float2 u) {
    float r = sqrt(-log(1.0f - u.x));
    float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
    float3 m = (float3)(-ax * r * sc.y, -ay * r * sc.x, 1.0f);
    return normalize(m);
}

inline float beckmann_pdf_all(float ax, float ay, float3 m) { return beckmann_D(ax, ay, m) * fmax(m.z, 0.0f); }

/* The x slope of a visible normal, for unit roughness and a view direction in the xz
 * plane at angle theta (tan_t = tan theta, cot_t = 1/tan theta, either may be 0 or inf).
 * Its density is (cot_t - x) exp(-x^2) / sqrt(pi) up to a constant for x < cot_t (Heitz
 * & d'Eon 2014, "Importance Sampling Microfacet-Based BSDFs using the Distribution of
 * Visible Normals", EGSR, section 4), with CDF proportional to
 *     C(x) = erfc(-x) + tan_t exp(-x^2) / sqrt(pi).
 * C(x) = u C(cot_t) is solved by Newton-Raphson safeguarded by bisection (Jakob 2014,
 * "An Improved Visible Normal Sampling Routine for the Beckmann Distribution", as in
 * Mitsuba 0.6, started from his fitted guess), but in the slope itself. Stops when the CDF is
 * within 1e-6 of its target (a mass error far below any test's resolution): the iterations'
 * erfc needs an absolute error only, and takes erfc_from_gaussian's, which reuses the step's
 * exp(-x^2) (in float 7e-7 at worst, near x = 0, as erfc_fast's 5e-7 there). */
inline float beckmann_visible_slope_x(float tan_t, float cot_t, float theta, float u) {
    /* C(cot_t) = erfc(-cot_t) + ..., and Jakob's c = erf(cot_t), from one erfc(cot_t) (cot_t
     * >= 0: erfc_fast(-x) is 2 - erfc_fast(x)). From cot_t = 6 on (the stretched view within
     * 9.5 degrees of the normal: at roughness 0.1, a view within 59 degrees) erfc(cot_t) <
     * 2e-17 and tan_t exp(-cot_t^2) < 4e-17: in float the total is 2 and c is 1, as computed
     * in full. */
    float total = 2.0f, c = 1.0f;
    if (cot_t < 6.0f) {
        const float r = erfc_fast(cot_t);
        total = (2.0f - r) + tan_t * exp(-cot_t * cot_t) * FC_INV_SQRT_PI;
        c = 1.0f - r;
    }
    float target = u * total;
    float lo = -8.0f;
    float hi = fmin(cot_t, 8.0f);
    /* Jakob's guess, fitted in the erf domain; (1 - u)^fit in base 2 (a starting point: pow's
     * last bits do not matter, and 1 - u > 0). */
    float fit = 1.0f + theta * (-0.876f + theta * (0.4265f - 0.0594f * theta));
    float x = erfinv_giles(c - (1.0f + c) * exp2(fit * log2(1.0f - u)));
    if (!(x > lo && x < hi)) x = 0.5f * (lo + hi);
    for (int it = 0; it < 24; ++it) {
        float e = exp(-x * x);
        float g = erfc_from_gaussian(-x, e) + tan_t * e * FC_INV_SQRT_PI - target;
        if (fabs(g) <= 1e-6f * total) break;
        if (g > 0.0f) hi = x;
        else lo = x;
        float dg = 2.0f * FC_INV_SQRT_PI * e * (1.0f - x * tan_t); /* >= 0 below cot_t */
        float next = x - g / dg;
        x = (next > lo && next < hi) ? next : 0.5f * (lo + hi);
        if (hi - lo <= 1e-7f * (1.0f + fabs(x))) break;
    }
    return x;
}

/* A normal drawn from the distribution of visible normals seen from wo (wo.z > 0),
 * exactly (Heitz & d'Eon 2014, algorithm 1): stretch wo to unit roughness, draw the
 * slopes of the isotropic configuration (x by inversion above, y a Gaussian), rotate
 * to wo's azimuth, unstretch. */
inline float3 beckmann_sample_visible(float ax, float ay, float3 wo, float2 u) {
    /* 1. stretch */
    float sx = ax * wo.x;
    float sy = ay * wo.y;
    float s = sqrt(sx * sx + sy * sy);
    float z = fmax(wo.z, 0.0f);
    float cos_phi = (s > 0.0f) ? sx / s : 1.0f;
    float sin_phi = (s > 0.0f) ? sy / s : 0.0f;
    /* 2. slopes of the unit-roughness configuration */
    float tan_t = s / z; /* z = 0 (grazing): tan_t = inf, handled by the loop's bisection */
    float cot_t = z / s; /* s = 0 (normal incidence): cot_t = inf, a plain Gaussian */
    if (!(z > 0.0f)) {
        tan_t = 1e30f;
        cot_t = 0.0f;
    }
    float x = beckmann_visible_slope_x(tan_t, cot_t, atan2_fast(s, z), u.x);
    float y = erfinv_giles(2.0f * u.y - 1.0f);
    /* 3. rotate, 4. unstretch */
    float mx = ax * (cos_phi * x - sin_phi * y);
    float my = ay * (sin_phi * x + cos_phi * y);
    /* 5. the normal of slope (mx, my) */
    return normalize((float3)(-mx, -my, 1.0f));
}

/* D_wo(m) = max(0, wo.m) D(m) / (wo.z (1 + Lambda(wo))) (Heitz & d'Eon 2014, eq. 2). */
inline float beckmann_pdf_visible(float ax, float ay, float3 wo, float3 m) {
    float wm = dot(wo, m);
    if (!(wo.z > 0.0f) || !(wm > 0.0f)) return 0.0f;
    return beckmann_D(ax, ay, m) * wm / beckmann_projected_area(ax, ay, wo);
}

#endif
