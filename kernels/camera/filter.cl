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
 * closed-form CDFs. The weight is 1 except for Mitchell. The code: filter_lanes.cl. */
#ifndef FACET_CAMERA_FILTER_CL
#define FACET_CAMERA_FILTER_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/shared/render_layout.h"

/* The code is lane-generic (kernels/camera/filter_lanes.cl: filter_sample_1d, one axis); the
 * scalar kernels run its W = 1 form through pixel_sample_ray_at (pixel_sample.cl). */

#endif
