/* A packet's rays through the triangles' tree together (issue 29): FC_PACKET_WIDTH rays, one a
 * lane, meet each node's child boxes and each leaf triangle in vector lanes, the node or the
 * triangle the same in every lane (Wald, Slusallek, Benthin & Wagner 2001, "Interactive
 * Rendering with Coherent Ray Tracing"), where the single-ray traversal (bvh_traverse.cl) meets
 * one ray against a node's eight boxes or a block's four triangles. A node is entered by the
 * rays that hit its box; once fewer than FC_PACKET_TRACE_MIN of them are left, each of them
 * finishes that subtree alone, by the single-ray traversal from there (Benthin, Wald, Woop,
 * Ernst & Mark 2012, "Combining Single and Packet-Ray Tracing for Arbitrary Ray Distributions
 * on the Intel MIC Architecture"), so incoherent rays in a large tree do not drag a packet of
 * mostly idle lanes down it. In a small scene (the Cornell box's 32 triangles) a packet meets
 * each triangle once for all its rays, where a ray alone pays the traversal's bookkeeping for
 * a handful of tests; in a large one the rays part after a few levels, and the host leaves
 * trees of over 50 000 triangles to single rays (host/render/packet_paths.hpp).
 *
 * Every box test and triangle test is the single-ray traversal's, operation for operation
 * (slabs_hit's and tri_hit's bodies), so a ray meets the same triangles with the same
 * distances and barycentrics; the nearest is kept with the same rule (a triangle must be
 * strictly nearer than the hit so far), so the hit is the same triangle unless two
 * triangles lie at the same computed distance, where the visiting order decides.
 *
 * Included by kernels/integrator/packet_paths.cl inside its lanes (kernels/lanes/lanes_open.cl
 * at FC_LW = FC_PACKET_W); the 8-wide nodes of CPUs, float or quantised. */
#ifndef FACET_TRACE_PACKET_TRACE_CL
#define FACET_TRACE_PACKET_TRACE_CL

#include "kernels/trace/bvh_traverse.cl"

#if FC_W != 8
#error "packet_trace.cl reads 8-wide nodes"
#endif

/* Rays a node needs to be entered by the packet; fewer finish it alone. The host sets 1 (every
 * ray to the leaves in the packet) in the smallest trees, where a subtree is a leaf or two
 * (packet_trace_min_for, host/render/packet_paths.hpp). */
#ifndef FC_PACKET_TRACE_MIN
#define FC_PACKET_TRACE_MIN 4
#endif

/* Bit j of the result: lane j of mask m is set (lane_bits_w of the 8-wide nodes' masks). */
#if FC_PACKET_W == 8
inline uint packet_bits(LINT m) { return lane_bits_w(m); }
#elif defined(__AVX512DQ__)
/* one vpmovd2m, folded by LLVM into the comparison that made m (vec3_lanes.cl's lanes_any) */
inline uint packet_bits(LINT m) { return (uint)__builtin_ia32_cvtd2mask512(__builtin_convertvector(m, FcLanesV16si)); }
#else
inline uint packet_bits(LINT m) { return lane_bits_w(m.lo) | (lane_bits_w(m.hi) << 8); }
#endif

/* The mask (-1) of the lanes whose bits are set. */
inline LINT packet_mask(uint bits) {
#if FC_PACKET_W == 8
    const LINT lane_bit = (LINT)(1, 2, 4, 8, 16, 32, 64, 128);
#else
    const LINT lane_bit = (LINT)(1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32768);
#endif
    return ((LINT)((int)bits) & lane_bit) != 0;
}

/* The smallest lane. */
inline float packet_min(LFLOAT v) {
#if FC_PACKET_W == 16
    const float8 a = fmin(v.lo, v.hi);
#else
    const float8 a = v;
#endif
    const float4 b = fmin(a.lo, a.hi);
    const float2 c = fmin(b.lo, b.hi);
    return fmin(c.x, c.y);
}

