/* The environment: light from infinitely far away, seen by rays that escape the
 * scene and sampled by next-event estimation (kernels/lights/environment.cl).
 *
 * An equirectangular map (width x height texels, linear RGB), or a constant
 * radiance when width == height == 0. Directions map to the image as
 *   u = phi / 2pi,  v = theta / pi,  with  d = (sin theta sin phi, cos theta, -sin theta cos phi)
 * in the map's own frame, after the world-to-map rotation `to_map` (rows of a 3x3
 * matrix): +y up (v = 0 the top row), the centre of the image (u = 0.5) looking along +z,
 * u growing to the right of a viewer inside the sphere looking at the centre (toward -x,
 * right-handed), so the map is seen unmirrored. Texel (x, y) covers
 * [x/W, (x+1)/W) x [y/H, (y+1)/H), its centre at ((x + 0.5)/W, (y + 0.5)/H). Lookups
 * (`filter`) are nearest-texel, or bilinear between the four nearest texel centres
 * (wrapping in u; constant beyond the first and last rows' centres, toward the poles).
 * Radiance = lookup * scale.
 * Sampling uses a piecewise-constant 2D distribution over luminance x sin(theta):
 * a marginal cdf over rows (H + 1 floats) then a conditional cdf per row (W + 1 floats
 * each) in the distribution buffer, then their guide tables (Chen & Asau 1974) that
 * start each search near its answer, then each row's largest conditional probability
 * (host/scene/environment_map.hpp documents the layout;
 * docs/environment.md the whole). */
#ifndef FACET_SHARED_ENVIRONMENT_LAYOUT_H
#define FACET_SHARED_ENVIRONMENT_LAYOUT_H

#include "kernels/shared/types.h"

#define FC_ENV_FILTER_NEAREST 0
#define FC_ENV_FILTER_BILINEAR 1

/* The entries, less one, of the guide table of a cdf of n intervals: the largest power of
 * two not above max(n / 2, 1) (a power of two, so that u g is exact in float). */
#if defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
inline uint env_guide_size(uint n) { return 1u << (31u - clz(max(n >> 1, 1u))); }
#else
static inline fc_uint env_guide_size(fc_uint n) {
    fc_uint g = 1u;
    while (2u * g <= (n >> 1)) g *= 2u;
    return g;
}
#endif

typedef struct FcEnvironment {
    fc_int width; /* 0: no map (constant radiance, or no environment at all) */
    fc_int height;
    fc_int enabled;     /* 0: no environment (escaped rays see black) */
    fc_int filter;      /* FC_ENV_FILTER_*: how a map is looked up */
    float scale[3];     /* radiance multiplier (the constant radiance when width == 0) */
    float total;        /* integral of luminance x sin(theta) over the map's (u, v) square */
    float to_map[3][4]; /* world-to-map rotation, row-major, 4th column unused */
} FcEnvironment;

FC_STATIC_ASSERT(sizeof(FcEnvironment) == 80, "FcEnvironment is 80 bytes");

#endif
