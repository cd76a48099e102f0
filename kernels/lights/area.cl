/* Area lights: emitting triangles, picked in proportion to power and sampled by the
 * solid angle they subtend (spherical_triangle.cl), or uniformly by area where that
 * angle is too small or too large for the spherical construction. Radiance L_e comes from the triangle's material; a
 * light emits on the side cross(e1, e2) points to, or on both sides when its material has FC_MAT_TWO_SIDED_EMISSION. */
#ifndef FACET_LIGHTS_AREA_CL
#define FACET_LIGHTS_AREA_CL

#include "kernels/shared/scene_layout.h"
#include "kernels/lights/spherical_triangle.cl"
#include "kernels/util/math.cl"

/* Uniform point on a triangle (the square-root parameterisation, Turk 1990):
 * barycentrics of v1 and v2. */
inline float2 square_to_triangle(float2 u) {
    float su = sqrt(u.x);
    return (float2)(su * (1.0f - u.y), su * u.y);
}

inline float3 area_light_normal(__global const FcLight* l) {
    return normalize_scaled_or(cross(load3(l->e1), load3(l->e2)), (float3)(0.0f, 0.0f, 1.0f));
}

/* A point uniformly distributed over the light's triangle. */
inline float3 area_light_point(__global const FcLight* l, float2 u) {
    float2 b = square_to_triangle(u);
    return load3(l->p0) + b.x * load3(l->e1) + b.y * load3(l->e2);
}

/* Radiance leaving the light toward direction w (pointing away from the light). */
inline float3 area_light_radiance(float3 emission, uint material_flags, float3 n, float3 w) {
    float c = dot(n, w);
    bool lit = (material_flags & FC_MAT_TWO_SIDED_EMISSION) ? (c != 0.0f) : (c > 0.0f);
    return lit ? emission : (float3)(0.0f);
}

/* Solid-angle density of reaching light `l` at distance `dist` with cosine `cos_light`
 * at the light, when lights are sampled by sample_area_light. */
inline float area_light_pdf_solid_angle(__global const FcLight* l, float dist, float cos_light) {
    float c = fabs(cos_light);
    return (c > 0.0f) ? l->pick_pdf / l->area * dist * dist / c : 0.0f;
}

/* The solid angle the light subtends at p when light sampling from p samples it by
 * solid angle, else 0 (then it samples by area). Both light sampling and the MIS weight
 * of a BSDF-sampled hit decide through this one function. */
inline float area_light_spherical_omega(__global const FcLight* l, float3 p) {
    float3 v0 = load3(l->p0);
    float omega = triangle_solid_angle(p, v0, v0 + load3(l->e1), v0 + load3(l->e2));
    return (omega >= FC_SPHERICAL_SAMPLE_MIN && omega <= FC_SPHERICAL_SAMPLE_MAX) ? omega : 0.0f;
}

/* Solid-angle density (pick included) with which light sampling from p reaches the
 * light's point at distance `dist`, where the light's cosine is `cos_light`. */
inline float area_light_pdf(__global const FcLight* l, float3 p, float dist, float cos_light) {
    float omega = area_light_spherical_omega(l, p);
    if (omega > 0.0f) return l->pick_pdf / omega;
    return area_light_pdf_solid_angle(l, dist, cos_light);
}

#endif