/* Component k (0, 1, 2: x, y, z) of (x, y, z), lane by lane. */
inline LFLOAT packet_axis(LFLOAT x, LFLOAT y, LFLOAT z, LINT k) { return select(select(x, y, k == 1), z, k == 2); }

/* The packet's rays, set up once: the slab test's reciprocals and signs (box_ray_setup's) and
 * the triangle test's axes and shear (tri_ray_setup's), lane by lane. */
typedef struct {
    LFLOAT ox, oy, oz, ix, iy, iz;
    LINT nx, ny, nz; /* the direction's negative components: the near plane is the box's max */
    LINT kx, ky, kz;
    LFLOAT tox, toy, toz, sx, sy, sz;
} PacketRays;

inline PacketRays packet_rays_setup(const float* o, const float* d) {
    PacketRays r;
    r.ox = LLOAD(o);
    r.oy = LLOAD(o + FC_PACKET_W);
    r.oz = LLOAD(o + 2 * FC_PACKET_W);
    const LFLOAT dx = LLOAD(d), dy = LLOAD(d + FC_PACKET_W), dz = LLOAD(d + 2 * FC_PACKET_W);
    r.ix = 1.0f / dx;
    r.iy = 1.0f / dy;
    r.iz = 1.0f / dz;
    r.nx = r.ix < 0.0f;
    r.ny = r.iy < 0.0f;
    r.nz = r.iz < 0.0f;
    const LFLOAT ax = fabs(dx), ay = fabs(dy), az = fabs(dz);
    r.kz = select(select((LINT)(2), (LINT)(1), ay > az), select((LINT)(2), (LINT)(0), ax > az), ax > ay);
    LINT kx = select(r.kz + 1, (LINT)(0), r.kz == 2);
    LINT ky = select(kx + 1, (LINT)(0), kx == 2);
    const LFLOAT dk = packet_axis(dx, dy, dz, r.kz);
    const LINT flip = dk < 0.0f; /* keep the winding */
    r.kx = select(kx, ky, flip);
    r.ky = select(ky, kx, flip);
    r.sx = packet_axis(dx, dy, dz, r.kx) / dk;
    r.sy = packet_axis(dx, dy, dz, r.ky) / dk;
    r.sz = packet_axis(r.ix, r.iy, r.iz, r.kz); /* 1 / dk, divided above */
    r.tox = packet_axis(r.ox, r.oy, r.oz, r.kx);
    r.toy = packet_axis(r.ox, r.oy, r.oz, r.ky);
    r.toz = packet_axis(r.ox, r.oy, r.oz, r.kz);
    return r;
}

/* One child box [lo, hi] against the packet (slabs_hit's operations, lane by lane): the lanes
 * that meet it within their t, and their entry distances in *tnear. */
inline LINT packet_box_hit(const PacketRays* r, float lx, float ly, float lz, float hx, float hy, float hz, LFLOAT t,
                           LFLOAT* tnear) {
    const LFLOAT ax = ((LFLOAT)(lx)-r->ox) * r->ix, bx = ((LFLOAT)(hx)-r->ox) * r->ix;
    const LFLOAT ay = ((LFLOAT)(ly)-r->oy) * r->iy, by = ((LFLOAT)(hy)-r->oy) * r->iy;
    const LFLOAT az = ((LFLOAT)(lz)-r->oz) * r->iz, bz = ((LFLOAT)(hz)-r->oz) * r->iz;
    const LFLOAT t0x = select(ax, bx, r->nx), t0y = select(ay, by, r->ny), t0z = select(az, bz, r->nz);
    const LFLOAT t1x = select(bx, ax, r->nx) * FC_SLAB_SCALE, t1y = select(by, ay, r->ny) * FC_SLAB_SCALE,
                 t1z = select(bz, az, r->nz) * FC_SLAB_SCALE;
    LFLOAT tn = (LFLOAT)(0.0f), tf = t;
    FC_SLAB_NARROW(tn, tf, t0x, t1x);
    FC_SLAB_NARROW(tn, tf, t0y, t1y);
    FC_SLAB_NARROW(tn, tf, t0z, t1z);
    *tnear = tn;
    return tn <= tf;
}

