/* The normalised Blinn-Phong normal distribution, D(m) = (e + 2) / (2 pi) cos^e(theta_m)
 * (Blinn 1977; normalised so that the projected area integrates to 1, Walter et al.
 * 2007, eq. 30), isotropic, exponent e = FcMaterial.exponent_x in [0, 2e14].
 *
 * - Sampling: D(m) cos(theta_m) exactly, cos(theta_m) = (1 - u)^(1 / (e + 2))
 *   (Walter 2007, eq. 31). Blinn-Phong has no visible-normal sampler here: with
 *   FC_SAMPLE_VISIBLE the all-normals sampler is used too (ndf.cl).
 * - Shadowing: Blinn-Phong has no closed-form Smith Lambda; the Beckmann Lambda at the
 *   equivalent roughness alpha = sqrt(2 / (e + 2)) stands in for it, the pairing
 *   Walter 2007 (section 5.2, eq. 33) recommends since both distributions then agree
 *   closely. This Smith G is therefore an approximation for this NDF.
 * cos^e is evaluated as exp(-e/2 log(1 + tan^2)) which, unlike pow(m.z, e), keeps its
 * precision for narrow lobes (e large, m.z within an ulp of 1). */
#ifndef FACET_BSDF_BLINN_PHONG_NDF_CL
#define FACET_BSDF_BLINN_PHONG_NDF_CL

#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

inline float bp_ndf_exponent(float e) { return fmax(e, 0.0f); }

/* Walter 2007, eq. 33: the Beckmann roughness matching exponent e. */
inline float bp_ndf_alpha(float e) { return sqrt(2.0f / (bp_ndf_exponent(e) + 2.0f)); }

inline float bp_ndf_D(float e, float3 m) {
    if (!(m.z > 0.0f)) return 0.0f;
    e = bp_ndf_exponent(e);
    float tan2 = (m.x * m.x + m.y * m.y) / (m.z * m.z);
    return (e + 2.0f) * (0.5f * FC_INV_PI) * exp(-0.5f * e * log1p(tan2));
}

/* cos(theta_m) = (1 - u)^(1/(e + 2)) through its logarithm L, so that
 * sin^2 = 1 - exp(2L) = -expm1(2L) has full precision near the pole. */
inline float3 bp_ndf_sample(float e, float2 u) {
    e = bp_ndf_exponent(e);
    float l = log(1.0f - u.x) / (e + 2.0f);
    float cos_t = exp(l);
    float sin_t = safe_sqrt(-expm1(2.0f * l));
    float2 sc = sincos_turns(u.y); /* phi = 2 pi u.y */
    return (float3)(sin_t * sc.y, sin_t * sc.x, cos_t);
}

inline float bp_ndf_pdf(float e, float3 m) { return bp_ndf_D(e, m) * fmax(m.z, 0.0f); }

#endif
