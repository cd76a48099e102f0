/* The packet paths' rays through the scene (issue 29): the triangles' tree and the spheres' in
 * packets where the program traces in packets (kernels/trace/packet_trace.cl,
 * packet_sphere.cl), else, and for instances, lane by lane through scene_trace_closest and
 * scene_trace_any. Included by kernels/integrator/packet_paths.cl inside its lanes (FC_LW =
 * FC_PACKET_W), after its lane helpers (lane3, set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_SCENE_TRACE_CL
#define FACET_INTEGRATOR_PACKET_SCENE_TRACE_CL

/* Rays in packets through the triangles' tree (kernels/trace/packet_trace.cl): on, unless the
 * host turns it off (in trees of over 50 000 triangles, or with FACET_PACKET_TRACE=0:
 * host/render/packet_paths.hpp, packet_trace_for), on CPUs' 8-wide nodes, and not in programs
 * with cut-outs (whose alpha test runs per ray). */
#ifndef FC_PACKET_TRACE
#define FC_PACKET_TRACE 1
#endif
#if FC_PACKET_TRACE && FC_W == 8 && !FC_HAS_ALPHA
#define FC_PACKET_TRACE_ON 1
#include "kernels/trace/packet_trace.cl"
/* The fewest rays a call traces as a packet, whatever the tree: fewer go ray by ray. A call of
 * one to three rays is most often the camera rays of the paths just begun in lanes whose paths
 * escaped (packet_paths.cl's step A), and a packet's box and triangle tests cost as much for
 * one ray as for sixteen (the Cornell box at 256 x 256, whose tree is traced to the leaves in
 * packets: 1.6 % faster; docs/performance.md). */
#ifndef FC_PACKET_CALL_MIN
#define FC_PACKET_CALL_MIN 4
#endif
#if FC_PACKET_TRACE_MIN > FC_PACKET_CALL_MIN
#define FC_PACKET_CALL_RAYS FC_PACKET_TRACE_MIN
#else
#define FC_PACKET_CALL_RAYS FC_PACKET_CALL_MIN
#endif
#else
#define FC_PACKET_TRACE_ON 0
#endif
/* The spheres' tree in packets too (kernels/trace/packet_sphere.cl), closest hits and shadow
 * rays, in programs with spheres that trace in packets. */
#if FC_PACKET_TRACE_ON && FC_HAS_SPHERES
#define FC_PACKET_SPHERES 1
#include "kernels/trace/packet_sphere.cl"
#else
#define FC_PACKET_SPHERES 0
#endif

/* The nearest hits of lanes `need` of the rays (o, d: lane arrays), scene_trace_closest's
 * for each lane, in hits[j]; the bits of the lanes that hit. With fewer lanes than
 * FC_PACKET_CALL_RAYS, or without packet traversal, lane by lane. */
inline uint packet_trace_closest(const SceneView* sc, const float* o, const float* d, uint need, const uint* seed,
                                 const uint* irev, const uint* depth, Hit* hits) {
    uint met = 0u;
#if FC_PACKET_TRACE_ON
    if (popcount(need) >= FC_PACKET_CALL_RAYS) {
        for (uint rest = need; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            hits[j].t = INFINITY; /* trace_closest_alpha's start */
            hits[j].u = 0.0f;
            hits[j].v = 0.0f;
            hits[j].prim = -1;
            hits[j].tri = -1;
            hits[j].inst = -1;
        }
        met = packet_trace_bvh(sc->nodes, o, d, need, false, (LFLOAT)(INFINITY), hits);
        for (uint rest = need; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            if ((met >> j) & 1u) hits[j].prim = sc->tris[hits[j].tri].prim;
            if (scene_trace_closest_instances(sc, lane3(o, j), lane3(d, j),
                                              alpha_ray_seed(seed[j], irev[j], depth[j], 0u), &hits[j]))
                met |= 1u << j;
        }
#if FC_PACKET_SPHERES
        /* then the spheres, each lane's to beat its hit so far (scene_trace_closest's order) */
        float t[FC_PACKET_W];
        int prim[FC_PACKET_W];
        for (int j = 0; j < FC_PACKET_W; ++j) t[j] = hits[j].t;
        const uint on_sphere = packet_trace_spheres(sc->sphere_nodes, sc->spheres, o, d, need, t, false, t, prim);
        for (uint rest = on_sphere; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            hits[j].t = t[j];
            hits[j].u = 0.0f;
            hits[j].v = 0.0f;
            hits[j].prim = prim[j];
            hits[j].tri = FC_HIT_SPHERE;
            hits[j].inst = -1;
        }
        met |= on_sphere;
#endif
        return met;
    }
#endif
    for (uint rest = need; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        if (scene_trace_closest(sc, lane3(o, j), lane3(d, j), INFINITY, alpha_ray_seed(seed[j], irev[j], depth[j], 0u),
                                &hits[j]))
            met |= 1u << j;
    }
    return met;
}

/* Which of lanes `bits` of the shadow rays (o, d: lane arrays, each up to tmax[j]) are blocked:
 * scene_trace_any's answer for each. With enough lanes and packet traversal, the triangles'
 * tree and the spheres' in packets (a ray met leaves its packet), the instances per lane;
 * otherwise lane by lane. */
inline uint packet_trace_any(const SceneView* sc, const float* o, const float* d, const float* tmax, uint bits,
                             const uint* seed, const uint* irev, const uint* depth) {
    uint blocked = 0u;
#if FC_PACKET_TRACE_ON
    if (popcount(bits) >= FC_PACKET_CALL_RAYS) {
        Hit hits[FC_PACKET_W]; /* scratch where rays finish a subtree alone */
        blocked = packet_trace_bvh(sc->nodes, o, d, bits, true, LLOAD(tmax), hits);
#if FC_HAS_INSTANCES
        for (uint rest = bits & ~blocked; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            Hit hit;
            hit.t = tmax[j];
            hit.prim = -1;
            hit.tri = -1;
            hit.inst = -1;
            if (trace_instances(sc, lane3(o, j), lane3(d, j), &hit, true,
                                alpha_ray_seed(seed[j], irev[j], depth[j], 1u)))
                blocked |= 1u << j;
        }
#endif
#if FC_PACKET_SPHERES
        const uint open = bits & ~blocked;
        if (popcount(open) >= FC_PACKET_TRACE_MIN)
            return blocked | packet_trace_spheres(sc->sphere_nodes, sc->spheres, o, d, open, tmax, true, 0, 0);
        for (uint rest = open; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            Hit hit;
            hit.t = tmax[j];
            if (trace_spheres(sc->sphere_nodes, sc->spheres, lane3(o, j), lane3(d, j), &hit, true)) blocked |= 1u << j;
        }
#endif
        return blocked;
    }
#endif
    for (uint rest = bits; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        if (scene_trace_any(sc, lane3(o, j), lane3(d, j), tmax[j], alpha_ray_seed(seed[j], irev[j], depth[j], 1u)))
            blocked |= 1u << j;
    }
    return blocked;
}

#endif
