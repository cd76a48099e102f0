/* Instancing (kernels/shared/instance_layout.h): rays against the instances of shared
 * meshes. A top-level small tree over the instances' world boxes (small_tree_traverse.cl, as
 * the spheres' tree) leads to instances; at each, the ray is taken
 * into the mesh's object space (its direction not renormalised, so that t along it is the
 * world ray's t and the nearest hit is shared by every instance and the world's triangles)
 * and the mesh's own tree is traversed from its root by bvh_traverse.cl (pbrt-v4's
 * TransformedPrimitive; Wald et al. 2003's two-level BVH). A hit records the instance. */
#ifndef FACET_TRACE_INSTANCE_CL
#define FACET_TRACE_INSTANCE_CL

#include "kernels/scene/instance_transform.cl"
#include "kernels/scene/scene_view.cl"
#include "kernels/trace/small_tree_traverse.cl"

/* The instances [first, first + count) of a leaf, shortening hit->t: a hit sets hit->inst
 * and hit->tri to the triangle's index in the whole FcTriangle array. `alpha_seed` is the
 * ray's seed for the alpha test (alpha_test.cl). */
inline bool instance_leaf_hit(const SceneView* sc, int first, int count, float3 o, float3 d, Hit* hit, bool any_hit,
                              uint alpha_seed) {
    bool found = false;
    for (int i = first; i < first + count; ++i) {
        __global const FcInstance* in = &sc->instances[i];
        const float3 oo = instance_point_to_object(in, o);
        const float3 od = instance_vector_to_object(in, d);
#if FC_HAS_ALPHA
        const AlphaTest alpha = {sc, in->tri_offset, alpha_seed};
        const AlphaTest* at = &alpha;
#else
        const AlphaTest* at = 0;
        (void)alpha_seed;
#endif
        if (!trace_bvh_from(sc->nodes, in->root, oo, od, hit, any_hit, at)) continue;
        if (any_hit) return true;
        hit->tri += in->tri_offset;
        hit->inst = i;
        found = true;
    }
    return found;
}

/* The instances' tree for instance_leaf_hit's hits, without hit->prim. */
inline bool instances_traverse(const SceneView* sc, float3 o, float3 d, Hit* hit, bool any_hit, uint alpha_seed) {
    bool found = false;
#define FC_INSTANCE_LEAF(first, count) instance_leaf_hit(sc, first, count, o, d, hit, any_hit, alpha_seed)
    FC_SMALL_TREE_TRAVERSE(sc->instance_nodes, o, d, hit, any_hit, found, FC_INSTANCE_LEAF);
#undef FC_INSTANCE_LEAF
}

/* Nearest instanced hit with 0 < t < hit->t (or, with `any_hit`, whether there is one). A
 * closest hit gets hit->prim (its triangle's index in the shading arrays). */
inline bool trace_instances(const SceneView* sc, float3 o, float3 d, Hit* hit, bool any_hit, uint alpha_seed) {
    const bool found = instances_traverse(sc, o, d, hit, any_hit, alpha_seed);
    if (found) hit->prim = sc->tris[hit->tri].prim;
    return found;
}

/* The world-space vertices of hit triangle hit->tri: its own, or placed by its instance. */
inline void hit_triangle_vertices(const SceneView* sc, const Hit* hit, float3* v0, float3* v1, float3* v2) {
    __global const FcTriangle* tri = &sc->tris[hit->tri];
    *v0 = load3(tri->v0);
    *v1 = load3(tri->v1);
    *v2 = load3(tri->v2);
#if FC_HAS_INSTANCES
    if (hit->inst >= 0) {
        __global const FcInstance* in = &sc->instances[hit->inst];
        *v0 = instance_point_to_world(in, *v0);
        *v1 = instance_point_to_world(in, *v1);
        *v2 = instance_point_to_world(in, *v2);
    }
#endif
}

#endif
