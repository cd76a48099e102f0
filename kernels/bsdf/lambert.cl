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

inline float cosine_hemisphere_pdf(float3 wo, float3 wi) {
    return (wo.z > 0.0f && wi.z > 0.0f) ? wi.z * FC_INV_PI : 0.0f;
}

/* A cosine-distributed direction on the upper hemisphere; z may be 0 on the rim. */
inline float3 square_to_cosine_hemisphere(float2 u) {
    float2 d = square_to_disk_concentric(u);
    float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
    return (float3)(d.x, d.y, z);
}

#endif
