/* Sampling a triangle by the solid angle it subtends (Arvo, "Stratified Sampling of
 * Spherical Triangles", SIGGRAPH 1995), as pbrt-v4 samples triangle lights: the
 * direction is uniform over the spherical triangle, so the light sample's density is
 * 1 / (solid angle) and carries none of area sampling's 1/r^2 and cosine variation,
 * which dominates the noise near a light.
 *
 * The spherical triangle has unit vertices a, b, c (the triangle's corners as seen
 * from the shading point). Its area is its solid angle; a uniform point is found by
 * choosing the sub-triangle (a, b, c') of area u0 * area, which fixes c' on the arc
 * from a to c (Arvo's eq. for cos of the arc length), then a point on the arc from b
 * to c' with cos(theta) linear in u1. */
#ifndef FACET_LIGHTS_SPHERICAL_TRIANGLE_CL
#define FACET_LIGHTS_SPHERICAL_TRIANGLE_CL

#include "kernels/util/math.cl"

/* Solid angles outside this range are sampled by area instead. Below it the float
 * construction loses uniformity on thin, grazing triangles (at 3.3e-4 sr, pbrt-v4's
 * lower limit being 3e-4, a grazing view failed tests/area_light_test.cpp's
 * chi-square), while area sampling of a light that small is nearly as good: its 1/r^2
 * and cosine hardly vary over it. Above the upper limit the shading point is almost
 * on the triangle (pbrt-v4's limit). */
#define FC_SPHERICAL_SAMPLE_MIN 1e-2f
#define FC_SPHERICAL_SAMPLE_MAX 6.22f

/* The angle between unit vectors, accurate near 0 and pi (no acos of a dot). */
inline float angle_between(float3 u, float3 v) {
    if (dot(u, v) < 0.0f) return M_PI_F - 2.0f * asin(fmin(length(u + v) * 0.5f, 1.0f));
    return 2.0f * asin(fmin(length(v - u) * 0.5f, 1.0f));
}

/* The solid angle of the triangle (v0, v1, v2) seen from p (Van Oosterom and
 * Strackee, "The Solid Angle of a Plane Triangle", IEEE Trans. Biomed. Eng. 1983). */
inline float triangle_solid_angle(float3 p, float3 v0, float3 v1, float3 v2) {
    float3 a = normalize_or(v0 - p, (float3)(0.0f)), b = normalize_or(v1 - p, (float3)(0.0f)),
           c = normalize_or(v2 - p, (float3)(0.0f));
    float det = fabs(dot(a, cross(b, c)));
    float denom = 1.0f + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0f * atan2(det, denom);
}

/* The part of v orthogonal to the unit vector w, normalised. */
inline float3 orthogonal_to(float3 v, float3 w) { return normalize_or(v - dot(v, w) * w, (float3)(0.0f)); }

/* A direction uniformly distributed over the spherical triangle (a, b, c). False when
 * the triangle is degenerate. */
inline bool sample_spherical_triangle(float3 a, float3 b, float3 c, float2 u, float3* w) {
    float3 n_ab = normalize_or(cross(a, b), (float3)(0.0f));
    float3 n_bc = normalize_or(cross(b, c), (float3)(0.0f));
    float3 n_ca = normalize_or(cross(c, a), (float3)(0.0f));
    if (is_black(n_ab) || is_black(n_bc) || is_black(n_ca)) return false;
    /* The interior angles at a, b and c; their sum minus pi is the area. */
    float alpha = angle_between(n_ab, -n_ca);
    float beta = angle_between(n_bc, -n_ab);
    float gamma = angle_between(n_ca, -n_bc);
    float area_pi = alpha + beta + gamma;
    if (!(area_pi > M_PI_F)) return false;
    /* The sub-triangle of area u0 * area: the arc length b' from a to c'. */
    float sub_pi = M_PI_F + u.x * (area_pi - M_PI_F);
    float cos_alpha = cos(alpha), sin_alpha = sin(alpha);
    float sin_sub = sin(sub_pi), cos_sub = cos(sub_pi);
    float sin_phi = sin_sub * cos_alpha - cos_sub * sin_alpha;
    float cos_phi = cos_sub * cos_alpha + sin_sub * sin_alpha;
    float k1 = cos_phi + cos_alpha;
    float k2 = sin_phi - sin_alpha * dot(a, b);
    float cos_bp = (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha) / ((k2 * sin_phi + k1 * cos_phi) * sin_alpha);
    cos_bp = clamp(cos_bp, -1.0f, 1.0f);
    float sin_bp = safe_sqrt(1.0f - cos_bp * cos_bp);
    float3 cp = cos_bp * a + sin_bp * orthogonal_to(c, a);
    /* A point on the arc from b to c' with cos(theta) uniform. */
    float cos_theta = 1.0f - u.y * (1.0f - dot(cp, b));
    float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    *w = normalize_or(cos_theta * b + sin_theta * orthogonal_to(cp, b), (float3)(0.0f));
    return !is_black(*w) && all_finite(*w);
}

#endif
