/* Punctual lights: point, spot and directional (Hoffman 2010, "Physics and Math of
 * Shading"). A punctual light's colour c is Hoffman's c_light: the radiance of a white
 * Lambertian surface lit at normal incidence (at distance 1 for point and spot
 * lights), so the irradiance it gives at normal incidence is E = pi c (/ d^2), and the
 * reflected radiance is Lo = pi f(l, v) c (n.l) (/ d^2). A punctual light is a delta
 * distribution: it can only be reached by next-event estimation. */
#ifndef FACET_LIGHTS_PUNCTUAL_CL
#define FACET_LIGHTS_PUNCTUAL_CL

#include "kernels/shared/scene_layout.h"
#include "kernels/util/math.cl"

/* Spot falloff: 1 inside cos_inner, 0 outside cos_outer, a smoothstep between. */
inline float spot_falloff(__global const FcLight* l, float cos_axis) {
    if (cos_axis >= l->cos_inner) return 1.0f;
    if (cos_axis <= l->cos_outer) return 0.0f;
    float t = (cos_axis - l->cos_outer) / (l->cos_inner - l->cos_outer);
    return t * t * (3.0f - 2.0f * t);
}

/* Direction to the light (*wi), distance (*dist, INFINITY for directional lights)
 * and the irradiance it brings at normal incidence at p (pi c / d^2 and falloff). */
inline float3 punctual_light_irradiance(__global const FcLight* l, float3 p, float3* wi, float* dist) {
    float3 color = load3(l->color);
    if (l->type == FC_LIGHT_DIRECTIONAL) {
        *wi = -load3(l->e1);
        *dist = INFINITY;
        return FC_PI * color;
    }
    float3 to = load3(l->p0) - p;
    float d2 = dot(to, to);
    if (!(d2 > 0.0f)) {
        *dist = 0.0f;
        return (float3)(0.0f);
    }
    *dist = sqrt(d2);
    *wi = to / *dist;
    float falloff = (l->type == FC_LIGHT_SPOT) ? spot_falloff(l, dot(-*wi, load3(l->e1))) : 1.0f;
    return FC_PI * color * (falloff / d2);
}

#endif
