/* Refraction at an interface (Snell-Descartes) and the relative index seen from a
 * direction. Conventions (docs/conventions.md, docs/brdf.md "Dielectrics"): eta =
 * n_below / n_above, the index on the -z side of the (micro)normal over the index on
 * its +z side; directions point away from the surface. */
#ifndef FACET_BSDF_REFRACTION_CL
#define FACET_BSDF_REFRACTION_CL

#include "kernels/util/math.cl"

/* The relative index n_far / n_near for a direction on the side of cos_w:
 * eta above the surface (cos_w > 0), 1 / eta below it. */
inline float relative_eta(float eta, float cos_w) { return cos_w > 0.0f ? eta : 1.0f / eta; }

/* The direction refracted from w through the interface of unit normal h and relative
 * index eta (n on h's back side / n on h's front side), pointing away on the far
 * side: wt = -w / e + (cos_i / e - cos_t) h with e the index ratio seen from w
 * (Snell-Descartes, n_i sin_i = n_t sin_t; the vector form of pbrt-v4's Refract).
 * False on total internal reflection (sin_t >= 1). */
inline bool refract_about(float3 w, float3 h, float eta, float3* wt) {
    float cos_i = dot(w, h);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
        h = -h;
    }
    float sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (!(sin2_t < 1.0f)) return false;
    float cos_t = sqrt(1.0f - sin2_t);
    *wt = normalize_or(-w / eta + (cos_i / eta - cos_t) * h, -h);
    return true;
}

#endif
