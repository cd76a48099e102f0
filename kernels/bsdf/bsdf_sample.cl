/* The result of sampling a BSDF lobe. Local shading frame (n = +z); wo and wi point
 * away from the surface. For a non-delta sample, f and pdf are exactly what the
 * lobe's eval and pdf return for wi, and weight = f cos(theta_i) / pdf. For a delta
 * lobe (a perfect mirror), f and pdf are meaningless (pdf = INFINITY) and weight
 * carries the whole throughput factor. */
#ifndef FACET_BSDF_BSDF_SAMPLE_CL
#define FACET_BSDF_BSDF_SAMPLE_CL

typedef struct {
    float3 wi;
    float3 f;
    float pdf;
    float3 weight;
    int delta;
} BsdfSample;

#endif
