/* The diffuse lobe of a material (FcMaterial.diffuse_model). Every diffuse lobe but
 * EON (eon.cl, its own CLTC sampling) is sampled with cosine-weighted directions
 * (lambert.cl).
 *
 * Lambert x (1 - F0) under an energy-compensated microfacet lobe (FC_MAT_ENERGY_COMPENSATION)
 * is weighted by (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (1 - E_s,avg) instead, E_s the specular
 * lobe's albedo (energy_compensation.cl), so that the pair conserves energy exactly. */
#ifndef FACET_BSDF_DIFFUSE_CL
#define FACET_BSDF_DIFFUSE_CL

#include "kernels/shared/material_layout.h"
#include "kernels/shared/feature_flags.h"
#include "kernels/bsdf/ashikhmin_shirley.cl"
#include "kernels/bsdf/energy_compensation.cl"
#include "kernels/bsdf/eon.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/lambert.cl"
#include "kernels/bsdf/oren_nayar.cl"
#include "kernels/util/math.cl"

inline float3 material_diffuse(const FcMaterial* m) { return load3p(m->diffuse); }

/* Whether the Lambert x (1 - F0) base is coupled to a compensated specular lobe, its
 * mirror limit included (there 1 - F0 and the mirror's F(mu) together gain up to 37% at
 * 80 degrees). */
inline bool diffuse_coupled(const FcMaterial* m) {
    return m->diffuse_model == FC_DIFFUSE_LAMBERT_1MF0 && m->specular_model == FC_SPECULAR_MICROFACET && ec_enabled(m);
}

inline float3 diffuse_eval(const FcMaterial* m, float3 wo, float3 wi) {
    switch (m->diffuse_model) {
        case FC_DIFFUSE_LAMBERT:
            return lambert_eval(material_diffuse(m), wo, wi);
        case FC_DIFFUSE_LAMBERT_1MF0:
            if (diffuse_coupled(m) && wo.z > 0.0f && wi.z > 0.0f)
                return lambert_eval(material_diffuse(m) * ec_diffuse_coupling(m, wo, wi), wo, wi);
            return lambert_eval(material_diffuse(m) * ((float3)(1.0f) - fresnel_f0(m)), wo, wi);
        case FC_DIFFUSE_EON:
            return eon_eval(m, wo, wi);
#if FC_HAS_OREN_NAYAR
        case FC_DIFFUSE_OREN_NAYAR:
            return oren_nayar_eval(m, wo, wi);
#endif
#if FC_HAS_ASHIKHMIN_SHIRLEY
        case FC_DIFFUSE_ASHIKHMIN_SHIRLEY:
            return ashikhmin_shirley_diffuse_eval(m, wo, wi);
#endif
        default:
            return (float3)(0.0f);
    }
}

/* The density with which diffuse_sample draws wi. */
inline float diffuse_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (m->diffuse_model == FC_DIFFUSE_EON) return eon_pdf(m, wo, wi);
    return cosine_hemisphere_pdf(wo, wi);
}

/* A direction for the diffuse lobe; false when none was made. */
inline bool diffuse_sample(const FcMaterial* m, float3 wo, float2 u, float3* wi) {
    if (m->diffuse_model == FC_DIFFUSE_EON) return eon_sample(m, wo, u, wi);
    *wi = square_to_cosine_hemisphere(u);
    return true;
}

/* A cheap estimate of the lobe's albedo, used only to choose between lobes. */
inline float diffuse_weight(const FcMaterial* m) {
    if (m->diffuse_model == FC_DIFFUSE_NONE) return 0.0f;
    float w = luminance(material_diffuse(m));
    if (m->diffuse_model == FC_DIFFUSE_LAMBERT_1MF0 || m->diffuse_model == FC_DIFFUSE_ASHIKHMIN_SHIRLEY)
        w *= 1.0f - luminance(fresnel_f0(m));
    return fmax(w, 0.0f);
}

#endif
