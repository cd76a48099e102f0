/* The material's normal distribution (FcMaterial.ndf): D(m), Smith's Lambda(w), the
 * sampling of a microfacet normal and its density.
 *
 * - GGX and Beckmann use alpha_x, alpha_y (anisotropic); the normalised Blinn-Phong
 *   NDF uses exponent_x and, wherever a roughness is needed (its Smith Lambda, the
 *   isotropic G approximations, the mirror limit), the equivalent Beckmann roughness
 *   alpha = sqrt(2 / (e + 2)) (Walter 2007, eq. 33; blinn_phong_ndf.cl).
 * - Sampling (FcMaterial.sampling): FC_SAMPLE_VISIBLE draws m from the distribution of
 *   visible normals D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z (Heitz & d'Eon 2014;
 *   Heitz 2018 for GGX), FC_SAMPLE_ALL from D(m) cos(theta_m). For GGX,
 *   FC_SAMPLE_SPHERICAL_CAP draws the visible normals by spherical caps and
 *   FC_SAMPLE_BOUNDED from the bounded VNDF, for reflection only: the dielectric, which
 *   needs the normals of refraction too, takes spherical caps instead
 *   (ndf_sample_two_sided). Beckmann samples visible normals for all three, Blinn-Phong
 *   always D cos.
 * Every density is per unit solid angle of m. */
#ifndef FACET_BSDF_NDF_CL
#define FACET_BSDF_NDF_CL

#include "kernels/shared/feature_flags.h"
#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/beckmann.cl"
#include "kernels/bsdf/blinn_phong_ndf.cl"
#include "kernels/bsdf/ggx.cl"

/* The roughness along x and y: alpha_x/alpha_y, or Blinn-Phong's equivalent alpha. */
inline float2 ndf_alpha(const FcMaterial* m) {
    if (m->ndf == FC_NDF_BLINN_PHONG) return (float2)(bp_ndf_alpha(m->exponent_x));
    return (float2)(m->alpha_x, m->alpha_y);
}

inline float ndf_D(const FcMaterial* m, float3 h) {
    switch (m->ndf) {
        case FC_NDF_GGX:
            return ggx_D(m->alpha_x, m->alpha_y, h);
        case FC_NDF_BLINN_PHONG:
            return bp_ndf_D(m->exponent_x, h);
        default:
            return beckmann_D(m->alpha_x, m->alpha_y, h);
    }
}

/* Smith's Lambda(w); uses |w.z|, infinite at w.z = 0. */
inline float ndf_lambda(const FcMaterial* m, float3 w) {
    float2 a = ndf_alpha(m);
    if (m->ndf == FC_NDF_GGX) return ggx_lambda(a.x, a.y, w);
    return beckmann_lambda(a.x, a.y, w);
}

/* wo.z (1 + Lambda(wo)), the microsurface's projected area seen from wo (wo.z >= 0),
 * computed without cancellation (ggx.cl, beckmann.cl). */
inline float ndf_projected_area(const FcMaterial* m, float3 wo) {
    float2 a = ndf_alpha(m);
    if (m->ndf == FC_NDF_GGX) return ggx_projected_area(a.x, a.y, wo);
    return beckmann_projected_area(a.x, a.y, wo);
}

/* Whether the material samples visible normals (bounded ones included; never for
 * Blinn-Phong). */
inline bool ndf_samples_visible(const FcMaterial* m) {
    return m->sampling != FC_SAMPLE_ALL && m->ndf != FC_NDF_BLINN_PHONG;
}

/* Whether the material samples GGX's bounded visible normals (reflection only). */
inline bool ndf_samples_bounded(const FcMaterial* m) {
    return m->sampling == FC_SAMPLE_BOUNDED && m->ndf == FC_NDF_GGX;
}

/* A microfacet normal for the view direction wo (wo.z > 0), u uniform in [0, 1)^2;
 * `reflection_only` lets GGX use the bounded sampler. */
inline float3 ndf_sample_for(const FcMaterial* m, float3 wo, float2 u, bool reflection_only) {
    bool visible = ndf_samples_visible(m);
    switch (m->ndf) {
        case FC_NDF_GGX:
            if (!visible) return ggx_sample_all(m->alpha_x, m->alpha_y, u);
            if (m->sampling == FC_SAMPLE_BOUNDED && reflection_only)
                return ggx_sample_bounded(m->alpha_x, m->alpha_y, wo, u);
            if (m->sampling == FC_SAMPLE_VISIBLE) return ggx_sample_visible(m->alpha_x, m->alpha_y, wo, u);
            return ggx_sample_visible_cap(m->alpha_x, m->alpha_y, wo, u);
        case FC_NDF_BLINN_PHONG:
            return bp_ndf_sample(m->exponent_x, u);
        default:
#if FC_HAS_BECKMANN
            return visible ? beckmann_sample_visible(m->alpha_x, m->alpha_y, wo, u)
                           : beckmann_sample_all(m->alpha_x, m->alpha_y, u);
#else
            return (float3)(0.0f, 0.0f, 1.0f); /* no Beckmann material in this program */
#endif
    }
}

/* A normal for a reflection (the microfacet lobe), and for reflection or refraction (the
 * dielectric). */
inline float3 ndf_sample(const FcMaterial* m, float3 wo, float2 u) { return ndf_sample_for(m, wo, u, true); }
inline float3 ndf_sample_two_sided(const FcMaterial* m, float3 wo, float2 u) { return ndf_sample_for(m, wo, u, false); }

/* The density (per solid angle) with which ndf_sample produces the normal h. */
inline float ndf_pdf(const FcMaterial* m, float3 wo, float3 h) {
    bool visible = ndf_samples_visible(m);
    switch (m->ndf) {
        case FC_NDF_GGX:
            if (ndf_samples_bounded(m)) return ggx_pdf_bounded(m->alpha_x, m->alpha_y, wo, h);
            return visible ? ggx_pdf_visible(m->alpha_x, m->alpha_y, wo, h) : ggx_pdf_all(m->alpha_x, m->alpha_y, h);
        case FC_NDF_BLINN_PHONG:
            return bp_ndf_pdf(m->exponent_x, h);
        default:
#if FC_HAS_BECKMANN
            return visible ? beckmann_pdf_visible(m->alpha_x, m->alpha_y, wo, h)
                           : beckmann_pdf_all(m->alpha_x, m->alpha_y, h);
#else
            return 0.0f;
#endif
    }
}

/* The density of the reflection of wo about a visible normal h, ndf_pdf(h) / (4 wo.h),
 * with wo.h cancelled analytically: D(h) / (4 wo.z (1 + Lambda(wo))), from d = ndf_D(m, h)
 * and area_o = ndf_projected_area(m, wo); or the bounded sampler's (ggx.cl), which reads
 * neither. */
inline float ndf_reflection_pdf_visible_at(const FcMaterial* m, float3 wo, float3 h, float d, float area_o) {
    if (ndf_samples_bounded(m)) return ggx_reflection_pdf_bounded(m->alpha_x, m->alpha_y, wo, h);
    return d / (4.0f * area_o);
}

#endif
