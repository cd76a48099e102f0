/* Camera rays: pinhole perspective and orthographic projections with a jittered
 * position inside the pixel (box filter). The camera layout is FcCamera in
 * kernels/shared/render_layout.h. */
#ifndef FACET_CAMERA_CAMERA_CL
#define FACET_CAMERA_CAMERA_CL

#include "kernels/shared/render_layout.h"
#include "kernels/util/math.cl"

/* The ray through image position (x, y) in pixels, (0, 0) the top-left corner. */
inline void camera_ray(__constant const FcCamera* cam, float x, float y, uint width, uint height, float3* origin,
                       float3* dir) {
    float sx = 2.0f * x / (float)width - 1.0f;
    float sy = 1.0f - 2.0f * y / (float)height;
    float3 eye = load3c(cam->eye);
    float3 forward = load3c(cam->forward);
    float3 right = load3c(cam->right);
    float3 up = load3c(cam->up);
    if (cam->projection == FC_PROJECTION_ORTHOGRAPHIC) {
        *origin = eye + sx * right + sy * up;
        *dir = forward;
    } else {
        *origin = eye;
        *dir = normalize(forward + sx * right + sy * up);
    }
}

#endif
