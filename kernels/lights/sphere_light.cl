/* Sphere lights: emitting analytic spheres (FC_LIGHT_SPHERE; kernels/shared/scene_layout.h
 * lists the fields). Seen from outside, the visible cap is sampled uniformly by solid angle
 * within the cone the sphere subtends (pbrt-v4's Sphere::Sample with a reference point,
 * section 6.2.4): a direction in the cone, then the point where it meets the sphere,
 * found from the angle alpha at the centre rather than by intersecting (which loses
 * precision at the silhouette). For cones narrower than 1.5 degrees, 1 - cos(theta_max) is
 * taken as sin^2(theta_max) / 2 (it would round to 0). From inside (and on the surface), the
 * whole sphere is visible and it is sampled uniformly by area. */
#ifndef FACET_LIGHTS_SPHERE_LIGHT_CL
#define FACET_LIGHTS_SPHERE_LIGHT_CL

#include "kernels/shared/scene_layout.h"
#include "kernels/util/frame.cl"
#include "kernels/util/math.cl"

/* sin^2 of 1.5 degrees: below it, the cone's 1 - cos is taken from the sine. */
#define FC_SPHERE_SMALL_CONE_SIN2 0.00068523f

/* Whether a point at squared distance dc2 from the centre is sampled by area, as from inside:
 * within r^2 (1 + 1e-3), so that a point on the sphere itself (a shading point of an inward
 * enclosure), which rounding puts on either side, never gets the degenerate cone of a point
 * on the surface. Area sampling stays unbiased just outside: the back it samples is hidden. */
inline bool sphere_light_by_area(float dc2, float r) { return dc2 <= r * r * (1.0f + 1e-3f); }

/* 1 - cos(theta_max) of the cone subtending radius r at squared distance dc2 > r^2. */
inline float sphere_cone_one_minus_cos(float r, float dc2) {
    const float sin2_max = r * r / dc2;
    return sin2_max < FC_SPHERE_SMALL_CONE_SIN2 ? 0.5f * sin2_max : 1.0f - safe_sqrt(1.0f - sin2_max);
}

/* Uniform direction on the unit sphere. */
inline float3 square_to_sphere(float2 u) {
    const float z = 1.0f - 2.0f * u.x;
    const float s = safe_sqrt(1.0f - z * z);
    const float phi = 2.0f * FC_PI * u.y;
    return (float3)(s * cos(phi), s * sin(phi), z);
}

/* A point on sphere light `l` seen from p: the point, the normal on its emitting side (for a
 * light emitting outward, the outward one) and the solid-angle density (without the pick). */
inline bool sphere_light_sample(__global const FcLight* l, float3 p, float2 u, float3* point, float3* normal,
                                float* pdf) {
    const float3 c = load3(l->p0);
    const float r = l->e1[0], orient = l->e1[1];
    const float3 pc = c - p;
    const float dc2 = dot(pc, pc);
    float3 n;
    if (sphere_light_by_area(dc2, r)) {
        /* Inside: uniform by area, converted to solid angle. */
        n = square_to_sphere(u);
        *point = c + r * n;
        const float3 w = *point - p;
        const float d2 = dot(w, w);
        const float cos_l = fabs(dot(n, w)) / sqrt(d2);
        if (!(d2 > 0.0f) || !(cos_l > 0.0f)) return false;
        *pdf = d2 / (cos_l * l->area);
    } else {
        /* Outside: uniform in the cone, then the point at angle alpha from the centre. */
        const float dc = sqrt(dc2);
        const float sin_max = r / dc, sin2_max = sin_max * sin_max;
        float cos_t, sin2_t;
        if (sin2_max < FC_SPHERE_SMALL_CONE_SIN2) {
            sin2_t = sin2_max * u.x;
            cos_t = sqrt(1.0f - sin2_t);
        } else {
            const float cos_max = safe_sqrt(1.0f - sin2_max);
            cos_t = (cos_max - 1.0f) * u.x + 1.0f;
            sin2_t = 1.0f - cos_t * cos_t;
        }
        const float cos_a = sin2_t / sin_max + cos_t * safe_sqrt(1.0f - sin2_t / sin2_max);
        const float sin_a = safe_sqrt(1.0f - cos_a * cos_a);
        const float phi = 2.0f * FC_PI * u.y;
        const Frame f = frame_from_normal(pc / dc);
        n = -frame_to_world(&f, (float3)(sin_a * cos(phi), sin_a * sin(phi), cos_a));
        *point = c + r * n;
        *pdf = 1.0f / (2.0f * FC_PI * sphere_cone_one_minus_cos(r, dc2));
    }
    *normal = orient * n;
    return true;
}

/* The density sphere_light_sample gives to the point a ray from o met at distance t with
 * cosine cos_light at the sphere. */
inline float sphere_light_pdf(__global const FcLight* l, float3 o, float t, float cos_light) {
    const float3 pc = load3(l->p0) - o;
    const float dc2 = dot(pc, pc), r = l->e1[0];
    if (sphere_light_by_area(dc2, r)) {
        const float c = fabs(cos_light);
        return c > 0.0f ? t * t / (c * l->area) : 0.0f;
    }
    return 1.0f / (2.0f * FC_PI * sphere_cone_one_minus_cos(r, dc2));
}

#endif
