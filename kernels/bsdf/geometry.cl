/* Shadowing-masking terms G(wo, wi, h) of the microfacet BRDF (FcMaterial.geometry).
 *
 *   FC_G_IMPLICIT          (n.l)(n.v): cancels the BRDF's denominator (Hoffman 2010)
 *   FC_G_COOK_TORRANCE     min(1, 2(n.h)(n.v)/(v.h), 2(n.h)(n.l)/(v.h)), the V-groove
 *                          model (Cook & Torrance 1982, eq. 9; Torrance & Sparrow 1967)
 *   FC_G_SMITH_SEPARABLE   G1(v) G1(l), G1 = 1 / (1 + Lambda) with the exact Lambda of
 *                          the NDF (Smith 1967; Heitz 2014, eq. 98)
 *   FC_G_SMITH_CORRELATED  1 / (1 + Lambda(v) + Lambda(l)), height-correlated (Heitz
 *                          2014, "Understanding the Masking-Shadowing Function in
 *                          Microfacet-Based BRDFs", JCGT 3(2), eq. 99)
 *   FC_G_SMITH_SCHLICK     Schlick 1994's approximation of Smith for Beckmann:
 *                          G1 = n.v / (n.v (1 - k) + k), k = alpha sqrt(2/pi)
 *   FC_G_SMITH_WALTER      Walter et al. 2007's rational approximation of Beckmann's
 *                          Smith G1 (eq. 27): a = 1/(alpha tan theta),
 *                          G1 = (3.535a + 2.181a^2)/(1 + 2.276a + 2.577a^2) for a < 1.6, else 1
 * Every Smith form includes the chi+ test that v and l see the front of the facet
 * (Walter 2007, eq. 23). The isotropic approximations use, for an anisotropic
 * roughness, the roughness projected on w's azimuth, alpha_w^2 =
 * (ax^2 x^2 + ay^2 y^2) / (x^2 + y^2) (Heitz 2014, section 5.4). Blinn-Phong uses its
 * equivalent Beckmann alpha (ndf.cl). Results lie in [0, 1]. */
#ifndef FACET_BSDF_GEOMETRY_CL
#define FACET_BSDF_GEOMETRY_CL

#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/ndf.cl"

/* Smith's exact monostatic masking of w by microfacets of normal h, 1 / (1 + Lambda(w)),
 * as w.z over the microsurface's projected area w.z (1 + Lambda(w)) (ndf_projected_area, a
 * sum of positive terms): the area is what the visible normals' density divides by, so a
 * BRDF evaluated with its density finds it once for both (microfacet.cl). */
inline float smith_G1(const FcMaterial* m, float3 w, float3 h) {
    if (!(w.z > 0.0f) || !(dot(w, h) > 0.0f)) return 0.0f;
    return w.z / ndf_projected_area(m, w);
}

/* alpha_w sqrt(x^2 + y^2) and z for the isotropic approximations. */
inline float projected_alpha_tan_numerator(const FcMaterial* m, float3 w) {
    float2 a = ndf_alpha(m);
    return sqrt(sqr(a.x * w.x) + sqr(a.y * w.y));
}

inline float schlick_G1(const FcMaterial* m, float3 w, float3 h) {
    if (!(w.z > 0.0f) || !(dot(w, h) > 0.0f)) return 0.0f;
    float r2 = w.x * w.x + w.y * w.y;
    float2 a = ndf_alpha(m);
    float alpha = (r2 > 0.0f) ? sqrt((sqr(a.x * w.x) + sqr(a.y * w.y)) / r2) : a.x;
    float k = alpha * 0.79788456080286535588f; /* sqrt(2/pi) */
    /* w.z (1 - k) + k >= min(1, k) > 0 for w.z in (0, 1]. */
    return w.z / (w.z * (1.0f - k) + k);
}

inline float walter_G1(const FcMaterial* m, float3 w, float3 h) {
    if (!(w.z > 0.0f) || !(dot(w, h) > 0.0f)) return 0.0f;
    float s = projected_alpha_tan_numerator(m, w);
    if (!(s * 1.6f > w.z)) return 1.0f; /* a = w.z / s >= 1.6 (also s = 0) */
    float a = w.z / s;
    return (3.535f * a + 2.181f * a * a) / (1.0f + 2.276f * a + 2.577f * a * a);
}

/* Whether G reads Smith's Lambda(wo) (as the projected area seen from wo). */
inline bool geometry_uses_area(const FcMaterial* m) {
    return m->geometry == FC_G_SMITH_SEPARABLE || m->geometry == FC_G_SMITH_CORRELATED;
}

/* G(wo, wi, h) for h the half vector of wo and wi, with area_o = ndf_projected_area(m, wo)
 * where geometry_uses_area (read nowhere else): the Smith forms' 1 + Lambda(w) is
 * area(w) / w.z. */
inline float geometry_G_area(const FcMaterial* m, float3 wo, float3 wi, float3 h, float area_o) {
    switch (m->geometry) {
        case FC_G_IMPLICIT:
            return fmax(wo.z, 0.0f) * fmax(wi.z, 0.0f);
        case FC_G_COOK_TORRANCE: {
            float vh = dot(wo, h);
            if (!(vh > 0.0f) || !(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
            float g = 2.0f * fmax(h.z, 0.0f) * fmin(wo.z, wi.z) / vh;
            return fmin(1.0f, g);
        }
        case FC_G_SMITH_SEPARABLE:
            if (!(wo.z > 0.0f) || !(dot(wo, h) > 0.0f)) return 0.0f;
            return wo.z / area_o * smith_G1(m, wi, h);
        case FC_G_SMITH_CORRELATED:
            if (!(wo.z > 0.0f) || !(dot(wo, h) > 0.0f) || !(wi.z > 0.0f) || !(dot(wi, h) > 0.0f)) return 0.0f;
            return 1.0f / (area_o / wo.z + ndf_projected_area(m, wi) / wi.z - 1.0f);
        case FC_G_SMITH_SCHLICK:
            return schlick_G1(m, wo, h) * schlick_G1(m, wi, h);
        case FC_G_SMITH_WALTER:
            return walter_G1(m, wo, h) * walter_G1(m, wi, h);
        default:
            return 0.0f;
    }
}

/* G(wo, wi, h) for h the half vector of wo and wi. */
inline float geometry_G(const FcMaterial* m, float3 wo, float3 wi, float3 h) {
    const bool area = geometry_uses_area(m) && wo.z > 0.0f;
    return geometry_G_area(m, wo, wi, h, area ? ndf_projected_area(m, wo) : 0.0f);
}

#endif
