/* Camera rays: pinhole and thin-lens perspective, and orthographic projections. Where
 * inside (or around) the pixel a sample looks is the pixel filter's business
 * (kernels/camera/filter.cl). The camera layout is FcCamera in
 * kernels/shared/render_layout.h.
 *
 * Thin lens (pbrt-v4's PerspectiveCamera, Kolb et al. 1995): the ray through image
 * position (x, y) of the pinhole meets the plane of focus, focus_distance along
 * `forward`; the thin-lens ray leaves a uniformly sampled point of the lens disk of
 * radius lens_radius (Shirley-Chiu concentric mapping) toward that point, so points on
 * the plane of focus are sharp and others are blurred by the aperture. */
#ifndef FACET_CAMERA_CAMERA_CL
#define FACET_CAMERA_CAMERA_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/shared/render_layout.h"
#include "kernels/util/math.cl"

/* The code is lane-generic (kernels/camera/camera_lanes.cl: camera_ray); the scalar kernels
 * run its W = 1 form through pixel_sample_ray_at (pixel_sample.cl). */

#endif
