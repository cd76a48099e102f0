/* A packet's rays through the analytic spheres' tree together (issue 29), as
 * kernels/trace/packet_trace.cl takes them through the triangles' tree: each node's child boxes
 * and each leaf sphere meet all the packet's rays in vector lanes, the sphere the same in every
 * lane. The ray/sphere test is the scalar one written over lanes (sphere_lanes.cl), so a ray
 * meets the same spheres at the same distances as trace_spheres gives it; the nearest is kept
 * with the same rule (strictly nearer than the hit so far), so the hit is trace_spheres' unless
 * two spheres lie at the same computed distance. The spheres' tree is small (a leaf per few
 * spheres), so the packet goes down it whole: no ray finishes alone.
 *
 * Included by kernels/integrator/packet_paths.cl inside its lanes (FC_LW = FC_PACKET_W), in
 * programs with spheres; the small trees' float nodes are FcBvhNode8 on CPUs. */
#ifndef FACET_TRACE_PACKET_SPHERE_CL
#define FACET_TRACE_PACKET_SPHERE_CL

#include "kernels/trace/packet_trace.cl"
#include "kernels/trace/sphere.cl"

/* Lanes `bits` of the rays (o, d: lane arrays, packet_trace_bvh's) against the spheres' tree
 * `buffer` (FcBvhNode8, root at 0) for t < t_in[j]. Nearest hits (any false): the lanes that
 * met a sphere nearer, with its distance in t_out[j] and its index in prim[j] (other lanes
 * left). Shadow rays (any true): the lanes that met one (t_out and prim not written). */
inline uint packet_trace_spheres(__global const FcBvhNode* buffer, __global const FcSphere* spheres, const float* o,
                                 const float* d, uint bits, const float* t_in, bool any, float* t_out, int* prim) {
    __global const FcBvhNode8* nodes = (__global const FcBvhNode8*)buffer;
    const PacketRays r = packet_rays_setup(o, d);
    const LFLOAT dx = LLOAD(d), dy = LLOAD(d + FC_PACKET_W), dz = LLOAD(d + 2 * FC_PACKET_W);
    LFLOAT t = LLOAD(t_in);
    LINT hit_prim = (LINT)(-1);
    uint found = 0u;
    const uint traced = bits;
    PacketStack st;
    st.sp = 0;
    int node = 0;
    for (;;) {
        const LINT m = packet_mask(bits);
        __global const FcBvhNode8* n = &nodes[node];
        PacketChildren ch;
        ch.n = 0;
        for (int c = 0; c < 8; ++c) {
            const float lx = n->lo_x[c], hx = n->hi_x[c];
            if (!(lx <= hx)) continue; /* an empty slot: inverted */
            LFLOAT tn;
            const LINT hc = m & packet_box_hit(&r, lx, n->lo_y[c], n->lo_z[c], hx, n->hi_y[c], n->hi_z[c], t, &tn);
            if (!LNAME(lanes_any)(hc)) continue;
            const int cnt = n->count[c], first = n->index[c];
            if (cnt <= 0) {
                packet_child_add(&ch, first, hc, tn);
                continue;
            }
            for (int i = first; i < first + cnt; ++i) {
                __global const FcSphere* s = &spheres[i];
                LFLOAT ts;
                const LINT h =
                    hc & LNAME(sphere_hit)((LFLOAT)(s->center[0]), (LFLOAT)(s->center[1]), (LFLOAT)(s->center[2]),
                                           (LFLOAT)(s->radius), r.ox, r.oy, r.oz, dx, dy, dz, t, &ts);
                if (!LNAME(lanes_any)(h)) continue;
                found |= packet_bits(h);
                /* a shadow ray met is done: below any distance, no box or sphere takes it */
                t = select(t, any ? (LFLOAT)(-INFINITY) : ts, h);
                hit_prim = select(hit_prim, (LINT)(i), h);
            }
            if (any && found == traced) return found;
        }
        if (!packet_next(&ch, &st, &node, &bits)) break;
    }
    if (!any) {
        LSTORE(t, t_out);
        LSTORE(hit_prim, prim);
    }
    return found;
}

#endif
