/* Pixel reconstruction filters, applied by filter importance sampling (Ernst, Stamminger
 * and Greiner, "Filter Importance Sampling", RT 2006; pbrt-v4's FilterSampler): each
 * camera sample's offset from the pixel centre is drawn with density proportional to
 * |f|, and the sample carries the weight f / pdf = sign(f) * (integral of |f|) /
 * (integral of f), so that the plain average of the samples is the filtered pixel and
 * the two half-images stay independent (host/film/error_metrics.hpp).
 *
 * Every filter is separable, f(x, y) = f1(x) f1(y), with support [-radius, radius]:
 *   FC_FILTER_BOX       f1 = 1 (radius 0.5: uniform jitter inside the pixel)
 *   FC_FILTER_TENT      f1 = max(0, 1 - |x| / radius)
 *   FC_FILTER_GAUSSIAN  f1 = max(0, g(x) - g(radius)), g a Gaussian of sigma = radius / 3
 *                       (pbrt-v4's truncated Gaussian; radius 1.5 is its sigma 0.5)
 *   FC_FILTER_MITCHELL  Mitchell-Netravali, B = C = 1/3 (Mitchell and Netravali 1988),
 *                       scaled so that its support [-2, 2] spans [-radius, radius]; its
 *                       negative lobes (|t| in (8/7, 2)) give samples of weight < 0.
 * Box and tent are inverted in closed form, Gaussian and Mitchell by bisection of their
 * closed-form CDFs. The weight is 1 except for Mitchell. */
#ifndef FACET_CAMERA_FILTER_CL
#define FACET_CAMERA_FILTER_CL

#include "kernels/shared/render_layout.h"

/* Gaussian: the integral of max(0, g(x) - g(r)) over [0, t], t <= r, with
 * g(x) = exp(-x^2 / (2 sigma^2)). */
inline float gaussian_filter_cdf(float t, float sigma, float r) {
    return sigma * 1.2533141f * erf(t / (sigma * 1.4142136f)) - exp(-r * r / (2.0f * sigma * sigma)) * t;
}

/* Mitchell-Netravali with B = C = 1/3 on t in [0, 2]: the filter, and the integral of
 * the filter over [0, t] (piecewise quartic). */
inline float mitchell_filter(float t) {
    return t < 1.0f ? (7.0f * t * t * t - 12.0f * t * t + 16.0f / 3.0f) / 6.0f
                    : (-7.0f / 3.0f * t * t * t + 12.0f * t * t - 20.0f * t + 32.0f / 3.0f) / 6.0f;
}
inline float mitchell_integral(float t) {
    float t2 = t * t;
    if (t < 1.0f) return (1.75f * t2 * t2 - 4.0f * t2 * t + 16.0f / 3.0f * t) / 6.0f;
    /* P1(1) - P2(1) + P2(t), P1 and P2 the pieces' antiderivatives */
    return 0.51388889f - 0.68055556f + (-7.0f / 12.0f * t2 * t2 + 4.0f * t2 * t - 10.0f * t2 + 32.0f / 3.0f * t) / 6.0f;
}
/* The integral of |filter| over [0, t]: the lobe changes sign at t = 8/7. */
#define FC_MITCHELL_ZERO (8.0f / 7.0f)
inline float mitchell_abs_integral(float t) {
    if (t <= FC_MITCHELL_ZERO) return mitchell_integral(t);
    return 2.0f * mitchell_integral(FC_MITCHELL_ZERO) - mitchell_integral(t);
}

/* Inverse CDFs by bisection on [0, hi]: the t where the increasing integral of the
 * filter over [0, t] reaches `target` (22 halvings: below a float's step at 2 pixels). */
#define FC_FILTER_BISECTIONS 22
inline float gaussian_filter_invert(float target, float sigma, float r) {
    float lo = 0.0f, hi = r;
    for (int i = 0; i < FC_FILTER_BISECTIONS; ++i) {
        float t = 0.5f * (lo + hi);
        if (gaussian_filter_cdf(t, sigma, r) < target) lo = t;
        else hi = t;
    }
    return 0.5f * (lo + hi);
}
inline float mitchell_abs_invert(float target) {
    float lo = 0.0f, hi = 2.0f;
    for (int i = 0; i < FC_FILTER_BISECTIONS; ++i) {
        float t = 0.5f * (lo + hi);
        if (mitchell_abs_integral(t) < target) lo = t;
        else hi = t;
    }
    return 0.5f * (lo + hi);
}

/* One axis: an offset in [-radius, radius] drawn from |f1| with u in [0, 1); returns
 * sign(f1(offset)) * (integral of |f1|) / (integral of f1). */
inline float filter_sample_1d(uint filter, float radius, float u, float* offset) {
    /* The sign from the first half of u, the magnitude from the rest. */
    float side = u < 0.5f ? -1.0f : 1.0f;
    float v = u < 0.5f ? 2.0f * u : 2.0f * u - 1.0f;
    float weight = 1.0f;
    float t;
    if (filter == FC_FILTER_TENT) {
        t = radius * (1.0f - sqrt(1.0f - v));
    } else if (filter == FC_FILTER_GAUSSIAN) {
        float sigma = radius / 3.0f;
        t = gaussian_filter_invert(v * gaussian_filter_cdf(radius, sigma, radius), sigma, radius);
    } else if (filter == FC_FILTER_MITCHELL) {
        float total = mitchell_abs_integral(2.0f);
        float s = mitchell_abs_invert(v * total);
        weight = (mitchell_filter(s) < 0.0f ? -total : total) / 0.5f; /* the integral over [0, 2] is 1/2 */
        t = s * (radius * 0.5f);
    } else {
        t = v * radius;
    }
    *offset = side * t;
    return weight;
}

/* The offset of a camera sample from the pixel centre, drawn from the filter with the
 * uniform point u, and its weight. */
inline float filter_sample(uint filter, float radius, float2 u, float2* offset) {
    float ox, oy;
    float wx = filter_sample_1d(filter, radius, u.x, &ox);
    float wy = filter_sample_1d(filter, radius, u.y, &oy);
    *offset = (float2)(ox, oy);
    return wx * wy;
}

#endif