/* The packet's state: per lane the hit so far (t, the triangle in BVH order or -1, the
 * barycentric weights of vertices 1 and 2 as u / det and v / det: the triangle test's edge
 * functions and their sum, divided when the hits are stored, once, not at every hit). */
typedef struct {
    LFLOAT t, u, v, det;
    LINT tri;
} PacketHits;

/* The packet's hits from hits[0..W-1] (every lane read; lanes not traced are not used). */
inline PacketHits packet_hits_load(const Hit* hits) {
    float t[FC_PACKET_W], u[FC_PACKET_W], v[FC_PACKET_W];
    int tri[FC_PACKET_W];
    for (int j = 0; j < FC_PACKET_W; ++j) {
        t[j] = hits[j].t;
        u[j] = hits[j].u;
        v[j] = hits[j].v;
        tri[j] = hits[j].tri;
    }
    PacketHits h;
    h.t = LLOAD(t);
    h.u = LLOAD(u);
    h.v = LLOAD(v);
    h.det = (LFLOAT)(1.0f); /* weights already divided: x * (1 / 1) is x */
    h.tri = LLOAD(tri);
    return h;
}

/* Lanes `bits` of the packet's hits into hits[j]. */
inline void packet_hits_store(const PacketHits* h, uint bits, Hit* hits) {
    float t[FC_PACKET_W], u[FC_PACKET_W], v[FC_PACKET_W];
    int tri[FC_PACKET_W];
    LSTORE(h->t, t);
    const LFLOAT inv = 1.0f / h->det; /* tri4_weights' */
    LSTORE(h->u * inv, u);
    LSTORE(h->v * inv, v);
    LSTORE(h->tri, tri);
    for (uint rest = bits; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        hits[j].t = t[j];
        hits[j].u = u[j];
        hits[j].v = v[j];
        hits[j].tri = tri[j];
    }
}

/* A packet traversal's stack: the nodes still to visit, each with the lanes that entered it. */
typedef struct {
    int node[FC_STACK];
    uint bits[FC_STACK];
    int sp;
} PacketStack;

/* The inner children of the node being visited that its lanes entered: each child's node, its
 * lanes and their nearest entry distance. */
typedef struct {
    int node[8];
    uint bits[8];
    float t[8];
    int n;
} PacketChildren;

/* Child `node`, entered by lanes `lanes` at distances tn. */
__attribute__((always_inline)) inline void packet_child_add(PacketChildren* ch, int node, LINT lanes, LFLOAT tn) {
    ch->node[ch->n] = node;
    ch->bits[ch->n] = packet_bits(lanes);
    ch->t[ch->n] = packet_min(select((LFLOAT)(INFINITY), tn, lanes));
    ++ch->n;
}

/* The step after a node: its nearest entered child next (*node, *bits), the others pushed
 * farthest first; with none, the stack's top. False when nothing is left. */
__attribute__((always_inline)) inline bool packet_next(PacketChildren* ch, PacketStack* st, int* node, uint* bits) {
    const int n = ch->n;
    if (n == 0) {
        if (st->sp == 0) return false;
        --st->sp;
        *node = st->node[st->sp];
        *bits = st->bits[st->sp];
        return true;
    }
    for (int a = 1; a < n; ++a) {
        const int cn = ch->node[a];
        const uint cb = ch->bits[a];
        const float ct = ch->t[a];
        int b = a;
        for (; b > 0 && ch->t[b - 1] < ct; --b) {
            ch->node[b] = ch->node[b - 1];
            ch->bits[b] = ch->bits[b - 1];
            ch->t[b] = ch->t[b - 1];
        }
        ch->node[b] = cn;
        ch->bits[b] = cb;
        ch->t[b] = ct;
    }
    for (int a = 0; a + 1 < n; ++a)
        if (st->sp < FC_STACK) { /* always, by the builder */
            st->node[st->sp] = ch->node[a];
            st->bits[st->sp] = ch->bits[a];
            ++st->sp;
        }
    *node = ch->node[n - 1];
    *bits = ch->bits[n - 1];
    return true;
}

