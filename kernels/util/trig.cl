/* Trigonometry for the angles sampling and the environment map use, without the
 * full-range argument reduction of the built-in sin, cos, atan2 and acos (on PoCL those
 * were a fifth of the sky scenes' render-kernel instructions, docs/performance.md,
 * "Shading costs").
 *
 * - sincos_turns(t): sin and cos of 2 pi t for an angle given in turns (every sampler
 *   writes phi = 2 pi u). The reduction to the nearest quarter turn is exact in float,
 *   then Taylor polynomials on |x| <= pi/4 (truncation below 2e-9). Max error over
 *   t in [-1, 2]: 8.1e-8 absolute, sin near 0 within 1.4e-7 relative (Trig.SincosTurnsMaxError),
 *   where sin(2 pi t) in float is already off by up to 2.4e-7 from rounding 2 pi t.
 * - atan2_fast(y, x): a polynomial atan on [0, 1] (odd, degree 17, fitted for least
 *   relative error) after folding the octants; max error 1.65e-7 relative, 2.9e-7
 *   absolute near +-pi (1.2 ulp of pi) over the whole plane (Trig.Atan2FastMaxError),
 *   with atan2's values on the axes and at signed zeros. */
#ifndef FACET_UTIL_TRIG_CL
#define FACET_UTIL_TRIG_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/util/math.cl"

/* (sin 2 pi t, cos 2 pi t) for finite t with |t| < 2^21 (kernels/util/trig_lanes.cl). */
inline float2 sincos_turns(float t) { return sincos_turns_l1(t); }

/* atan2(y, x) in [-pi, pi], for finite y and x (atan2_fast(+-0, -0) = +-pi, as atan2;
 * kernels/util/trig_lanes.cl). */
inline float atan2_fast(float y, float x) { return atan2_fast_l1(y, x); }

#endif
