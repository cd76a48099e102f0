/* Lane-generic body (kernels/lanes/lanes.cl): e^x, the same bits at every width. PoCL's
 * built-in exp, exp2 and log2 round differently in scalar and vector code (a few of 8192
 * arguments differ by an ulp: tests/lanes_test.cpp), which the lanes' contract forbids. */
#ifndef FACET_UTIL_EXP_LANES_PASS
#define FACET_UTIL_EXP_LANES_PASS

/* e^x: x = k ln 2 + r with k = rint(x / ln 2) and |r| <= ln 2 / 2 (Cody & Waite's two-part
 * ln 2), e^r by its Taylor polynomial of degree 7 (truncation below 6e-9 relative), times 2^k
 * in two factors so that results down to the subnormals are reached. Within 1 ulp over
 * [-87, 88] (0.91 measured: Trig.ExpPolyMaxError); 0 below -104, infinite above 89, NaN for NaN. */
inline LFLOAT LNAME(exp_poly)(LFLOAT x) {
    const LFLOAT xc = fmin(fmax(x, -104.0f), 89.0f);
    const LFLOAT k = rint(xc * 1.44269504088896341f);
    const LFLOAT r = (xc - k * 0.693145751953125f) - k * 1.42860682030941723e-6f;
    LFLOAT p = 1.0f / 5040.0f;
    p = 1.0f / 720.0f + r * p;
    p = 1.0f / 120.0f + r * p;
    p = 1.0f / 24.0f + r * p;
    p = 1.0f / 6.0f + r * p;
    p = 0.5f + r * p;
    p = 1.0f + r * p;
    p = 1.0f + r * p;
    const LINT ki = LCONVERT_INT(k);
    const LINT k1 = ki >> 1, k2 = ki - k1;
    const LFLOAT y = p * LAS_FLOAT((k1 + 127) << 23) * LAS_FLOAT((k2 + 127) << 23);
    return select(y, x + x, x != x);
}

#undef FACET_UTIL_EXP_LANES_PASS
#endif
