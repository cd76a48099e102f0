/* The specular lobe of a material (FcMaterial.specular_model): dispatch to the
 * microfacet BRDF, the Blinn-Phong lobes or Ashikhmin-Shirley's. */
#ifndef FACET_BSDF_SPECULAR_CL
#define FACET_BSDF_SPECULAR_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/ashikhmin_shirley.cl"
#include "kernels/bsdf/blinn_phong.cl"
#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/microfacet.cl"
#include "kernels/util/math.cl"

inline float3 specular_eval(const FcMaterial* m, float3 wo, float3 wi) {
    switch (m->specular_model) {
#if FC_HAS_MICROFACET
        case FC_SPECULAR_MICROFACET:
            return microfacet_eval(m, wo, wi);
#endif
#if FC_HAS_BLINN_PHONG
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            return blinn_phong_eval(m, wo, wi);
#endif
#if FC_HAS_ASHIKHMIN_SHIRLEY
        case FC_SPECULAR_ASHIKHMIN_SHIRLEY:
            return ashikhmin_shirley_eval(m, wo, wi);
#endif
        default:
            return (float3)(0.0f);
    }
}

inline float specular_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    switch (m->specular_model) {
#if FC_HAS_MICROFACET
        case FC_SPECULAR_MICROFACET:
            return microfacet_pdf(m, wo, wi);
#endif
#if FC_HAS_BLINN_PHONG
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            return blinn_phong_pdf(m, wo, wi);
#endif
#if FC_HAS_ASHIKHMIN_SHIRLEY
        case FC_SPECULAR_ASHIKHMIN_SHIRLEY:
            return ashikhmin_shirley_pdf(m, wo, wi);
#endif
        default:
            return 0.0f;
    }
}

/* specular_eval's value and specular_pdf's in *pdf, the microfacet lobe's at once. */
inline float3 specular_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
#if FC_HAS_MICROFACET
    if (m->specular_model == FC_SPECULAR_MICROFACET) return microfacet_eval_pdf(m, wo, wi, pdf);
#endif
    *pdf = specular_pdf(m, wo, wi);
    return specular_eval(m, wo, wi);
}

/* Samples the lobe alone: s->f and s->pdf are the lobe's own. */
inline bool specular_sample(const FcMaterial* m, float3 wo, float2 u, BsdfSample* s) {
    switch (m->specular_model) {
#if FC_HAS_MICROFACET
        case FC_SPECULAR_MICROFACET:
            return microfacet_sample(m, wo, u, s);
#endif
#if FC_HAS_BLINN_PHONG
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            return blinn_phong_sample(m, wo, u, s);
#endif
#if FC_HAS_ASHIKHMIN_SHIRLEY
        case FC_SPECULAR_ASHIKHMIN_SHIRLEY:
            return ashikhmin_shirley_sample(m, wo, u, s);
#endif
        default:
            return false;
    }
}

/* A cheap estimate of the lobe's albedo seen from wo, used only to choose lobes. */
inline float specular_weight(const FcMaterial* m, float3 wo) {
    switch (m->specular_model) {
        case FC_SPECULAR_MICROFACET:
        case FC_SPECULAR_ASHIKHMIN_SHIRLEY:
            return fmax(luminance(fresnel_eval(m, wo.z)), 0.0f);
        case FC_SPECULAR_BLINN_PHONG:
        case FC_SPECULAR_BLINN_PHONG_NORMALIZED:
            return fmax(luminance(load3p(m->specular)), 0.0f);
        default:
            return 0.0f;
    }
}

/* Whether the specular lobe is a perfect mirror (a delta distribution). */
inline bool specular_is_delta(const FcMaterial* m) {
#if FC_HAS_MICROFACET
    return m->specular_model == FC_SPECULAR_MICROFACET && microfacet_is_mirror(m);
#else
    return false;
#endif
}

#endif
