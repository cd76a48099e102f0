/* The packet prototype of issue 29 (bench/packet/README.md): one bounce's shading work of
 * the Cornell box, written once over a lane type and compiled twice, as REAL = float (one
 * path per work-item, the GPU form) and REAL = float8 (eight paths per work-item in
 * AVX2's lanes, the CPU form). packet_prototype.py defines the lane types and the
 * gathers, then includes this file once per width.
 *
 * The work stands in for what path.cl does between two traces. It is timing code, not
 * facet's physics:
 * - two 4-D points from a Burley-style scrambled table (as sampler_get4);
 * - an area light picked from two and a point sampled on it, with its solid-angle pdf;
 * - a Lambertian BSDF's value, its pdf and the power-heuristic weight;
 * - a cosine-weighted direction (concentric disk, polynomial sin and cos of turns);
 * - the throughput update and Russian roulette from the third bounce.
 *
 * The trace and the hit's surface are replaced by a gather from a table of 1024 points
 * and normals, indexed by a hash of the path's last direction, so the work keeps a
 * path's serial dependence.
 *
 * Width-generic rules, which a product version would keep:
 * - every branch on lane data is a select (the ternary operator on vectors is
 *   elementwise in OpenCL C);
 * - every read of memory indexed by lane data goes through a gather macro;
 * - scalar and vector forms then run the same IEEE operations in the same order. */

typedef struct {
    REAL x, y, z;
} V3;

