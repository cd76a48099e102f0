/* Area lights: emitting triangles, picked in proportion to power and sampled
 * uniformly by area. Radiance L_e is the triangle's material's emission, which the
 * host copies into the light record with the unit normal and the material's
 * FC_MAT_TWO_SIDED_EMISSION (kernels/shared/scene_layout.h); a light emits on the side
 * cross(e1, e2) points to, or on both sides when its material has that flag. (Sampling
 * by solid angle, Arvo 1995, was tried and dropped: docs/lights.md.) */
#ifndef FACET_LIGHTS_AREA_CL
#define FACET_LIGHTS_AREA_CL

#include "kernels/shared/scene_layout.h"
#include "kernels/lanes/scalar.cl"
#include "kernels/util/math.cl"

/* Uniform point on a triangle (the square-root parameterisation, Turk 1990;
 * kernels/util/warp_lanes.cl): barycentrics of v1 and v2. */
inline float2 square_to_triangle(float2 u) { return square_to_triangle_l1(u.x, u.y); }

/* The unit normal of the emitting side, normalize(cross(e1, e2)), stored by the host. */
inline float3 area_light_normal(__global const FcLight* l) { return load3(l->n); }

/* A point uniformly distributed over the light's triangle. */
inline float3 area_light_point(__global const FcLight* l, float2 u) {
    float2 b = square_to_triangle(u);
    return load3(l->p0) + b.x * load3(l->e1) + b.y * load3(l->e2);
}

/* Radiance leaving the light toward direction w (pointing away from the light). */
inline float3 area_light_radiance(float3 emission, uint material_flags, float3 n, float3 w) {
    return area_light_lit_l1((material_flags & FC_MAT_TWO_SIDED_EMISSION) != 0u, dot(n, w)) ? emission : (float3)(0.0f);
}

/* Solid-angle density of reaching light `l` at distance `dist` with cosine `cos_light`
 * at the light, when lights are sampled by sample_area_light. */
inline float area_light_pdf_solid_angle(__global const FcLight* l, float dist, float cos_light) {
    return area_light_pdf_solid_angle_l1(l->pick_pdf, l->area, dist, cos_light); /* kernels/lights/area_lanes.cl */
}

#endif
