/* The Beckmann normal distribution, anisotropic (Beckmann & Spizzichino 1963; Walter
 * et al. 2007, eqs. 25-28; anisotropic form from Heitz 2014, "Understanding the
 * Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2), eqs. 80-84).
 *
 * Parameters: roughness ax along the tangent (x), ay along the bitangent (y), each in
 * [1e-7, 1] with ax/ay within 1e4 (below FC_ALPHA_MIRROR the caller treats the lobe as
 * a mirror). Its slope distribution is a Gaussian of standard deviations ax/sqrt(2),
 * ay/sqrt(2), which every sampler below uses. Local frame, n = +z.
 *
 * The functions below that return a *_l1 call are the W = 1 forms of the lane-generic bodies
 * of kernels/bsdf/beckmann_lanes.cl (kernels/lanes/lanes.cl), which the packet kernels run in lanes. */
#ifndef FACET_BSDF_BECKMANN_CL
#define FACET_BSDF_BECKMANN_CL

#include "kernels/lanes/scalar.cl" /* the W = 1 forms of kernels/bsdf/beckmann_lanes.cl (and FC_INV_SQRT_PI) */
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

/* erf^-1(x) for x in (-1, 1): Giles 2010, "Approximating the erfinv function", GPU
 * Computing Gems Jade, single-precision version (a few ulp). The argument is kept one
 * float away from +-1 so that the result stays finite (|result| <= 3.9). */
inline float erfinv_giles(float x) { return erfinv_giles_l1(x); }

/* erfc(x) by Chebyshev fitting (Press et al. 2007, Numerical Recipes 3rd ed., section
 * 6.2.2, "erfcc"): relative error below 1.2e-7 everywhere, a few ulp more in float. Used
 * by Smith's Lambda, the projected area and the visible-normal sampler's inversion: PoCL's
 * erfc (SLEEF's scalar erfcf) took 14 % of the render time of the bench's material_grid,
 * whose spheres are mostly Beckmann (docs/performance.md, "Beckmann's erfc"). */
inline float erfc_fast(float x) { return erfc_fast_l1(x); }

/* erfc(x) from e = exp(-x^2), which the caller has: Abramowitz & Stegun 1964, eq. 7.1.26,
 * absolute error below 1.5e-7 (7e-7 in float, near x = 0, where erfc is near 1), no
 * relative precision in the far tail. Enough where only an absolute error counts: the
 * visible-slope inversion's CDF. */
inline float erfc_from_gaussian(float x, float e) { return erfc_from_gaussian_l1(x, e); }

/* D(m) = exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay z^4) (Heitz 2014, eq. 80). The
 * exponent is tested first: past 88 the value is below the float range, which also
 * keeps z^4 away from 0. */
inline float beckmann_D(float ax, float ay, float3 m) { return beckmann_D_l1(ax, ay, m); }

/* Smith's Lambda (Heitz 2014, eq. 83), with a = 1 / (alpha_w tan theta) =
 * |z| / sqrt(ax^2 x^2 + ay^2 y^2): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2,
 * the erfc form avoiding the cancellation of (erf(a) - 1). Below 1e-16 past a = 6. */
inline float beckmann_lambda(float ax, float ay, float3 w) { return beckmann_lambda_l1(ax, ay, w); }

/* w.z (1 + Lambda(w)) for w.z >= 0, the projected area of the microsurface, as a sum of
 * positive terms: (z (1 + erf(a)) + s exp(-a^2) / sqrt(pi)) / 2. Its erfc appears only as
 * 2 - erfc(a) = 1 + erf(a), where an absolute error suffices: erfc_from_gaussian's, on the
 * exp(-a^2) the second term needs anyway (one exponential, not two; within 2.4e-7 relative:
 * Trig.BeckmannAreaAndLambdaMaxError). From a = 6 on, both of Lambda's terms are below 1e-16
 * of z, far below z's rounding: the area is z, without the exponential (a smooth surface seen
 * away from grazing; as beckmann_lambda cuts off). */
inline float beckmann_projected_area(float ax, float ay, float3 w) { return beckmann_projected_area_l1(ax, ay, w); }

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
    return beckmann_visible_slope_x_l1(tan_t, cot_t, theta, u);
}

/* A normal drawn from the distribution of visible normals seen from wo (wo.z > 0),
 * exactly (Heitz & d'Eon 2014, algorithm 1): stretch wo to unit roughness, draw the
 * slopes of the isotropic configuration (x by inversion above, y a Gaussian), rotate
 * to wo's azimuth, unstretch. */
inline float3 beckmann_sample_visible(float ax, float ay, float3 wo, float2 u) {
    return beckmann_sample_visible_l1(ax, ay, wo, u.x, u.y);
}

/* D_wo(m) = max(0, wo.m) D(m) / (wo.z (1 + Lambda(wo))) (Heitz & d'Eon 2014, eq. 2). */
inline float beckmann_pdf_visible(float ax, float ay, float3 wo, float3 m) {
    return beckmann_pdf_visible_l1(ax, ay, wo, m);
}

#endif
