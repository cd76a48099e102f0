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
 * whose negative lobes give a negative weight). The packet paths draw u_camera in lanes. */
inline float pixel_sample_ray_at(__constant const FcRenderParams* params, uint x, uint y, float4 u_camera,
                                 float3* origin, float3* dir) {
    float2 offset;
    float weight = filter_sample(params->filter, params->filter_radius, u_camera.xy, &offset);
    camera_ray(&params->camera, (float)x + 0.5f + offset.x, (float)y + 0.5f + offset.y, params->width, params->height,
               u_camera.zw, origin, dir);
    return weight;
}

/* pixel_sample_ray_at with the sample's camera dimension set. */
inline float pixel_sample_ray(__constant const FcRenderParams* params, uint x, uint y, Sampler* sampler, float3* origin,
                              float3* dir) {
    return pixel_sample_ray_at(params, x, y, sampler_get4(sampler, FC_SET_CAMERA), origin, dir);
}

#endif
