/* Oren-Nayar diffuse reflection from a surface of Lambertian V-cavities (Oren &
 * Nayar 1994, "Generalization of Lambert's Reflectance Model", the qualitative
 * model without interreflections), in the form of Chmelik & Cejka's lecture (docs/brdf.md):
 *
 *   f = rho/pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta))
 *   A = 1 - 0.5 s^2 / (s^2 + 0.57),  B = 0.45 s^2 / (s^2 + 0.09)
 *   alpha = max(theta_i, theta_o),   beta = min(theta_i, theta_o)
 *
 * Parameters: rho = FcMaterial.diffuse (albedo, [0, 1]), s = FcMaterial.sigma,
 * the standard deviation of the facet slope angle in radians ([0, ~1]; 0 is
 * Lambert). The paper's qualitative model prints 0.33 in A; 0.57 (the lecture's) is
 * the common variant that partly stands in for the dropped interreflection term.
 * docs/brdf.md has the mapping from the lecture's I_diff and the energy table.
 *
 * Robust form: for unit vectors sin(alpha) sin(beta) = sin(theta_i) sin(theta_o)
 * and cos(phi) sin(theta_i) sin(theta_o) = wi.x wo.x + wi.y wo.y, so
 *   max(0, cos phi) sin(alpha) tan(beta) = max(0, wi.xy . wo.xy) / max(cos_i, cos_o),
 * which needs no normalisation of the projected vectors (0 at normal incidence,
 * where phi is undefined) and no tan(pi/2). The result is symmetric in wo and wi. */
#ifndef FACET_BSDF_OREN_NAYAR_CL
#define FACET_BSDF_OREN_NAYAR_CL

#include "kernels/shared/material_layout.h"
#include "kernels/util/math.cl"

/* Below this the larger cosine is clamped: both directions are then within 1e-7 rad
 * of the horizon, and f stays finite (f cos(theta_i) is bounded by rho/pi (A + B)). */
#define FC_OREN_NAYAR_MIN_COS 1e-7f

inline float3 oren_nayar_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    float3 rho = fmax(load3p(m->diffuse), (float3)(0.0f));
    /* sigma: NaN or negative -> Lambert */
    float sigma = (m->sigma > 0.0f) ? fmin(m->sigma, 1e6f) : 0.0f;
    float s2 = sigma * sigma;
    float a = 1.0f - 0.5f * s2 / (s2 + 0.57f);
    float b = 0.45f * s2 / (s2 + 0.09f);
    /* max(0, cos phi) sin(alpha) tan(beta) */
    float proj = fmax(wo.x * wi.x + wo.y * wi.y, 0.0f);
    float cos_max = fmax(fmax(wo.z, wi.z), FC_OREN_NAYAR_MIN_COS);
    float c = proj / cos_max;
    return rho * (FC_INV_PI * (a + b * c));
}

#endif
