/* Multiple importance sampling weights: the scalar forms of kernels/util/mis_lanes.cl. */
#ifndef FACET_UTIL_MIS_CL
#define FACET_UTIL_MIS_CL

#include "kernels/lanes/scalar.cl"

/* Veach's power heuristic with beta = 2, for two strategies with one sample each (Veach
 * 1997, section 9.2.4). Safe for infinite pdfs (delta lobes) and zeros. */
inline float power_heuristic(float pdf_a, float pdf_b) { return power_heuristic_l1(pdf_a, pdf_b); }

#endif
