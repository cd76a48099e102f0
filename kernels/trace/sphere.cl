/* Analytic spheres: the ray/sphere intersection, the traversal of the spheres' own binary
 * tree (kernels/shared/sphere_layout.h, traversed by small_tree_traverse.cl), and the surface at a hit.
 *
 * The intersection is the numerically careful quadratic of Haines et al. 2019 ("Precision
 * Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7) as pbrt-v4 (section
 * 6.2) uses it: the discriminant r^2 - |l|^2 comes from l, the vector from the centre to the
 * line's closest point, as (r - |l|)(r + |l|), not from b^2 - 4ac (which cancels
 * catastrophically when the ray starts far away); the near root is c / q and the far one
 * q / a, with q = -(b + sign(b) sqrt(disc)), so neither subtracts nearly equal numbers.
 * The hit point is re-projected onto the sphere, and the next ray leaves from a point
 * offset along the normal by the point's error bound (pbrt-v4 section 6.8.6), so a ray
 * leaving either side never meets the sphere it starts on: the sign of |o - c| - r, which
 * decides which roots are ahead, is then beyond rounding. */
#ifndef FACET_TRACE_SPHERE_CL
#define FACET_TRACE_SPHERE_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/shared/sphere_layout.h"
#include "kernels/trace/small_tree_traverse.cl"
#include "kernels/util/math.cl"

/* Hit.tri of a sphere hit; Hit.prim is then the sphere's index in the FcSphere array. */
#define FC_HIT_SPHERE (-2)

/* gamma(n) = n eps / (1 - n eps), eps = 2^-24: the relative bound of n rounded operations. */
inline float fc_gamma(int n) {
    const float e = (float)n * 0x1p-24f;
    return e / (1.0f - e);
}

/* The two roots t0 <= t1 of |o + t d - c| = r (d need not be unit); false when the line
 * misses the sphere. The test is written once over lanes (sphere_lanes.cl). */
inline bool sphere_roots(float3 c, float r, float3 o, float3 d, float* t0, float* t1) {
    return sphere_roots_l1(c.x, c.y, c.z, r, o.x, o.y, o.z, d.x, d.y, d.z, t0, t1) != 0;
}

/* The nearest intersection with 0 < t < tmax, in *t. */
inline bool sphere_hit(float3 c, float r, float3 o, float3 d, float tmax, float* t) {
    return sphere_hit_l1(c.x, c.y, c.z, r, o.x, o.y, o.z, d.x, d.y, d.z, tmax, t) != 0;
}

/* Tests the leaf's spheres [first, first + count), shortening hit->t. */
inline bool sphere_leaf_hit(__global const FcSphere* spheres, int first, int count, float3 o, float3 d, Hit* hit,
                            bool any_hit) {
    bool found = false;
    for (int i = first; i < first + count; ++i) {
        float t;
        if (!sphere_hit(load3(spheres[i].center), spheres[i].radius, o, d, hit->t, &t)) continue;
        if (any_hit) return true;
        hit->t = t;
        hit->u = 0.0f;
        hit->v = 0.0f;
        hit->prim = i;
        hit->tri = FC_HIT_SPHERE;
        found = true;
    }
    return found;
}

/* Nearest sphere hit with 0 < t < hit->t (or, with `any_hit`, whether there is one). */
inline bool trace_spheres(__global const FcBvhNode* nodes, __global const FcSphere* spheres, float3 o, float3 d,
                          Hit* hit, bool any_hit) {
    bool found = false;
#define FC_SPHERE_LEAF(first, count) sphere_leaf_hit(spheres, first, count, o, d, hit, any_hit)
    FC_SMALL_TREE_TRAVERSE(nodes, o, d, hit, any_hit, found, FC_SPHERE_LEAF);
#undef FC_SPHERE_LEAF
}

/* The hit point o + t d re-projected onto the sphere, its outward unit normal in *n and a
 * bound on each coordinate's rounding error in *err (pbrt-v4 eq. 6.8 with the centre's
 * translation added). */
inline float3 sphere_hit_point(float3 c, float r, float3 o, float3 d, float t, float3* n, float3* err) {
    const float3 v = o + t * d - c;
    *n = normalize_or(v, (float3)(0.0f, 0.0f, 1.0f));
    *err = fc_gamma(6) * (fabs(c) + r);
    return c + r * *n;
}

/* A ray origin off the sphere point p on the side of unit normal `n`: moved along n by
 * twice the error bound's projection, then rounded away from the surface. */
inline float3 sphere_offset_origin(float3 p, float3 err, float3 n) {
    const float dist = 2.0f * dot(fabs(n), err);
    const float3 po = p + dist * n;
    /* Each coordinate one float further along n's sign (nextafter(po, +-INFINITY) for a
     * finite po, which this is), on the three at once: a zero takes n's sign, then the bit
     * pattern steps by +1 where po and n have the same sign (the magnitude grows) and by -1
     * where they differ; a zero component of n leaves the coordinate. */
    const float3 z = select(po, copysign((float3)(0.0f), n), po == 0.0f);
    const int3 bits = as_int3(z);
    const int3 step = select((int3)(-1), (int3)(1), (bits ^ as_int3(n)) >= 0);
    return select(as_float3(bits + step), po, n == 0.0f);
}

/* The parametrisation at outward unit normal n, about the +y axis (facet's up): u = phi /
 * (2 pi) with phi = atan2(n.z, n.x) in [0, 2 pi), v = theta / pi with theta = acos(n.y) from
 * the +y pole. */
inline float2 sphere_uv(float3 n) {
    float phi = atan2(n.z, n.x);
    if (phi < 0.0f) phi += 2.0f * FC_PI;
    return (float2)(phi * (0.5f * FC_INV_PI), acos(clamp(n.y, -1.0f, 1.0f)) * FC_INV_PI);
}

/* The unit tangent dp/du at outward unit normal n (along increasing phi), +x at the poles. */
inline float3 sphere_tangent(float3 n) { return normalize_or((float3)(-n.z, 0.0f, n.x), (float3)(1.0f, 0.0f, 0.0f)); }

#endif
