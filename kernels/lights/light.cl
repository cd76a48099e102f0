/* Light selection and sampling for next-event estimation, over every light type:
 * area (area.cl), sphere (sphere_light.cl), point, spot and directional (punctual.cl) and the environment
 * (environment.cl). A light is picked with probability pick_pdf (in proportion to an
 * estimate of its power), then sampled. */
#ifndef FACET_LIGHTS_LIGHT_CL
#define FACET_LIGHTS_LIGHT_CL

#include "kernels/scene/scene_view.cl"
#include "kernels/lights/area.cl"
#include "kernels/lights/environment.cl"
#include "kernels/lights/punctual.cl"
#if FC_HAS_TEXTURES
#include "kernels/texture/material_textures.cl"
#endif
#include "kernels/lights/sphere_light.cl"
#if FC_HAS_ALPHA
#include "kernels/trace/alpha_test.cl"
#endif

typedef struct {
    float3 wi;    /* unit direction from the shading point to the light */
    float dist;   /* distance to the light; INFINITY for directional and environment */
    float3 li;    /* radiance arriving along wi; for delta lights the irradiance at normal incidence */
    float pdf;    /* solid-angle density, pick included; delta lights: the pick probability */
    int delta;    /* a punctual light: no MIS, no BSDF strategy can reach it */
    float3 point; /* area lights: the sampled point, and the light's normal (for the shadow ray) */
    float3 normal;
} LightSample;

/* Picks a light with probability pick_pdf from the cdf (light_count + 1 entries, cdf[0] = 0,
 * cdf[light_count] = 1): the light k with cdf[k] <= u < cdf[k + 1]. A few lights are counted,
 * the entries at or below u (the cdf rises, so that is k); more by binary search. Neither
 * branches on u (a branch on u mispredicts half the time, and LLVM made a select in the
 * search's loop a branch again, so its step is masked): the count's comparisons add up as
 * integers, and the search's loop runs the same ceil(log2(light_count)) times every call,
 * whatever u is. The packets run the same body in lanes. */
inline int pick_light(__global const float* cdf, uint light_count, float u) {
    return (int)pick_light_l1(cdf, light_count, u); /* kernels/lights/light_pick_lanes.cl */
}

/* Samples a light as seen from point p. Returns false when the sample carries nothing. */
inline bool sample_light(const SceneView* sc, float3 p, float u_pick, float2 u, LightSample* ls) {
    uint count = sc->params->light_count;
    if (count == 0u) return false;
    __global const FcLight* l = &sc->lights[pick_light(sc->light_cdf, count, u_pick)];
    ls->delta = 0;
    if (false) { /* each light type below is compiled only when the scene has it */
#if FC_HAS_AREA_LIGHTS
    } else if (l->type == FC_LIGHT_AREA_TRIANGLE) {
        ls->normal = area_light_normal(l);
        ls->point = area_light_point(l, u);
        float3 to = ls->point - p;
        float d2 = dot(to, to);
        if (!(d2 > 0.0f)) return false;
        ls->dist = sqrt(d2);
        ls->wi = to / ls->dist;
        ls->pdf = area_light_pdf_solid_angle(l, ls->dist, dot(ls->normal, ls->wi));
        ls->li = area_light_radiance(load3(l->color), l->flags, ls->normal, -ls->wi);
#if FC_HAS_TEXTURES
        ls->li *= emission_texture_at(sc, l->prim, sc->shading[l->prim].material, square_to_triangle(u));
#endif
#if FC_HAS_ALPHA
        ls->li *= alpha_light_coverage(sc, l->prim, square_to_triangle(u));
#endif
#endif
#if FC_HAS_AREA_LIGHTS && FC_HAS_SPHERES
    } else if (l->type == FC_LIGHT_SPHERE) {
        float3 point;
        float pdf;
        if (!sphere_light_sample(l, p, u, &point, &ls->normal, &pdf)) return false;
        float3 to = point - p;
        ls->dist = length(to);
        if (!(ls->dist > 0.0f)) return false;
        ls->wi = to / ls->dist;
        ls->pdf = pdf * l->pick_pdf;
        ls->li =
            area_light_radiance(load3(l->color), l->e1[2] > 0.0f ? FC_MAT_TWO_SIDED_EMISSION : 0u, ls->normal, -ls->wi);
        /* The shadow ray's end, pulled back by 1e-4 of the distance (pbrt's ShadowEpsilon):
         * the point's rounding error grows with the sphere's distance from the origin. */
        ls->point = point - 1e-4f * to;
#endif
#if FC_HAS_ENVIRONMENT
    } else if (l->type == FC_LIGHT_ENVIRONMENT) {
        float pdf;
        ls->li = env_sample(&sc->params->environment, sc->env_texels, sc->env_dist, u, &ls->wi, &pdf);
        ls->dist = INFINITY;
        ls->pdf = pdf * l->pick_pdf;
#endif
#if FC_HAS_PUNCTUAL_LIGHTS
    } else if (l->type == FC_LIGHT_POINT || l->type == FC_LIGHT_SPOT || l->type == FC_LIGHT_DIRECTIONAL) {
        ls->li = punctual_light_irradiance(l, p, &ls->wi, &ls->dist);
        ls->pdf = l->pick_pdf;
        ls->delta = 1;
#endif
    } else {
        return false;
    }
    return ls->pdf > 0.0f && isfinite(ls->pdf) && !is_black(ls->li) && all_finite(ls->li);
}

/* Density with which sample_light reaches the point of light `index` that a ray from o met
 * at distance t with cosine cos_light there (for MIS; pick included). */
inline float light_pdf_hit(const SceneView* sc, int index, float3 o, float t, float cos_light) {
    __global const FcLight* l = &sc->lights[index];
#if FC_HAS_SPHERES
    if (l->type == FC_LIGHT_SPHERE) return l->pick_pdf * sphere_light_pdf(l, o, t, cos_light);
#else
    (void)o;
#endif
    return area_light_pdf_solid_angle(l, t, cos_light);
}

/* The probability with which sample_light picks the environment (0: never); times
 * env_pdf, the density with which it reaches the environment along a direction (MIS). */
inline float environment_pick_pdf(const SceneView* sc) {
    int index = sc->params->environment_light;
    return index < 0 ? 0.0f : sc->lights[index].pick_pdf;
}

#endif
