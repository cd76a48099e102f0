/* Small math helpers shared by every kernel. */
#ifndef FACET_UTIL_MATH_CL
#define FACET_UTIL_MATH_CL

#include "kernels/shared/types.h"

#define FC_PI 3.14159265358979323846f
#define FC_INV_PI 0.31830988618379067154f
#define FC_2PI 6.28318530717958647693f
#define FC_INV_2PI 0.15915494309189533577f
#define FC_PI_2 1.57079632679489661923f
#define FC_ONE_MINUS_EPSILON 0x1.fffffep-1f

inline float3 load3(const __global float* p) { return (float3)(p[0], p[1], p[2]); }
inline float3 load3c(const __constant float* p) { return (float3)(p[0], p[1], p[2]); }
inline float3 load3p(const float* p) { return (float3)(p[0], p[1], p[2]); }

/* Rec. 709 / linear sRGB luminance. */
inline float luminance(float3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

inline float max3(float3 c) { return fmax(c.x, fmax(c.y, c.z)); }

inline bool is_black(float3 c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }

inline bool all_finite(float3 c) { return isfinite(c.x) && isfinite(c.y) && isfinite(c.z); }

inline float sqr(float x) { return x * x; }

/* x^y for x > 0, as exp2(y log2 x). PoCL's pow() works in extended precision (its
 * __pocl_epln and __pocl_expep were 6 % of material_grid's render-kernel instructions,
 * docs/performance.md); this costs two built-ins of at most 3 ulp each (OpenCL 1.2) and
 * the rounding of y log2 x, an error in the exponent that grows with |y log2 x|, so with
 * how small the result is: within 1e-5 relative wherever x^y >= 1e-30, 2e-6 where
 * x^y >= 1e-6 (Math.PowPositiveRelativeError). x = 0 gives 0 for y > 0; the callers keep
 * x > 0 (0 * log2(0) would be NaN at y = 0). */
inline float pow_positive(float x, float y) { return exp2(y * log2(x)); }

inline float safe_sqrt(float x) { return sqrt(fmax(x, 0.0f)); }

/* Index of the lowest set bit of a non-zero mask (OpenCL C 1.2 has clz, not ctz). */
inline uint lowest_bit(uint bits) { return 31u - clz(bits & (0u - bits)); }

/* Normalises v, or returns `fallback` when v has zero or non-finite length. */
inline float3 normalize_or(float3 v, float3 fallback) {
    float len2 = dot(v, v);
    return (len2 > 0.0f && isfinite(len2)) ? v * rsqrt(len2) : fallback;
}

/* normalize_or for a vector of any finite size, scaled by its largest component first:
 * a geometric normal cross(e1, e2) of edges above ~4e9 (or below ~1e-10) has a squared
 * length beyond the float range, and the scene format allows edges to 2e18. */
inline float3 normalize_scaled_or(float3 v, float3 fallback) {
    float m = fmax(fmax(fabs(v.x), fabs(v.y)), fabs(v.z));
    if (!(m > 0.0f) || !isfinite(m)) return fallback;
    return normalize_or(v / m, fallback);
}

#endif