/* The triangles of a leaf's `blocks` blocks from row `row` (the first `count` of them; all
 * four of every block where count is not known: padding never hits) against lanes m. */
inline LINT packet_leaf_hit(__global const float4* rows, int row, int blocks, int count, const PacketRays* r, LINT m,
                            PacketHits* h) {
    LINT found = (LINT)(0);
    for (; blocks > 0; --blocks, row += 10, count -= 4) {
        __global const float* b = (__global const float*)(rows + row);
        __global const int* ids = (__global const int*)(rows + row + 9);
        const int n = min(count, 4);
        for (int k = 0; k < n; ++k) {
            /* vertex coordinate (row, lane k) along each lane's axes */
#define FC_PK_AXIS(v, kk)                                                           \
    packet_axis((LFLOAT)(b[4 * (3 * (v)) + k]), (LFLOAT)(b[4 * (3 * (v) + 1) + k]), \
                (LFLOAT)(b[4 * (3 * (v) + 2) + k]), r->kk)
            LFLOAT t, vv, ww, det;
            LINT hit =
                LNAME(tri_hit)(r->tox, r->toy, r->toz, r->sx, r->sy, r->sz, FC_PK_AXIS(0, kx), FC_PK_AXIS(0, ky),
                               FC_PK_AXIS(0, kz), FC_PK_AXIS(1, kx), FC_PK_AXIS(1, ky), FC_PK_AXIS(1, kz),
                               FC_PK_AXIS(2, kx), FC_PK_AXIS(2, ky), FC_PK_AXIS(2, kz), h->t, &t, &vv, &ww, &det);
#undef FC_PK_AXIS
            hit &= m;
            if (!LNAME(lanes_any)(hit)) continue;
            found |= hit;
            h->t = select(h->t, t, hit);
            h->u = select(h->u, vv, hit);
            h->v = select(h->v, ww, hit);
            h->det = select(h->det, det, hit);
            h->tri = select(h->tri, (LINT)(ids[k]), hit);
        }
    }
    return found;
}

/* Lanes `bits` of the rays (origins o, directions d: lane arrays, x of lane j at [j], y at
 * [W + j], z at [2W + j]) against the triangles' tree in `buffer`, each up to its lane of
 * tmax. Nearest hits (any false): hits[j] set where a triangle nearer than tmax is met (t, u,
 * v, tri; prim and inst left to the caller, and the lanes that meet none). Shadow rays (any
 * true): whether a triangle nearer than tmax is met at all; a lane met stops there (its t set
 * to -infinity, which no box and no triangle is nearer than), and the packet when all have.
 * Returns the bits of the lanes that met a triangle. `hits` is scratch for every lane when
 * rays finish a subtree alone. The packet's hits start in registers: read back from the
 * lanes' Hit records, just written one lane at a time, they waited on the stores (a vector
 * load of scalar stores is not forwarded). No alpha test: programs with cut-outs trace ray by
 * ray (packet_paths.cl). */