inline V3 FN(v3)(REAL x, REAL y, REAL z) {
    V3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
inline V3 FN(v3_sub)(V3 a, V3 b) { return FN(v3)(a.x - b.x, a.y - b.y, a.z - b.z); }
inline V3 FN(v3_add)(V3 a, V3 b) { return FN(v3)(a.x + b.x, a.y + b.y, a.z + b.z); }
inline V3 FN(v3_scale)(V3 a, REAL s) { return FN(v3)(a.x * s, a.y * s, a.z * s); }
inline V3 FN(v3_mul)(V3 a, V3 b) { return FN(v3)(a.x * b.x, a.y * b.y, a.z * b.z); }
inline REAL FN(v3_dot)(V3 a, V3 b) { return fma(a.x, b.x, fma(a.y, b.y, a.z * b.z)); }

/* Integer mixing of a lane's word: a 32-bit multiply-xorshift bijection. */
inline UINT FN(mix32)(UINT x) {
    x = (x ^ (x >> 16)) * 0x7feb352du;
    x = (x ^ (x >> 15)) * 0x846ca68bu;
    return x ^ (x >> 16);
}

/* A nested scramble of x's bits upward, from a seed (Laine and Karras's form). */
inline UINT FN(scramble_up)(UINT x, UINT seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    return x ^ (x * 0x8d22f6e6u);
}

/* x's bits in reverse order, by swapping ever smaller fields. */
inline UINT FN(bits_reversed)(UINT x) {
    UINT y = rotate(x, (UINT)(16u));
    y = ((y >> 8) & 0x00ff00ffu) | ((y & 0x00ff00ffu) << 8);
    y = ((y >> 4) & 0x0f0f0f0fu) | ((y & 0x0f0f0f0fu) << 4);
    y = ((y >> 2) & 0x33333333u) | ((y & 0x33333333u) << 2);
    return ((y >> 1) & 0x55555555u) | ((y & 0x55555555u) << 1);
}

/* The 4-D point of dimension set `set` for the sample whose reversed index is index_rev:
 * the index scrambled, eight table chunks XORed (a gather per lane), each coordinate
 * scrambled with its own seed, reversed and scaled to [0, 1). */
inline void FN(point4)(__constant const uint4* table, UINT pixel_seed, UINT index_rev, UINT set, REAL* u) {
    UINT seed = FN(mix32)(pixel_seed ^ (set * 0x9e3779b9u));
    UINT r = FN(scramble_up)(index_rev, seed);
    UINT c[4];
    GATHER_TABLE(table, r, c);
    for (uint i = 0; i < 4u; ++i) {
        UINT bits = FN(bits_reversed)(FN(scramble_up)(c[i], FN(mix32)(seed + (i + 1u) * 0x9e3779b9u)));
        u[i] = CONVERT_REAL(bits >> 8) * 0x1p-24f;
    }
}

/* sin and cos of 2 pi t for t in [0, 1): the quarter turn by exact reduction, then Taylor
 * polynomials on [0, pi / 2). */
inline void FN(sincos_turns)(REAL t, REAL* s, REAL* c) {
    REAL quarter = floor(t * 4.0f);
    REAL f = (t - quarter * 0.25f) * 6.2831853f;
    REAL f2 = f * f;
    REAL sn = f * fma(f2, fma(f2, fma(f2, -1.9841270e-4f, 8.3333333e-3f), -1.6666667e-1f), 1.0f);
    REAL cs = fma(f2, fma(f2, fma(f2, -1.3888889e-3f, 4.1666667e-2f), -0.5f), 1.0f);
    INT q = CONVERT_INT(quarter);
    *s = (q == 0) ? sn : (q == 1) ? cs : (q == 2) ? -sn : -cs;
    *c = (q == 0) ? cs : (q == 1) ? -sn : (q == 2) ? -cs : sn;
}

/* One bounce at point p with normal n: returns the light sample's contribution (before
 * the shadow test, which is a trace), writes the next direction, updates the
 * throughput and clears `alive` for lanes that roulette ends. */
inline V3 FN(shade)(__constant const uint4* table, __global const float* lights, UINT pixel_seed, UINT index_rev,
                    UINT depth, V3 p, V3 n, V3 albedo, V3* throughput, V3* dir, INT* alive) {
    REAL ul[4], ub[4];
    FN(point4)(table, pixel_seed, index_rev, 1u + 2u * depth, ul);
    FN(point4)(table, pixel_seed, index_rev, 2u + 2u * depth, ub);

    /* an orthonormal basis around n (Duff et al. 2017) */
    REAL sign = (n.z >= 0.0f) ? (REAL)(1.0f) : (REAL)(-1.0f);
    REAL a = -1.0f / (sign + n.z);
    REAL b = n.x * n.y * a;
    V3 tx = FN(v3)(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    V3 ty = FN(v3)(b, sign + n.y * n.y * a, -n.y);

    /* the light: a record of 16 floats (v0, e1, e2, normal, emission, area), one of two */
    INT pick = (ul[0] < 0.5f) ? (INT)(0) : (INT)(1);
    V3 v0, e1, e2, ln, le;
    REAL area;
    GATHER_LIGHT(lights, pick, v0, e1, e2, ln, le, area);
    REAL su = sqrt(ul[1]);
    V3 lp = FN(v3_add)(v0, FN(v3_add)(FN(v3_scale)(e1, 1.0f - su), FN(v3_scale)(e2, ul[2] * su)));
    V3 to = FN(v3_sub)(lp, p);
    REAL d2 = FN(v3_dot)(to, to);
    V3 wi = FN(v3_scale)(to, rsqrt(d2));
    REAL cos_light = -FN(v3_dot)(ln, wi);
    REAL pdf_light = 0.5f * d2 / (area * fabs(cos_light));
    REAL cos_i = FN(v3_dot)(wi, n);
    INT lit = (cos_i > 0.0f) & (cos_light > 0.0f) & (d2 > 0.0f);
    REAL pdf_bsdf = cos_i * 0.31830989f;
    REAL w = pdf_light * pdf_light / (pdf_light * pdf_light + pdf_bsdf * pdf_bsdf);
    REAL k = lit ? cos_i * w / pdf_light * 0.31830989f : (REAL)(0.0f);
    V3 direct = FN(v3_mul)(FN(v3_mul)(*throughput, albedo), FN(v3_scale)(le, k));

    /* a cosine-weighted direction: the concentric disk lifted to the hemisphere */
    REAL sx = 2.0f * ub[0] - 1.0f, sy = 2.0f * ub[1] - 1.0f;
    INT x_major = fabs(sx) > fabs(sy);
    REAL r = x_major ? sx : sy;
    REAL ratio = x_major ? sy / sx : sx / sy;
    REAL turns = x_major ? 0.125f * ratio : 0.25f - 0.125f * ratio;
    turns = (r < 0.0f) ? turns + 0.5f : turns;
    turns -= floor(turns);
    REAL sn, cs;
    FN(sincos_turns)(turns, &sn, &cs);
    REAL lx = fabs(r) * cs, ly = fabs(r) * sn;
    REAL lz = sqrt(fmax(0.0f, 1.0f - lx * lx - ly * ly));
    *dir = FN(v3_add)(FN(v3_add)(FN(v3_scale)(tx, lx), FN(v3_scale)(ty, ly)), FN(v3_scale)(n, lz));

    /* throughput and roulette (survival: the largest channel, at most 0.95) */
    *throughput = FN(v3_mul)(*throughput, albedo);
    REAL survive = fmin(fmax(throughput->x, fmax(throughput->y, throughput->z)), 0.95f);
    INT roulette = depth + 1u >= 3u;
    *alive &= roulette ? (INT)(ub[3] < survive) : (INT)(TRUE_MASK);
    *throughput = FN(v3_scale)(*throughput, roulette ? (REAL)(1.0f / survive) : (REAL)(1.0f));
    return direct;
}

/* The surface a path's ray meets, standing in for the trace: one of the table's 1024
 * points, chosen by a hash of the sample, the bounce and the last direction. */
inline void FN(next_surface)(__global const float* points, UINT index, UINT depth, V3 dir, uint gid, V3* p, V3* n) {
    UINT k = FN(mix32)(index ^ AS_UINT(dir.x) ^ (gid + depth * 7919u)) & 1023u;
    GATHER_POINT(points, k, *p, *n);
}

#define FC_PROTO_ALBEDO FN(v3)(0.886f, 0.699f, 0.666f) /* the Cornell box's white wall */

/* Without regeneration: a work-item's LANES paths start together, and the packet runs
 * until its last path ends (at most max_depth bounces). */
__kernel void FN(paths)(__constant const uint4* table, __global const float* lights, __global const float* points,
                        __global float* out, __global uint* slots, uint max_depth) {
    uint gid = get_global_id(0);
    UINT pixel_seed = FN(mix32)((UINT)(gid * 0x85ebca6bu));
    V3 sum = FN(v3)(0.0f, 0.0f, 0.0f);
    uint used = 0u, busy = 0u;
    for (uint s = 0; s < SAMPLES_PER_ITEM; s += LANES) {
        UINT index = (UINT)(s) + LANE_IDS;
        UINT index_rev = FN(bits_reversed)(index);
        V3 throughput = FN(v3)(1.0f, 1.0f, 1.0f), dir = FN(v3)(0.0f, 0.0f, 1.0f), p, n;
        INT alive = (INT)(TRUE_MASK);
        for (uint depth = 0; depth < max_depth && ANY(alive); ++depth) {
            used += LANES;
            busy += COUNT(alive);
            FN(next_surface)(points, index, (UINT)(depth), dir, gid, &p, &n);
            INT was_alive = alive;
            V3 c = FN(shade)(table, lights, pixel_seed, index_rev, (UINT)(depth), p, n, FC_PROTO_ALBEDO, &throughput,
                             &dir, &alive);
            sum = FN(v3_add)(sum, FN(v3_scale)(c, was_alive ? (REAL)(1.0f) : (REAL)(0.0f)));
        }
    }
    out[gid] = HSUM(sum.x + sum.y + sum.z);
    slots[2u * gid] = used;
    slots[2u * gid + 1u] = busy;
}

/* With regeneration (Novák et al. 2010): lane j renders samples j, j + LANES, ..., and a
 * lane whose path ended starts its next sample at the next step, so lanes stay busy until
 * the work-item's last samples. */
__kernel void FN(paths_regenerated)(__constant const uint4* table, __global const float* lights,
                                    __global const float* points, __global float* out, __global uint* slots,
                                    uint max_depth) {
    uint gid = get_global_id(0);
    UINT pixel_seed = FN(mix32)((UINT)(gid * 0x85ebca6bu));
    V3 sum = FN(v3)(0.0f, 0.0f, 0.0f);
    uint used = 0u, busy = 0u;
    UINT index = LANE_IDS, depth = (UINT)(0u);
    V3 throughput = FN(v3)(1.0f, 1.0f, 1.0f), dir = FN(v3)(0.0f, 0.0f, 1.0f), p, n;
    INT active = (INT)(TRUE_MASK); /* the lane has a sample to render */
    while (ANY(active)) {
        used += LANES;
        busy += COUNT(active);
        FN(next_surface)(points, index, depth, dir, gid, &p, &n);
        INT alive = (INT)(TRUE_MASK);
        V3 c = FN(shade)(table, lights, pixel_seed, FN(bits_reversed)(index), depth, p, n, FC_PROTO_ALBEDO, &throughput,
                         &dir, &alive);
        sum = FN(v3_add)(sum, FN(v3_scale)(c, active ? (REAL)(1.0f) : (REAL)(0.0f)));
        depth += 1u;
        INT ended = !alive | (depth >= max_depth);
        index = ended ? index + (UINT)(LANES) : index;
        depth = ended ? (UINT)(0u) : depth;
        throughput.x = ended ? (REAL)(1.0f) : throughput.x;
        throughput.y = ended ? (REAL)(1.0f) : throughput.y;
        throughput.z = ended ? (REAL)(1.0f) : throughput.z;
        dir.x = ended ? (REAL)(0.0f) : dir.x;
        dir.y = ended ? (REAL)(0.0f) : dir.y;
        dir.z = ended ? (REAL)(1.0f) : dir.z;
        active &= (INT)(index < (UINT)(SAMPLES_PER_ITEM));
    }
    out[gid] = HSUM(sum.x + sum.y + sum.z);
    slots[2u * gid] = used;
    slots[2u * gid + 1u] = busy;
}

#undef FC_PROTO_ALBEDO
