/* Rays against everything in the scene: the triangles' BVH (bvh_traverse.cl), then, in
 * programs built with FC_HAS_INSTANCES, the instances of shared meshes (instance.cl), and in
 * programs built with FC_HAS_SPHERES, the analytic spheres' own tree (sphere.cl); each only
 * has to beat the nearest hit so far. Programs without them trace triangles alone. */
#ifndef FACET_TRACE_SCENE_TRACE_CL
#define FACET_TRACE_SCENE_TRACE_CL

#include "kernels/scene/scene_view.cl"
#include "kernels/trace/bvh_traverse.cl"
/* Every program: hit_triangle_vertices places an instanced triangle's vertices. */
#include "kernels/trace/instance.cl"
#if FC_HAS_SPHERES
#include "kernels/trace/sphere.cl"
#endif

/* The alpha test of the world's triangles for a ray of seed `alpha_seed`, or none in
 * programs without FC_HAS_ALPHA. */
#if FC_HAS_ALPHA
#define FC_WORLD_ALPHA(seed)                     \
    const AlphaTest world_alpha = {sc, 0, seed}; \
    const AlphaTest* alpha = &world_alpha
#else
#define FC_WORLD_ALPHA(seed)    \
    const AlphaTest* alpha = 0; \
    (void)(seed)
#endif

/* The instances (in programs built with FC_HAS_INSTANCES), each only to beat hit->t: whether
 * one was nearer. */
inline bool scene_trace_closest_instances(const SceneView* sc, float3 o, float3 d, uint alpha_seed, Hit* hit) {
#if FC_HAS_INSTANCES
    return trace_instances(sc, o, d, hit, false, alpha_seed);
#else
    (void)sc;
    (void)o;
    (void)d;
    (void)alpha_seed;
    (void)hit;
    return false;
#endif
}

/* What lies past the triangles' tree, each only to beat hit->t: in programs built with
 * FC_HAS_INSTANCES the instances, with FC_HAS_SPHERES the spheres. Whether one was nearer. */
inline bool scene_trace_closest_past_triangles(const SceneView* sc, float3 o, float3 d, uint alpha_seed, Hit* hit) {
    bool found = scene_trace_closest_instances(sc, o, d, alpha_seed, hit);
#if FC_HAS_SPHERES
    if (trace_spheres(sc->sphere_nodes, sc->spheres, o, d, hit, false)) {
        hit->inst = -1;
        found = true;
    }
#endif
    return found;
}

/* Nearest hit with 0 < t < tmax that the alpha test keeps (kernels/trace/alpha_test.cl;
 * `alpha_seed` is the ray's seed): a triangle (hit->tri >= 0; hit->inst >= 0 when met in an
 * instance) or a sphere (FC_HIT_SPHERE). */
inline bool scene_trace_closest(const SceneView* sc, float3 o, float3 d, float tmax, uint alpha_seed, Hit* hit) {
    FC_WORLD_ALPHA(alpha_seed);
    bool found = trace_closest_alpha(sc->nodes, sc->tris, o, d, tmax, hit, alpha);
    if (scene_trace_closest_past_triangles(sc, o, d, alpha_seed, hit)) found = true;
    return found;
}

/* Whether anything that the alpha test keeps is hit with 0 < t < tmax (shadow rays). */
inline bool scene_trace_any(const SceneView* sc, float3 o, float3 d, float tmax, uint alpha_seed) {
    FC_WORLD_ALPHA(alpha_seed);
    if (trace_any_alpha(sc->nodes, sc->tris, o, d, tmax, alpha)) return true;
#if FC_HAS_INSTANCES || FC_HAS_SPHERES
    Hit hit;
    hit.t = tmax;
    hit.prim = -1;
    hit.tri = -1;
    hit.inst = -1;
#endif
#if FC_HAS_INSTANCES
    if (trace_instances(sc, o, d, &hit, true, alpha_seed)) return true;
#endif
#if FC_HAS_SPHERES
    if (trace_spheres(sc->sphere_nodes, sc->spheres, o, d, &hit, true)) return true;
#endif
    return false;
}

#undef FC_WORLD_ALPHA

#endif
