/* The result of sampling a BSDF lobe. Local shading frame (n = +z); wo and wi point
 * away from the surface. For a non-delta sample, f and pdf are exactly what the
 * lobe's eval and pdf return for wi, and weight = f cos(theta_i) / pdf. For a delta
 * lobe (a perfect mirror), f and pdf are meaningless (pdf = INFINITY) and weight
 * carries the whole throughput factor. Only the dielectric (dielectric.cl) returns wi
 * below the surface (wi.z < 0, a refraction). */
#ifndef FACET_BSDF_BSDF_SAMPLE_CL
#define FACET_BSDF_BSDF_SAMPLE_CL

#include "kernels/util/math.cl"

typedef struct {
    float3 wi;
    float3 f;
    float pdf;
    float3 weight;
    int delta;
} BsdfSample;

/* wo reflected about the unit (micro)normal h. False when wo does not see h's front
 * or the reflection leaves at or below the surface. */
inline bool reflect_about(float3 wo, float3 h, float3* wi) {
    float wo_h = dot(wo, h);
    if (!(wo_h > 0.0f)) return false;
    *wi = normalize_or(2.0f * wo_h * h - wo, (float3)(0.0f));
    return wi->z > 0.0f;
}

/* Completes a non-delta sample from the value f and density pdf of its direction
 * s->wi: weight = f |cos| / pdf (|cos|: refracted directions lie below the surface).
 * False for a zero or non-finite density or weight. */
inline bool finish_sample(BsdfSample* s, float3 f, float pdf) {
    s->f = f;
    s->pdf = pdf;
    if (!(pdf > 0.0f) || !isfinite(pdf)) return false;
    s->weight = f * (fabs(s->wi.z) / pdf);
    return all_finite(s->weight);
}

#endif
