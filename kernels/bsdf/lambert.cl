/* Lambertian diffuse reflection, f = albedo / pi, and the cosine-weighted sampling
 * every diffuse lobe uses (Malley's method on the concentric disk, Shirley & Chiu
 * 1997). Local frame, n = +z; wo and wi point away from the surface. */
#ifndef FACET_BSDF_LAMBERT_CL
#define FACET_BSDF_LAMBERT_CL

#include "kernels/util/math.cl"
#include "kernels/util/warp.cl"

inline float3 lambert_eval(float3 albedo, float3 wo, float3 wi) {
    return (wo.z > 0.0f && wi.z > 0.0f) ? albedo * FC_INV_PI : (float3)(0.0f);
}

/* Cosine-weighted sampling: kernels/util/warp_lanes.cl. */
inline float cosine_hemisphere_pdf(float3 wo, float3 wi) { return cosine_hemisphere_pdf_l1(wo.z, wi.z); }

/* A cosine-distributed direction on the upper hemisphere; z may be 0 on the rim. */
inline float3 square_to_cosine_hemisphere(float2 u) { return square_to_cosine_hemisphere_l1(u.x, u.y); }

#endif
