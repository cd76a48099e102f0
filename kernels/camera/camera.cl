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

#include "kernels/shared/render_layout.h"
#include "kernels/util/math.cl"
#include "kernels/util/warp.cl"

/* The ray through image position (x, y) in pixels, (0, 0) the top-left corner; u_lens
 * picks the point on the lens. */
inline void camera_ray(__constant const FcCamera* cam, float x, float y, uint width, uint height, float2 u_lens,
                       float3* origin, float3* dir) {
    float sx = 2.0f * x / (float)width - 1.0f;
    float sy = 1.0f - 2.0f * y / (float)height;
    float3 eye = load3c(cam->eye);
    float3 forward = load3c(cam->forward);
    float3 right = load3c(cam->right);
    float3 up = load3c(cam->up);
    if (cam->projection == FC_PROJECTION_ORTHOGRAPHIC) {
        *origin = eye + sx * right + sy * up;
        *dir = forward;
        return;
    }
    float3 pinhole = forward + sx * right + sy * up; /* at distance 1 along forward */
    if (!(cam->lens_radius > 0.0f)) {
        *origin = eye;
        *dir = normalize(pinhole);
        return;
    }
    float3 focus = eye + cam->focus_distance * pinhole;
    float2 lens = cam->lens_radius * square_to_disk_concentric(u_lens);
    *origin = eye + lens.x * normalize(right) + lens.y * normalize(up);
    *dir = normalize(focus - *origin);
}

#endif
