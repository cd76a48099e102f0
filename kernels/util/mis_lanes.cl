/* Lane-generic body (kernels/lanes/lanes.cl): multiple importance sampling weights. */
#ifndef FACET_UTIL_MIS_LANES_PASS
#define FACET_UTIL_MIS_LANES_PASS

/* Veach's power heuristic with beta = 2, for two strategies with one sample each (Veach
 * 1997, section 9.2.4): the weight of strategy a. 1 where pdf_a is infinite (a delta
 * lobe), 0 where both densities are 0. */
inline LFLOAT LNAME(power_heuristic)(LFLOAT pdf_a, LFLOAT pdf_b) {
    LFLOAT a = pdf_a * pdf_a;
    LFLOAT b = pdf_b * pdf_b;
    LFLOAT w = select((LFLOAT)(0.0f), a / (a + b), a + b > 0.0f);
    return select(w, (LFLOAT)(1.0f), isinf(pdf_a));
}

#undef FACET_UTIL_MIS_LANES_PASS
#endif
