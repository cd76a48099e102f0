/* Lane-generic body (kernels/lanes/lanes.cl): sin and cos of an angle in turns
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

#undef FACET_UTIL_TRIG_LANES_PASS
#endif
