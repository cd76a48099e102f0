/* A sample's camera ray: the pixel filter (kernels/camera/filter.cl) picks where in or
 * around pixel (x, y) it looks, the camera (camera.cl) makes the ray, both from the
 * sample's camera dimension set. The render and AOV kernels start their samples here. */
#ifndef FACET_CAMERA_PIXEL_SAMPLE_CL
#define FACET_CAMERA_PIXEL_SAMPLE_CL

#include "kernels/camera/camera.cl"
#include "kernels/camera/filter.cl"
#include "kernels/shared/render_layout.h"
#include "kernels/util/sampler.cl"

/* Writes the ray of the sample whose camera dimension set is u_camera, and returns the
 * filter's weight for the sample's radiance (1 for every filter but Mitchell-Netravali's,
 * whose negative lobes give a negative weight): kernels/camera/camera_lanes.cl's at W = 1. The
 * packet paths make their rays at their width, several paths at once. */
inline float pixel_sample_ray_at(__constant const FcRenderParams* params, uint x, uint y, float4 u_camera,
                                 float3* origin, float3* dir) {
    return pixel_sample_ray_at_l1(params, (float)x, (float)y, u_camera.x, u_camera.y, u_camera.z, u_camera.w, origin,
                                  dir);
}

/* pixel_sample_ray_at with the sample's camera dimension set. */
inline float pixel_sample_ray(__constant const FcRenderParams* params, uint x, uint y, Sampler* sampler, float3* origin,
                              float3* dir) {
    return pixel_sample_ray_at(params, x, y, sampler_get4(sampler, FC_SET_CAMERA), origin, dir);
}

#endif