inline uint packet_trace_bvh(__global const FcBvhNode* buffer, const float* o, const float* d, uint bits, bool any,
                             LFLOAT tmax, Hit* hits) {
    __global const FcNode* nodes = (__global const FcNode*)buffer;
    __global const float4* rows = (__global const float4*)buffer;
    const PacketRays r = packet_rays_setup(o, d);
    PacketHits h;
    h.t = tmax;
    h.u = (LFLOAT)(0.0f);
    h.v = (LFLOAT)(0.0f);
    h.det = (LFLOAT)(1.0f);
    h.tri = (LINT)(-1);
    uint found = 0u, alone = 0u; /* lanes that met a triangle: in packets, alone */
    const uint traced = bits;
    PacketStack st;
    st.sp = 0;
    int node = 0;
    for (;;) {
        PacketChildren ch;
        ch.n = 0;
        if (popcount(bits) < FC_PACKET_TRACE_MIN) {
            /* the few rays left finish this subtree alone (every lane's hit so far stored, as
             * every lane is loaded back); a shadow ray already met has nothing left to find */
            packet_hits_store(&h, 0xffffffffu >> (32 - FC_PACKET_W), hits);
            for (uint rest = any ? bits & ~(found | alone) : bits; rest; rest &= rest - 1u) {
                const uint j = lowest_bit(rest);
                const float3 oj = (float3)(o[j], o[FC_PACKET_W + j], o[2 * FC_PACKET_W + j]);
                const float3 dj = (float3)(d[j], d[FC_PACKET_W + j], d[2 * FC_PACKET_W + j]);
                if (trace_bvh_at(buffer, node, oj, dj, &hits[j], any, 0)) {
                    alone |= 1u << j;
                    if (any) hits[j].t = -INFINITY;
                }
            }
            h = packet_hits_load(hits);
        } else {
            const LINT m = packet_mask(bits);
            __global const FcNode* n = &nodes[node];
#if FC_BVH_QUANTISED
            const float4 head = *(__global const float4*)n;
            const uint e = as_uint(head.w);
            const uint inner_slots = e >> 24;
            const float qx = as_float((e & 0xffu) << 23), qy = as_float(((e >> 8) & 0xffu) << 23),
                        qz = as_float(((e >> 16) & 0xffu) << 23);
            __global const uchar* q = (__global const uchar*)n->q_lo_x; /* lo x, y, z, hi x, y, z: 8 bytes each */
            const ulong meta = as_ulong(vload2(0, n->meta));
#endif
            for (int c = 0; c < 8; ++c) {
#if FC_BVH_QUANTISED
                const bool is_inner = ((inner_slots >> c) & 1u) != 0u;
                const uint mc = (uint)(meta >> (8u * (uint)c)) & 0xffu; /* blocks | first << 3 */
                if (!is_inner && (mc & 7u) == 0u) continue;             /* an empty slot */
                const float lx = head.x + (float)q[c] * qx, ly = head.y + (float)q[8 + c] * qy,
                            lz = head.z + (float)q[16 + c] * qz, hx = head.x + (float)q[24 + c] * qx,
                            hy = head.y + (float)q[32 + c] * qy, hz = head.z + (float)q[40 + c] * qz;
#else
                const float lx = n->lo_x[c], hx = n->hi_x[c];
                if (!(lx <= hx)) continue; /* an empty slot: inverted */
                const float ly = n->lo_y[c], lz = n->lo_z[c], hy = n->hi_y[c], hz = n->hi_z[c];
                const int cnt = n->count[c];
                const bool is_inner = cnt <= 0;
#endif
                LFLOAT tn;
                const LINT hc = m & packet_box_hit(&r, lx, ly, lz, hx, hy, hz, h.t, &tn);
                if (!LNAME(lanes_any)(hc)) continue;
                if (is_inner) {
#if FC_BVH_QUANTISED
                    packet_child_add(&ch, n->child_base + (int)popcount(inner_slots & ((1u << c) - 1u)), hc, tn);
#else
                    packet_child_add(&ch, n->index[c], hc, tn);
#endif
                    continue;
                }
#if FC_BVH_QUANTISED
                const int row = n->leaf_base + 10 * (int)(mc >> 3), blocks = (int)(mc & 7u), count = 4 * blocks;
#else
                const int row = n->index[c], blocks = (cnt + 3) >> 2, count = cnt;
#endif
                const LINT met = packet_leaf_hit(rows, row, blocks, count, &r, hc, &h);
                found |= packet_bits(met);
                if (any) h.t = select(h.t, (LFLOAT)(-INFINITY), met);
            }
            if (any && (found | alone) == traced) return found | alone;
        }
        if (!packet_next(&ch, &st, &node, &bits)) break;
    }
    const uint met = found | alone;
    if (!any) packet_hits_store(&h, met, hits);
    return met;
}

#endif
