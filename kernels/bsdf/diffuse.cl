/* The diffuse lobe of a material (FcMaterial.diffuse_model). Every diffuse lobe is
 * sampled with cosine-weighted directions (lambert.cl). */
#ifndef FACET_BSDF_DIFFUSE_CL
#define FACET_BSDF_DIFFUSE_CL

#include "kernels/shared/material_layout.h"
#include "kernels/shared/feature_flags.h"
#include "kernels/bsdf/ashikhmin_shirley.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/bsdf/lambert.cl"
#include "kernels/bsdf/oren_nayar.cl"
#include "kernels/util/math.cl"

inline float3 material_diffuse(const FcMaterial* m) { return load3p(m->diffuse); }

inline float3 diffuse_eval(const FcMaterial* m, float3 wo, float3 wi) {
    switch (m->diffuse_model) {
        case FC_DIFFUSE_LAMBERT:
            return lambert_eval(material_diffuse(m), wo, wi);
        case FC_DIFFUSE_LAMBERT_1MF0:
            return lambert_eval(material_diffuse(m) * ((float3)(1.0f) - fresnel_f0(m)), wo, wi);
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

/* A cheap estimate of the lobe's albedo, used only to choose between lobes. */
inline float diffuse_weight(const FcMaterial* m) {
    if (m->diffuse_model == FC_DIFFUSE_NONE) return 0.0f;
    float w = luminance(material_diffuse(m));
    if (m->diffuse_model == FC_DIFFUSE_LAMBERT_1MF0 || m->diffuse_model == FC_DIFFUSE_ASHIKHMIN_SHIRLEY)
        w *= 1.0f - luminance(fresnel_f0(m));
    return fmax(w, 0.0f);
}

#endif
