/* Lane-generic body (kernels/lanes/lanes.cl): the pixel filters' sampling (kernels/camera/filter.cl
 * has the models and the method; this is their only code). The scalar kernels run it at
 * W = 1, the packet paths at their width for the paths that begin together (issue 29). The
 * filter is the same for every lane, so its branches are too. */
#ifndef FACET_CAMERA_FILTER_LANES_PASS
#define FACET_CAMERA_FILTER_LANES_PASS

#ifndef FC_FILTER_BISECTIONS
#define FC_FILTER_BISECTIONS 22        /* halvings: below a float's step at 2 pixels */
#define FC_MITCHELL_ZERO (8.0f / 7.0f) /* where Mitchell-Netravali's lobe changes sign */
#endif

/* erf, lane by lane: PoCL's vector and scalar erf differ in the last bit here and there, and the
 * Gaussian's bisection must take the same steps at every width (tests/lanes_test.cpp). */
#if FC_LW == 1
inline LFLOAT LNAME(filter_erf)(LFLOAT x) { return erf(x); }
#else
inline LFLOAT LNAME(filter_erf)(LFLOAT x) {
    float v[FC_LW];
    LSTORE(x, v);
#pragma clang loop vectorize(disable) /* scalar erf calls, not the vector one */
    for (int j = 0; j < FC_LW; ++j) v[j] = erf(v[j]);
    return LLOAD(v);
}
#endif

/* Gaussian: the integral of max(0, g(x) - g(r)) over [0, t], t <= r, with
 * g(x) = exp(-x^2 / (2 sigma^2)). */
inline LFLOAT LNAME(gaussian_filter_cdf)(LFLOAT t, float sigma, float r) {
    return sigma * 1.2533141f * LNAME(filter_erf)(t / (sigma * 1.4142136f)) - exp(-r * r / (2.0f * sigma * sigma)) * t;
}

/* Mitchell-Netravali with B = C = 1/3 on t in [0, 2]: the filter, and the integral of the
 * filter over [0, t] (piecewise quartic; P1(1) - P2(1) + P2(t) past 1, P1 and P2 the
 * pieces' antiderivatives). */
inline LFLOAT LNAME(mitchell_filter)(LFLOAT t) {
    return select((-7.0f / 3.0f * t * t * t + 12.0f * t * t - 20.0f * t + 32.0f / 3.0f) / 6.0f,
                  (7.0f * t * t * t - 12.0f * t * t + 16.0f / 3.0f) / 6.0f, t < 1.0f);
}
inline LFLOAT LNAME(mitchell_integral)(LFLOAT t) {
    const LFLOAT t2 = t * t;
    return select(
        0.51388889f - 0.68055556f + (-7.0f / 12.0f * t2 * t2 + 4.0f * t2 * t - 10.0f * t2 + 32.0f / 3.0f * t) / 6.0f,
        (1.75f * t2 * t2 - 4.0f * t2 * t + 16.0f / 3.0f * t) / 6.0f, t < 1.0f);
}
/* The integral of |filter| over [0, t]: the lobe changes sign at t = 8/7. */
inline LFLOAT LNAME(mitchell_abs_integral)(LFLOAT t) {
    const LFLOAT i = LNAME(mitchell_integral)(t);
    return select(2.0f * LNAME(mitchell_integral)((LFLOAT)(FC_MITCHELL_ZERO)) - i, i, t <= FC_MITCHELL_ZERO);
}

/* Inverse cdfs by bisection on [0, r] and [0, 2]: the t where the increasing integral of the
 * filter over [0, t] reaches `target` (FC_FILTER_BISECTIONS halvings). */
inline LFLOAT LNAME(gaussian_filter_invert)(LFLOAT target, float sigma, float r) {
    LFLOAT lo = 0.0f, hi = r;
    for (int i = 0; i < FC_FILTER_BISECTIONS; ++i) {
        const LFLOAT t = 0.5f * (lo + hi);
        const LINT below = LNAME(gaussian_filter_cdf)(t, sigma, r) < target;
        lo = select(lo, t, below);
        hi = select(t, hi, below);
    }
    return 0.5f * (lo + hi);
}
inline LFLOAT LNAME(mitchell_abs_invert)(LFLOAT target) {
    LFLOAT lo = 0.0f, hi = 2.0f;
    for (int i = 0; i < FC_FILTER_BISECTIONS; ++i) {
        const LFLOAT t = 0.5f * (lo + hi);
        const LINT below = LNAME(mitchell_abs_integral)(t) < target;
        lo = select(lo, t, below);
        hi = select(t, hi, below);
    }
    return 0.5f * (lo + hi);
}

/* One axis: an offset in [-radius, radius] drawn from |f1| with u in [0, 1), in *offset;
 * returns sign(f1(offset)) * (integral of |f1|) / (integral of f1). The sign from the first
 * half of u, the magnitude from the rest. */
inline LFLOAT LNAME(filter_sample_1d)(uint filter, float radius, LFLOAT u, LFLOAT* offset) {
    const LINT low = u < 0.5f;
    const LFLOAT side = select((LFLOAT)(1.0f), (LFLOAT)(-1.0f), low);
    const LFLOAT v = select(2.0f * u - 1.0f, 2.0f * u, low);
    LFLOAT weight = 1.0f;
    LFLOAT t;
    if (filter == FC_FILTER_TENT) {
        t = radius * (1.0f - sqrt(1.0f - v));
    } else if (filter == FC_FILTER_GAUSSIAN) {
        const float sigma = radius / 3.0f;
        t = LNAME(gaussian_filter_invert)(v * gaussian_filter_cdf_l1(radius, sigma, radius), sigma, radius);
    } else if (filter == FC_FILTER_MITCHELL) {
        const float total = mitchell_abs_integral_l1(2.0f); /* the same for every lane */
        const LFLOAT s = LNAME(mitchell_abs_invert)(v * total);
        /* the integral over [0, 2] is 1/2 */
        weight = select((LFLOAT)(total / 0.5f), (LFLOAT)(-total / 0.5f), LNAME(mitchell_filter)(s) < 0.0f);
        t = s * (radius * 0.5f);
    } else {
        t = v * radius;
    }
    *offset = side * t;
    return weight;
}

#undef FACET_CAMERA_FILTER_LANES_PASS
#endif
