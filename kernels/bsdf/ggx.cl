/* The GGX / Trowbridge-Reitz normal distribution, anisotropic (Trowbridge & Reitz 1975;
 * Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", EGSR;
 * anisotropic form from Heitz 2014, "Understanding the Masking-Shadowing Function in
 * Microfacet-Based BRDFs", JCGT 3(2), eq. 85).
 *
 * Parameters: roughness ax along the tangent (x), ay along the bitangent (y), each in
 * [1e-7, 1] with ax/ay within 1e4 (below FC_ALPHA_MIRROR the caller treats the lobe as
 * a mirror and never gets here). Directions are in the local frame (n = +z); every
 * function is written in "stretched" forms (x/ax, y/ay) that neither overflow nor
 * cancel for tiny alphas or grazing directions.
 *
 * The functions below that return a *_l1 call are the W = 1 forms of the lane-generic bodies
 * of kernels/bsdf/ggx_lanes.cl (kernels/lanes/lanes.cl), which the packet kernels run in lanes. */
#ifndef FACET_BSDF_GGX_CL
#define FACET_BSDF_GGX_CL

#include "kernels/lanes/scalar.cl" /* the W = 1 forms of kernels/bsdf/ggx_lanes.cl */
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

/* D(m) = 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) for a unit m with m.z > 0
 * (Heitz 2014, eq. 85, multiplied through by cos^4). */
inline float ggx_D(float ax, float ay, float3 m) { return ggx_D_l1(ax, ay, m); }

/* Smith's Lambda(w) = (-1 + sqrt(1 + alpha_w^2 tan^2 theta)) / 2 (Heitz 2014, eq. 86),
 * alpha_w^2 tan^2 theta = (ax^2 x^2 + ay^2 y^2) / z^2, rewritten without cancellation
 * as s2 / (2 |z| (|z| + sqrt(z^2 + s2))). Infinite at z = 0 (full masking). */
inline float ggx_lambda(float ax, float ay, float3 w) { return ggx_lambda_l1(ax, ay, w); }

/* A normal drawn from D(m) cos(theta_m): the slope distribution of GGX is a stretched
 * isotropic one with radial CDF r^2 / (1 + r^2) (Walter 2007, eqs. 35-36), so with
 * r^2 = u / (1 - u) the unnormalised normal (-ax r cos phi, -ay r sin phi, 1) scaled
 * by sqrt(1 - u) needs no division. */
inline float3 ggx_sample_all(float ax, float ay, float2 u) {
    float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
    float r = sqrt(u.x);
    float3 m = (float3)(ax * r * sc.y, ay * r * sc.x, sqrt(1.0f - u.x));
    return normalize_or(m, (float3)(0.0f, 0.0f, 1.0f));
}

inline float ggx_pdf_all(float ax, float ay, float3 m) { return ggx_D(ax, ay, m) * fmax(m.z, 0.0f); }

/* A normal drawn from the distribution of visible normals seen from wo,
 * D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z (Heitz 2018, "Sampling the GGX Distribution
 * of Visible Normals", JCGT 7(4), listing 1): stretch wo to the unit-roughness
 * configuration, sample the projected hemisphere, unstretch. */
inline float3 ggx_sample_visible(float ax, float ay, float3 wo, float2 u) {
    return ggx_sample_visible_l1(ax, ay, wo, u.x, u.y);
}

/* The projected area of the microsurface seen from w (w.z > 0), normalised by the
 * macro-surface's: w.z (1 + Lambda(w)) = (w.z + sqrt(w.z^2 + s2)) / 2. Never 0 for w != 0. */
inline float ggx_projected_area(float ax, float ay, float3 w) { return ggx_projected_area_l1(ax, ay, w); }

/* D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z = max(0, wo.m) D(m) / (wo.z (1 + Lambda(wo))). */
inline float ggx_pdf_visible(float ax, float ay, float3 wo, float3 m) { return ggx_pdf_visible_l1(ax, ay, wo, m); }

