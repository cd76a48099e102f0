/* Area lights: emitting triangles, picked in proportion to power and sampled
 * uniformly by area. Radiance L_e comes from the triangle's material; a light
 * emits on the side cross(e1, e2) points to, or on both sides when its material
 * has FC_MAT_TWO_SIDED_EMISSION. */
#ifndef FACET_LIGHTS_AREA_CL
#define FACET_LIGHTS_AREA_CL

#include "../shared/scene.h"
#include "../util/math.cl"

typedef struct {
    float3 p;       /* point on the light */
    float3 n;       /* unit normal of the emitting side */
    float pdf_area; /* probability density per unit area, light choice included */
    int light;      /* index in the light array */
} LightSample;

/* Picks a light with probability pick_pdf by binary search of the cdf
 * (light_count + 1 entries, cdf[0] = 0, cdf[light_count] = 1). */
inline int pick_light(__global const float* cdf, uint light_count, float u) {
    uint lo = 0, hi = light_count;   /* invariant: cdf[lo] <= u < cdf[hi] */
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return (int)lo;
}

/* Uniform point on a triangle (the square-root parameterisation, Turk 1990):
 * barycentrics of v1 and v2. */
inline float2 square_to_triangle(float2 u) {
    float su = sqrt(u.x);
    return (float2)(su * (1.0f - u.y), su * u.y);
}

inline float3 area_light_normal(__global const FcLight* l) {
    return normalize_or(cross(load3(l->e1), load3(l->e2)), (float3)(0.0f, 0.0f, 1.0f));
}

inline LightSample sample_area_light(__global const FcLight* lights, __global const float* cdf,
                                     uint light_count, float u_pick, float2 u_point) {
    LightSample s;
    s.light = pick_light(cdf, light_count, u_pick);
    __global const FcLight* l = &lights[s.light];
    float2 b = square_to_triangle(u_point);
    s.p = load3(l->p0) + b.x * load3(l->e1) + b.y * load3(l->e2);
    s.n = area_light_normal(l);
    s.pdf_area = l->pick_pdf / l->area;
    return s;
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

#endif
