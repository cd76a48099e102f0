/* Refraction at an interface (Snell-Descartes) and the relative index seen from a
 * direction. Conventions (docs/conventions.md, docs/brdf.md "Dielectrics"): eta =
 * n_below / n_above, the index on the -z side of the (micro)normal over the index on
 * its +z side; directions point away from the surface. The lane form
 * (refraction_lanes.cl) is the formulas; these are its W = 1 calls. */
#ifndef FACET_BSDF_REFRACTION_CL
#define FACET_BSDF_REFRACTION_CL

#include "kernels/lanes/scalar.cl" /* the W = 1 forms of kernels/bsdf/refraction_lanes.cl */
#include "kernels/util/math.cl"

/* The relative index n_far / n_near for a direction on the side of cos_w:
 * eta above the surface (cos_w > 0), 1 / eta below it. */
inline float relative_eta(float eta, float cos_w) { return relative_eta_l1(eta, cos_w); }

/* The direction refracted from w through the interface of unit normal h and relative
 * index eta (n on h's back side / n on h's front side), pointing away on the far
 * side: wt = -w / e + (cos_i / e - cos_t) h with e the index ratio seen from w
 * (Snell-Descartes, n_i sin_i = n_t sin_t; the vector form of pbrt-v4's Refract).
 * False on total internal reflection (sin_t >= 1), *wt then left as it was. */
inline bool refract_about(float3 w, float3 h, float eta, float3* wt) {
    float3 t;
    if (!refract_about_l1(w, h, eta, &t)) return false;
    *wt = t;
    return true;
}

#endif
