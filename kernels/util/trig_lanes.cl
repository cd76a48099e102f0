/* Lane-generic body (kernels/lanes/lanes.cl): sin and cos of an angle in turns, and atan2
 * (kernels/util/trig.cl has the accuracy figures). */
#ifndef FACET_UTIL_TRIG_LANES_PASS
#define FACET_UTIL_TRIG_LANES_PASS

/* (sin 2 pi t, cos 2 pi t) for finite t with |t| < 2^21. */
inline LVEC2 LNAME(sincos_turns)(LFLOAT t) {
    /* t = q / 4 + f exactly, q an integer, |f| <= 1/8 */
    LFLOAT q = rint(4.0f * t);
    LFLOAT f = t - 0.25f * q;
    LFLOAT x = FC_2PI * f;
    LFLOAT x2 = x * x;
    /* Taylor series of sin and cos on |x| <= pi/4 */
    LFLOAT s = 2.7557319e-06f;
    s = -1.9841270e-04f + x2 * s;
    s = 8.3333338e-03f + x2 * s;
    s = -1.6666667e-01f + x2 * s;
    s = x + x * x2 * s;
    LFLOAT c = -2.7557320e-07f;
    c = 2.4801588e-05f + x2 * c;
    c = -1.3888889e-03f + x2 * c;
    c = 4.1666668e-02f + x2 * c;
    c = -0.5f + x2 * c;
    c = 1.0f + x2 * c;
    /* turn by q quarter turns: (sin, cos)(x + k pi/2) */
    LINT k = LCONVERT_INT(q) & 3;
    LINT odd = (k & 1) != 0;
    LFLOAT a = select(s, c, odd);
    LFLOAT b = select(c, s, odd);
    return LNAME(vec2)(select(a, -a, (k & 2) != 0), select(b, -b, ((k + 1) & 2) != 0));
}

/* atan(t) for t in [0, 1]: t p(t^2), p fitted by iteratively reweighted least squares
 * for the least maximum relative error (1.5e-8 in exact arithmetic). */
inline LFLOAT LNAME(atan_unit)(LFLOAT t) {
    LFLOAT t2 = t * t;
    LFLOAT p = 2.8499854e-03f;
    p = -1.6068989e-02f + t2 * p;
    p = 4.2692069e-02f + t2 * p;
    p = -7.5043380e-02f + t2 * p;
    p = 1.0640953e-01f + t2 * p;
    p = -1.4203648e-01f + t2 * p;
    p = 1.9992620e-01f + t2 * p;
    p = -3.3333072e-01f + t2 * p;
    p = 1.0f + t2 * p;
    return t * p;
}

/* atan2(y, x) in [-pi, pi], for finite y and x (+-pi at (+-0, -0), as atan2): the octants
 * folded onto [0, 1], then unfolded by selects. */
inline LFLOAT LNAME(atan2_fast)(LFLOAT y, LFLOAT x) {
    LFLOAT ax = fabs(x), ay = fabs(y);
    LFLOAT hi = fmax(ax, ay), lo = fmin(ax, ay);
    LFLOAT r = LNAME(atan_unit)(select((LFLOAT)(0.0f), lo / hi, hi > 0.0f));
    r = select(r, FC_PI_2 - r, ay > ax);
    r = select(r, FC_PI - r, signbit(x));
    return copysign(r, y);
}

#undef FACET_UTIL_TRIG_LANES_PASS
#endif