/* The spherical-cap visible-normal samplers, in the hemisphere configuration of
 * Heitz 2018 (wo stretched to unit roughness, i = normalize(ax wo.x, ay wo.y, wo.z)):
 * a visible normal is i + o, o uniform on the part of the unit sphere with o.z >= -b,
 * unstretched (Dupuy & Benyoub 2023, "Sound and Robust Sampling of the GGX Distribution
 * of Visible Normals", with b = i.z: the same distribution as Heitz 2018). Eto &
 * Tokuyoshi 2023 ("Bounded VNDF Sampling for Smith-GGX Reflections", SIGGRAPH Asia
 * technical communications, eqs. 5-8) shrink the cap to b = k i.z,
 *     k = (1 - a^2) s^2 / (s^2 + a^2 wo.z^2),  s = 1 + |wo.xy|,  a = min(ax, ay, 1),
 * a conservative bound that drops most of the normals whose reflection of wo goes below
 * the horizon (all of them at normal incidence and at alpha = 1). u.x picks the height
 * of o, u.y its azimuth. */
inline float ggx_bounded_k(float ax, float ay, float3 wo) {
    float a = clamp(fmin(ax, ay), 0.0f, 1.0f);
    float s = 1.0f + sqrt(wo.x * wo.x + wo.y * wo.y);
    float a2 = a * a, s2 = s * s;
    return (1.0f - a2) * s2 / (s2 + a2 * wo.z * wo.z);
}

inline float3 ggx_sample_cap(float ax, float ay, float3 wo, float2 u, float k) {
    float3 i = normalize((float3)(ax * wo.x, ay * wo.y, wo.z));
    float b = k * i.z;
    float z = (1.0f - u.x) * (1.0f + b) - b;
    float sin_t = safe_sqrt(1.0f - z * z);
    float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
    float3 h = i + (float3)(sin_t * sc.y, sin_t * sc.x, z);
    return normalize_or((float3)(ax * h.x, ay * h.y, fmax(h.z, 0.0f)), (float3)(0.0f, 0.0f, 1.0f));
}

inline float3 ggx_sample_visible_cap(float ax, float ay, float3 wo, float2 u) {
    return ggx_sample_cap(ax, ay, wo, u, 1.0f);
}

inline float3 ggx_sample_bounded(float ax, float ay, float3 wo, float2 u) {
    return ggx_sample_cap(ax, ay, wo, u, ggx_bounded_k(ax, ay, wo));
}

/* The density of the reflected direction of a bounded sample whose normal is m (Eto &
 * Tokuyoshi 2023, eq. 8 times the reflection's Jacobian): D(m) / (2 (k wo.z + t)),
 * t = |(ax wo.x, ay wo.y, wo.z)|; k = 1 gives Heitz's D / (4 wo.z (1 + Lambda(wo))). */
inline float ggx_reflection_pdf_bounded(float ax, float ay, float3 wo, float3 m) {
    float t = sqrt(sqr(ax * wo.x) + sqr(ay * wo.y) + wo.z * wo.z);
    return ggx_D(ax, ay, m) / (2.0f * (ggx_bounded_k(ax, ay, wo) * wo.z + t));
}

/* The density of the bounded sampler's normal m: 4 (wo.m) times the above, for m
 * inside the cap (the reflection of the stretched wo about the stretched m has
 * z >= -k i.z), else 0. */
inline float ggx_pdf_bounded(float ax, float ay, float3 wo, float3 m) {
    float wm = dot(wo, m);
    if (!(wo.z > 0.0f) || !(wm > 0.0f)) return 0.0f;
    float3 i = normalize((float3)(ax * wo.x, ay * wo.y, wo.z));
    float3 h = normalize_or((float3)(m.x / ax, m.y / ay, m.z), (float3)(0.0f, 0.0f, 1.0f));
    float oz = 2.0f * dot(i, h) * h.z - i.z;
    if (oz < -ggx_bounded_k(ax, ay, wo) * i.z) return 0.0f;
    return 4.0f * wm * ggx_reflection_pdf_bounded(ax, ay, wo, m);
}

#endif
