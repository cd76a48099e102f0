/* Fresnel reflectance.
 *
 * - Schlick's approximation from the reflectance at normal incidence F0
 *   (Schlick 1994): F = F0 + (1 - F0)(1 - cos)^5, and F0 from a real index of
 *   refraction, F0 = ((n - 1)/(n + 1))^2 (Hoffman 2010). With FC_MAT_SPECULAR_F90 the
 *   material's FC_FRESNEL_SCHLICK reaches F90 = `specular_f90` at grazing incidence,
 *   F = F0 + (F90 - F0)(1 - cos)^5 (KHR_materials_specular's fresnel_mix; F90 = 0 and
 *   F0 = 0: no specular reflection at all).
 * - The exact unpolarised Fresnel equations of a dielectric interface (relative
 *   index eta = n_transmitted / n_incident) and of a conductor with complex index
 *   eta + i k (per RGB channel; the real-arithmetic form of pbrt-v3, section 8.2.1).
 * All functions take the cosine between the direction and the (micro)normal; they
 * return values in [0, 1] for every input, including cosines outside [0, 1]. */
#ifndef FACET_BSDF_FRESNEL_CL
#define FACET_BSDF_FRESNEL_CL

#include "kernels/lanes/scalar.cl" /* the W = 1 forms of kernels/bsdf/fresnel_lanes.cl */
#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"

inline float pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

/* Schlick's form reaching f90 at grazing incidence (f90 = 1: fresnel_schlick). */
inline float3 fresnel_schlick_f90(float3 f0, float f90, float cos_theta) {
    return (float3)(fresnel_schlick_channel_l1(f0.x, f90, cos_theta), fresnel_schlick_channel_l1(f0.y, f90, cos_theta),
                    fresnel_schlick_channel_l1(f0.z, f90, cos_theta));
}

inline float3 fresnel_schlick(float3 f0, float cos_theta) { return fresnel_schlick_f90(f0, 1.0f, cos_theta); }

/* The material's Schlick reflectance at grazing incidence: `specular_f90` in [0, 1] where
 * FC_MAT_SPECULAR_F90 is set, else 1. */
inline float fresnel_f90(const FcMaterial* m) {
    return (m->flags & FC_MAT_SPECULAR_F90) ? clamp(m->specular_f90, 0.0f, 1.0f) : 1.0f;
}

inline float f0_from_ior(float n) {
    float r = (n - 1.0f) / (n + 1.0f);
    return r * r;
}

/* Exact dielectric reflectance for light arriving at cosine cos_i on the side the
 * normal points to (cos_i < 0: from the other side, where the relative index is
 * 1/eta). Total internal reflection gives 1. */
inline float fresnel_dielectric(float cos_i, float eta) { return fresnel_dielectric_l1(cos_i, eta); }

/* The dielectric transmittance 1 - F of a refraction whose two cosines are known,
 * cos_i on the incident side and cos_t on the far side (both > 0; eta = n_t / n_i):
 * 1 - rs^2 = 4 eta ci ct / (ci + eta ct)^2 and 1 - rp^2 = 4 eta ci ct / (eta ci + ct)^2,
 * without the cancellation of 1 - F or of cos_t = sqrt(1 - sin^2_t) near the critical
 * angle; symmetric under (ci, ct, eta) -> (ct, ci, 1 / eta), as reciprocity demands. */
inline float fresnel_dielectric_transmittance(float cos_i, float cos_t, float eta) {
    return fresnel_dielectric_transmittance_l1(cos_i, cos_t, eta);
}

/* Exact conductor reflectance, index eta + i k per channel, from the outside: the lane form
 * (fresnel_lanes.cl) with the three channels in the lanes of a float4. */
inline float3 fresnel_conductor(float cos_i, float3 eta, float3 k) {
    return fresnel_conductor_channel_l4((float4)(cos_i), (float4)(eta, 1.0f), (float4)(k, 0.0f)).xyz;
}

/* The material's Fresnel term at cosine cos_d between the direction and the
 * microfacet normal. */
inline float3 fresnel_eval(const FcMaterial* m, float cos_d) {
    switch (m->fresnel) {
        case FC_FRESNEL_SCHLICK:
            return fresnel_schlick_f90(load3p(m->specular), fresnel_f90(m), cos_d);
        case FC_FRESNEL_SCHLICK_IOR:
            return fresnel_schlick((float3)(f0_from_ior(m->ior)), cos_d);
        case FC_FRESNEL_DIELECTRIC:
            return (float3)(fresnel_dielectric(cos_d, m->ior));
        case FC_FRESNEL_CONDUCTOR:
            return fresnel_conductor(cos_d, load3p(m->eta), load3p(m->k));
        default:
            return (float3)(1.0f);
    }
}

/* F0 of the material's Fresnel term (the reflectance at normal incidence). */
inline float3 fresnel_f0(const FcMaterial* m) { return fresnel_eval(m, 1.0f); }

#endif
