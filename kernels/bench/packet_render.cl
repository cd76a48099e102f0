/* Issue 29's packet prototype in the real renderer: render_pass's paths for a scene of
 * Lambertian materials and triangle area lights, eight paths per work-item in float8
 * lanes, with regeneration. Trace, surface, camera ray and accumulation per lane (facet's
 * scalar functions); the sampler, light sampling, the BSDF and roulette in lanes. A
 * measurement, not a product kernel: the lane code repeats the scalar formulas. */
#include "kernels/integrator/path.cl"

#define W 8
#define PATH_ENDED 0xfffffffeu /* depth[j] of a lane whose path ended and is not yet added */

typedef struct {
    float8 x, y, z;
} L3;

inline L3 l3(float8 x, float8 y, float8 z) {
    L3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
inline L3 l3_load(const float* a) { return l3(vload8(0, a), vload8(0, a + W), vload8(0, a + 2 * W)); }
inline void l3_store(L3 v, float* a) {
    vstore8(v.x, 0, a);
    vstore8(v.y, 0, a + W);
    vstore8(v.z, 0, a + 2 * W);
}
inline float3 lane3(const float* a, int j) { return (float3)(a[j], a[W + j], a[2 * W + j]); }
inline void set_lane3(float* a, int j, float3 v) {
    a[j] = v.x;
    a[W + j] = v.y;
    a[2 * W + j] = v.z;
}
inline float8 l3_dot(L3 a, L3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

inline ulong8 mix64_8(ulong8 z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9UL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebUL;
    return z ^ (z >> 31);
}
inline uint8 lk8(uint8 x, uint8 seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    return x ^ (x * 0x8d22f6e6u);
}
inline uint8 hash32_8(uint8 x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}
inline uint8 rev8(uint8 x) {
    x = (x >> 16) | (x << 16);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

/* offset_ray_origin (kernels/trace/ray.cl) on eight lanes */
inline float8 offset_ulps8(float8 p, float8 n) {
    int8 of_i = convert_int8(FC_OFFSET_INT_SCALE * n);
    float8 p_i = as_float8(as_int8(p) + select(of_i, -of_i, p < 0.0f));
    return select(p_i, p + FC_OFFSET_FLOAT_SCALE * n, fabs(p) < FC_OFFSET_ORIGIN);
}
inline L3 offset_origin8(L3 p, L3 n) {
    return l3(offset_ulps8(p.x, n.x), offset_ulps8(p.y, n.y), offset_ulps8(p.z, n.z));
}

/* sampler_get4 for eight lanes (Sobol' only): u[0..3] the four coordinates. */
inline void get4_8(uint8 pixel_seed, uint8 index_rev, uint8 set, float8* u) {
    uint8 seed = convert_uint8(mix64_8((convert_ulong8(pixel_seed) << 32) | convert_ulong8(set)));
    uint8 r = lk8(index_rev, seed);
    uint rr[W];
    vstore8(r, 0, rr);
    uint c[4 * W];
    for (int j = 0; j < W; ++j) {
        uint4 q = sobol4_reversed(rr[j]);
        c[j] = q.x;
        c[W + j] = q.y;
        c[2 * W + j] = q.z;
        c[3 * W + j] = q.w;
    }
    for (uint k = 0; k < 4u; ++k) {
        uint8 x = rev8(lk8(vload8(0, c + k * W), hash32_8(seed + (k + 1u) * 0x9e3779b9u)));
        u[k] = convert_float8(x >> 8) * 0x1p-24f;
    }
}

/* sincos_turns (kernels/util/trig.cl) on eight lanes: returns sin, writes cos. */
inline float8 sincos_turns8(float8 t, float8* cos_out) {
    float8 q = rint(4.0f * t);
    float8 f = t - 0.25f * q;
    float8 x = FC_2PI * f;
    float8 x2 = x * x;
    float8 s = 2.7557319e-06f;
    s = -1.9841270e-04f + x2 * s;
    s = 8.3333338e-03f + x2 * s;
    s = -1.6666667e-01f + x2 * s;
    s = x + x * x2 * s;
    float8 c = -2.7557320e-07f;
    c = 2.4801588e-05f + x2 * c;
    c = -1.3888889e-03f + x2 * c;
    c = 4.1666668e-02f + x2 * c;
    c = -0.5f + x2 * c;
    c = 1.0f + x2 * c;
    int8 k = convert_int8(q) & 3;
    float8 a = select(s, c, (k & 1) != 0);
    float8 b = select(c, s, (k & 1) != 0);
    *cos_out = select(b, -b, ((k + 1) & 2) != 0);
    return select(a, -a, (k & 2) != 0);
}

__kernel void packet_pass(FC_SCENE_KERNEL_PARAMS, __global float4* accum) {
    uint gid = get_global_id(0);
    uint x = gid % params->width;
    uint y = params->row_begin + gid / params->width;
    if (gid / params->width >= params->row_count || y >= params->height) return;
    SceneView scv = FC_SCENE_VIEW_INIT;
    const SceneView* sc = &scv;
    __constant const FcRenderParams* P = params;
    uint pixel = y * params->width + x;
    float4 sum[2] = {(float4)(0.0f), (float4)(0.0f)};
    float square[2] = {0.0f, 0.0f};
    const uint end = params->sample_begin + params->sample_count;

    /* per-lane state, in arrays (lane j at [j], 3-vectors as x[0..7] y[8..15] z[16..23]) */
    float o[3 * W], d[3 * W], thr[3 * W], rad[3 * W], p[3 * W], ng[3 * W], ns[3 * W], alb[3 * W];
    float prev_pdf[W], fweight[W];
    uint index[W], depth[W], seed[W], irev[W];
    int active[W], alive[W];
    for (int j = 0; j < W; ++j) {
        index[j] = params->sample_begin + (uint)j;
        active[j] = index[j] < end;
        alive[j] = 0; /* start a sample */
        depth[j] = 0u;
    }
    for (;;) {
        /* A: finished lanes accumulate, then take their next sample */
        bool any_active = false;
        for (int j = 0; j < W; ++j) {
            if (!active[j]) continue;
            if (!alive[j]) {
                if (depth[j] == PATH_ENDED) { /* a finished path: add it */
                    float3 l = lane3(rad, j);
                    uint idx = index[j];
                    if (all_finite(l) && l.x >= 0.0f && l.y >= 0.0f && l.z >= 0.0f) {
                        l = fmin(l, (float3)(FC_MAX_RADIANCE));
                        float peak = max3(l);
                        if (peak > params->clamp) l *= params->clamp / peak;
                        float3 weighted = fweight[j] * l;
                        sum[idx & 1u].xyz += weighted;
                        square[idx & 1u] += fmin(dot(weighted, weighted), FC_MAX_SQUARE);
                    } else sum[idx & 1u].w += 1.0f;
                    index[j] += W;
                    if (index[j] >= end) {
                        active[j] = 0;
                        continue;
                    }
                }
                Sampler s = sampler_init(params->sampler, params->seed, pixel, index[j]);
                seed[j] = s.seed;
                irev[j] = s.index_reversed;
                float3 oo, dd;
                fweight[j] = pixel_sample_ray(params, x, y, &s, &oo, &dd);
                set_lane3(o, j, oo);
                set_lane3(d, j, dd);
                set_lane3(thr, j, (float3)(1.0f));
                set_lane3(rad, j, (float3)(0.0f));
                prev_pdf[j] = INFINITY;
                depth[j] = 0u;
                alive[j] = 1;
            }
            any_active = true;
        }
        if (!any_active) break;

        /* B: per lane, the closest hit, its surface and emission */
        for (int j = 0; j < W; ++j) {
            if (!active[j] || !alive[j]) continue;
            float3 oo = lane3(o, j), dd = lane3(d, j);
            Hit hit;
            if (!scene_trace_closest(sc, oo, dd, INFINITY, alpha_ray_seed(seed[j], irev[j], depth[j], 0u), &hit)) {
                alive[j] = 0;
                depth[j] = PATH_ENDED;
                continue;
            }
            Surface s = surface_at(sc, &hit);
            __global const FcMaterial* m = &sc->materials[s.material];
            float3 wo = -dd;
            float3 le = area_light_radiance(load3(m->emission), m->flags, s.ng, wo);
            if (!is_black(le) && s.light >= 0) {
                float w = 1.0f;
                if (depth[j] > 0u) {
                    float light_pdf = light_pdf_hit(sc, s.light, oo, hit.t, dot(s.ng, wo));
                    w = bsdf_strategy_weight(P->strategy, prev_pdf[j], light_pdf);
                }
                set_lane3(rad, j, lane3(rad, j) + lane3(thr, j) * le * w);
            }
            if (depth[j] >= P->max_depth) {
                alive[j] = 0;
                depth[j] = PATH_ENDED;
                continue;
            }
            /* two-sided: the side the ray came from */
            if (dot(s.ng, wo) < 0.0f) {
                s.ng = -s.ng;
                s.ns = -s.ns;
            }
            set_lane3(p, j, s.p);
            set_lane3(ng, j, s.ng);
            set_lane3(ns, j, s.ns);
            set_lane3(alb, j, load3(m->diffuse));
        }

        /* C: in lanes, the frame, the light sample and the BSDF sample */
        int8 live = (vload8(0, alive) != 0) & (vload8(0, active) != 0);
        L3 D = l3_load(d), N = l3_load(ns), NG = l3_load(ng), PP = l3_load(p), A = l3_load(alb), T = l3_load(thr);
        L3 wo = l3(-D.x, -D.y, -D.z);
        /* frame_from_normal(ns); ns = ng where wo is below ns */
        float8 wz = l3_dot(wo, N);
        int8 below = wz <= 0.0f;
        N.x = select(N.x, NG.x, below);
        N.y = select(N.y, NG.y, below);
        N.z = select(N.z, NG.z, below);
        float8 sign = copysign((float8)(1.0f), N.z);
        float8 a = -1.0f / (sign + N.z);
        float8 b = N.x * N.y * a;
        L3 S = l3(1.0f + sign * N.x * N.x * a, sign * b, -sign * N.x);
        L3 Tt = l3(b, sign + N.y * N.y * a, -N.y);
        float8 wo_z = l3_dot(wo, N);
        uint8 dep = vload8(0, depth), sd = vload8(0, seed), ir = vload8(0, irev);
        float8 ul[4], ub[4];
        get4_8(sd, ir, 1u + 2u * dep, ul);
        get4_8(sd, ir, 2u + 2u * dep, ub);

        /* the light: picked and read per lane */
        float lp0[3 * W], le1[3 * W], le2[3 * W], ln[3 * W], lc[3 * W], lpick[W], larea[W];
        uint lflags[W];
        float upick[W];
        vstore8(ul[0], 0, upick);
        for (int j = 0; j < W; ++j) {
            __global const FcLight* l = &sc->lights[pick_light(sc->light_cdf, P->light_count, upick[j])];
            set_lane3(lp0, j, load3(l->p0));
            set_lane3(le1, j, load3(l->e1));
            set_lane3(le2, j, load3(l->e2));
            set_lane3(ln, j, load3(l->n));
            set_lane3(lc, j, load3(l->color));
            lpick[j] = l->pick_pdf;
            larea[j] = l->area;
            lflags[j] = l->flags;
        }
        float8 su = sqrt(ul[1]);
        float8 b0 = su * (1.0f - ul[2]), b1 = su * ul[2];
        L3 LP = l3_load(lp0), E1 = l3_load(le1), E2 = l3_load(le2), LN = l3_load(ln), LC = l3_load(lc);
        L3 point = l3(LP.x + b0 * E1.x + b1 * E2.x, LP.y + b0 * E1.y + b1 * E2.y, LP.z + b0 * E1.z + b1 * E2.z);
        L3 to = l3(point.x - PP.x, point.y - PP.y, point.z - PP.z);
        float8 d2 = l3_dot(to, to);
        float8 dist = sqrt(d2);
        L3 wi = l3(to.x / dist, to.y / dist, to.z / dist);
        float8 cl = l3_dot(LN, wi);
        float8 acl = fabs(cl);
        float8 pdf_l = select((float8)(0.0f), vload8(0, lpick) * (dist * dist) / (vload8(0, larea) * acl), acl > 0.0f);
        uint8 two = vload8(0, lflags) & FC_MAT_TWO_SIDED_EMISSION;
        int8 lit = select(-cl > 0.0f, -cl != 0.0f, two != 0u); /* area_light_radiance toward -wi */
        float8 side = l3_dot(NG, wi);
        float8 wi_z = l3_dot(wi, N);
        float8 f_scale = FC_INV_PI;
        int8 ok = live & (d2 > 0.0f) & (pdf_l > 0.0f) & isfinite(pdf_l) & lit & (side > 0.0f) & (wi_z * side > 0.0f) &
                  (wo_z > 0.0f) & (wi_z > 0.0f);
        float8 pdf_b = wi_z * f_scale;
        float8 w = (pdf_l * pdf_l) / (pdf_l * pdf_l + pdf_b * pdf_b);
        float8 k = select((float8)(0.0f), fabs(wi_z) * w / pdf_l, ok);
        L3 contrib = l3(T.x * A.x * f_scale * LC.x * k, T.y * A.y * f_scale * LC.y * k, T.z * A.z * f_scale * LC.z * k);
        /* the shadow rays, in lanes: from the offset point to the offset point on the light */
        L3 so = offset_origin8(PP, NG);
        int8 back = cl < 0.0f;
        L3 tn = l3(select(-LN.x, LN.x, back), select(-LN.y, LN.y, back), select(-LN.z, LN.z, back));
        L3 target = offset_origin8(point, tn);
        L3 seg = l3(target.x - so.x, target.y - so.y, target.z - so.z);
        float8 tmax = sqrt(l3_dot(seg, seg));
        ok &= tmax > 0.0f;
        L3 sd8 = l3(seg.x / tmax, seg.y / tmax, seg.z / tmax);
        float cx[3 * W], so_a[3 * W], sd_a[3 * W], tmax_a[W];
        int oka[W];
        l3_store(contrib, cx);
        l3_store(so, so_a);
        l3_store(sd8, sd_a);
        vstore8(tmax, 0, tmax_a);
        vstore8(ok, 0, oka);

        /* D: shadow rays per lane */
        for (int j = 0; j < W; ++j) {
            if (!oka[j]) continue;
            if (!scene_trace_any(sc, lane3(so_a, j), lane3(sd_a, j), tmax_a[j],
                                 alpha_ray_seed(seed[j], irev[j], depth[j], 1u)))
                set_lane3(rad, j, lane3(rad, j) + lane3(cx, j));
        }

        /* E: the BSDF sample (cosine hemisphere), throughput and roulette, in lanes */
        float8 px = 2.0f * ub[0] - 1.0f, py = 2.0f * ub[1] - 1.0f;
        int8 xm = fabs(px) > fabs(py);
        float8 r = select(py, px, xm);
        float8 turns = select(0.25f - 0.125f * (px / py), 0.125f * (py / px), xm);
        float8 cs;
        float8 sn = sincos_turns8(turns, &cs);
        int8 zero = (px == 0.0f) & (py == 0.0f);
        float8 dx = select(r * cs, (float8)(0.0f), zero), dy = select(r * sn, (float8)(0.0f), zero);
        float8 dz = sqrt(fmax(0.0f, 1.0f - dx * dx - dy * dy));
        L3 nwi = l3(dx * S.x + dy * Tt.x + dz * N.x, dx * S.y + dy * Tt.y + dz * N.y, dx * S.z + dy * Tt.z + dz * N.z);
        float8 nside = l3_dot(NG, nwi);
        int8 cont = live & (wo_z > 0.0f) & (dz > 0.0f) & (nside * dz > 0.0f);
        L3 T2 = l3(T.x * A.x, T.y * A.y, T.z * A.z);
        int8 rr = convert_int8(dep + 1u >= P->rr_depth);
        float8 survive = fmin(fmax(T2.x, fmax(T2.y, T2.z)), 0.95f);
        cont &= select((int8)(-1), ub[3] < survive, rr);
        T2 = l3(select(T2.x, T2.x / survive, rr), select(T2.y, T2.y / survive, rr), select(T2.z, T2.z / survive, rr));
        l3_store(T2, thr);
        l3_store(nwi, d);
        l3_store(offset_origin8(PP, NG), o);
        vstore8(dz * f_scale, 0, prev_pdf);
        int conta[W];
        vstore8(cont, 0, conta);
        for (int j = 0; j < W; ++j) {
            if (!active[j] || !alive[j]) continue;
            if (!conta[j]) {
                alive[j] = 0;
                depth[j] = PATH_ENDED;
                continue;
            }
            depth[j] += 1u;
        }
    }
    accum[pixel] += sum[0];
    uint pixels = params->width * params->height;
    accum[pixels + pixel] += sum[1];
    __global float* squares = (__global float*)(accum + 2u * pixels);
    squares[pixel] += square[0];
    squares[pixels + pixel] += square[1];
}
