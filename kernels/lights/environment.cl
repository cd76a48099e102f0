/* The environment light: radiance from infinitely far away, seen by escaping rays and
 * sampled by next-event estimation. Layout and direction convention: FcEnvironment in
 * kernels/shared/environment_layout.h; the host side (loading, sanitising, the distribution) is
 * host/scene/environment_map.cpp; docs/environment.md explains the whole.
 *
 * - Constant environment (width == 0): radiance `scale` from every direction, sampled
 *   uniformly over the sphere, pdf 1 / (4 pi) (0 when the radiance is black).
 * - Equirectangular map (`filter`): the nearest texel (the default: the radiance piecewise
 *   constant over the texels, like the texel-picking density) or bilinear between texel
 *   centres (opt-in: smooth reflections, as Mitsuba 3 and Cycles look maps up; slower:
 *   docs/environment.md). Sampling picks a texel from a
 *   piecewise-constant 2D distribution over luminance x sin(theta) (for the bilinear
 *   lookup the luminance integrated over the texel; a marginal cdf over
 *   rows, a conditional cdf per row; pbrt-v3 section 14.2.4, Pharr, Jakob, Humphreys
 *   2016) and a point in it: uniform for the nearest lookup; for the bilinear one with
 *   density in proportion to the interpolated luminance, so that radiance over pdf stays
 *   nearly constant inside a texel as it does for the nearest lookup (each quarter of the
 *   texel is a bilinear patch between the values at its corners: the quarter chosen by
 *   its integral, the point by the bilinear warp of pbrt-v4's SampleBilinear, Pharr, Jakob
 *   and Humphreys 2023; Mitsuba 3's continuous 2D distributions follow the interpolation
 *   likewise). The density in (u, v) converts to solid angle with
 *   the Jacobian of the equirectangular map, d(omega) = 2 pi^2 sin(theta) du dv:
 *     p(omega) = p(u, v) / (2 pi^2 sin(theta)).
 *   Directions at the poles (sin(theta) == 0) get pdf 0.
 *
 * Every probability is derived from differences of the stored float cdfs, so a texel
 * the float binary search can never pick reports pdf 0: env_pdf is the density of
 * env_sample as it runs, not of the exact real-number distribution. env_sample returns
 * the radiance and pdf of the direction it produced through the same lookup as
 * env_radiance and env_pdf, so the three always agree bit for bit. */
#ifndef FACET_LIGHTS_ENVIRONMENT_CL
#define FACET_LIGHTS_ENVIRONMENT_CL

#include "kernels/shared/environment_layout.h"
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

#define FC_INV_4PI 0.07957747154594766788f
#define FC_INV_2PI2 0.05066059182116888572f /* 1 / (2 pi^2) */

/* The directions' conversions are lane-generic (kernels/lights/environment_lanes.cl): these
 * are their W = 1 forms, to_map's rows read here. */

/* World direction to the map's frame (rows of to_map). */
inline float3 env_dir_to_map(__constant const FcEnvironment* env, float3 d) {
    return env_dir_to_map_l1(load3c(env->to_map[0]), load3c(env->to_map[1]), load3c(env->to_map[2]), d);
}

/* The map's frame back to world (the transpose: to_map is a rotation). */
inline float3 env_map_to_dir(__constant const FcEnvironment* env, float3 m) {
    return env_map_to_dir_l1(load3c(env->to_map[0]), load3c(env->to_map[1]), load3c(env->to_map[2]), m);
}

/* Map-frame direction to (u, v) in [0, 1]^2:
 * d = (sin theta sin phi, cos theta, -sin theta cos phi), u = phi / 2pi, v = theta / pi. */
inline float2 env_map_dir_to_uv(float3 m) {
    float sin_theta;
    return env_map_dir_to_uv_l1(m, &sin_theta);
}

/* (u, v) to the map-frame direction: phi = 2 pi u and theta = pi v in turns. */
inline float3 env_uv_to_map_dir(float2 uv) { return env_uv_to_map_dir_l1(uv); }

/* (u, v) to the unit world direction. */
inline float3 env_uv_to_dir(__constant const FcEnvironment* env, float2 uv) {
    return env_uv_to_dir_l1(load3c(env->to_map[0]), load3c(env->to_map[1]), load3c(env->to_map[2]), uv);
}

/* The texel (x, y) holding (u, v), clamped into the map. */
inline int2 env_texel(__constant const FcEnvironment* env, float2 uv) {
    int x = clamp((int)(uv.x * (float)env->width), 0, env->width - 1);
    int y = clamp((int)(uv.y * (float)env->height), 0, env->height - 1);
    return (int2)(x, y);
}

/* The texel world direction `dir` falls in, its (u, v), and sin(theta) in the map's
 * frame (from the horizontal component: accurate near the poles). */
inline int2 env_locate(__constant const FcEnvironment* env, float3 dir, float* sin_theta, float2* uv) {
    *uv = env_map_dir_to_uv_l1(env_dir_to_map(env, dir), sin_theta);
    return env_texel(env, *uv);
}

/* The map's value at (u, v), which lies in texel t, before `scale`: texel t itself, or
 * the bilinear interpolation of the four texel centres around (u, v), wrapping around in
 * u and clamped to the first and last rows in v. */
inline float3 env_lookup(__constant const FcEnvironment* env, __global const float4* texels, float2 uv, int2 t) {
    int w = env->width, h = env->height;
    if (env->filter != FC_ENV_FILTER_BILINEAR) return texels[t.y * w + t.x].xyz;
    float x = uv.x * (float)w - 0.5f, y = uv.y * (float)h - 0.5f;
    float x0f = floor(x), y0f = floor(y);
    float fx = clamp(x - x0f, 0.0f, 1.0f), fy = clamp(y - y0f, 0.0f, 1.0f);
    int x0 = (int)x0f, y0 = (int)y0f;
    int x1 = x0 + 1, y1 = y0 + 1;
    x0 = (x0 < 0) ? x0 + w : x0;
    x1 = (x1 >= w) ? x1 - w : x1;
    x0 = clamp(x0, 0, w - 1);
    x1 = clamp(x1, 0, w - 1);
    y0 = clamp(y0, 0, h - 1);
    y1 = clamp(y1, 0, h - 1);
    float3 top = mix(texels[y0 * w + x0].xyz, texels[y0 * w + x1].xyz, fx);
    float3 bottom = mix(texels[y1 * w + x0].xyz, texels[y1 * w + x1].xyz, fx);
    return mix(top, bottom, fy);
}

/* Radiance arriving from world direction `dir` (unit, pointing away from the scene). */
inline float3 env_radiance(__constant const FcEnvironment* env, __global const float4* texels, float3 dir) {
    if (!env->enabled) return (float3)(0.0f);
    if (env->width == 0) return load3c(env->scale);
    float sin_theta;
    float2 uv;
    int2 t = env_locate(env, dir, &sin_theta, &uv);
    return env_lookup(env, texels, uv, t) * load3c(env->scale);
}

/* The solid-angle density of a texel of row probability p_row and conditional probability
 * p_col at sin(theta) `sin_theta`: p(u, v) / (2 pi^2 sin(theta)). Non-decreasing in p_col as
 * float rounding is monotone, which env_row_pdf_bound relies on. */
inline float env_density(__constant const FcEnvironment* env, float p_row, float p_col, float sin_theta) {
    return p_row * (float)env->height * p_col * (float)env->width * FC_INV_2PI2 / sin_theta;
}

/* The solid-angle pdf of texel t at sin(theta) `sin_theta` (0 at the poles). */
inline float env_texel_pdf(__constant const FcEnvironment* env, __global const float* dist, int2 t, float sin_theta) {
    if (!(env->total > 0.0f) || !(sin_theta > 0.0f)) return 0.0f;
    __global const float* cond = dist + (env->height + 1) + t.y * (env->width + 1);
    float pdf = env_density(env, dist[t.y + 1] - dist[t.y], cond[t.x + 1] - cond[t.x], sin_theta);
    return isfinite(pdf) ? pdf : 0.0f;
}

/* An upper bound of env_texel_pdf over the texels of row y at sin(theta) `sin_theta`:
 * env_density with the row's largest conditional probability (the table after the guide
 * tables, host/scene/environment_map.hpp) for the texel's; infinite or NaN where sin_theta is
 * 0. It reads
 * the small marginal cdf and one float a row, not the row's conditional cdf (megabytes for a
 * map 1024 texels wide, most of a density's cost on a CPU). */
inline float env_row_pdf_bound(__constant const FcEnvironment* env, __global const float* dist, int y,
                               float sin_theta) {
    if (!(env->total > 0.0f)) return 0.0f;
    const uint w = (uint)env->width, h = (uint)env->height;
    const uint bounds =
        (h + 1u) + h * (w + 1u) + (env_guide_size(h) + 1u) + h * (env_guide_size(w) + 1u); /* past the guides */
    return env_density(env, dist[y + 1] - dist[y], dist[bounds + (uint)y], sin_theta);
}

/* The pdf of env_sample at a direction in texel t, where the lookup gives `value` (scale
 * included): the texel's, and for the bilinear lookup times the density inside the texel
 * relative to a uniform one, the interpolated luminance over its mean over the texel's square
 * (the texel's fourth float, written by the host: host/scene/environment_map.cpp). */
inline float env_point_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                           __global const float* dist, int2 t, float sin_theta, float3 value) {
    float pdf = env_texel_pdf(env, dist, t, sin_theta);
    if (env->filter != FC_ENV_FILTER_BILINEAR || !(pdf > 0.0f)) return pdf;
    float mean = texels[t.y * env->width + t.x].w;
    pdf = mean > 0.0f ? pdf * (luminance(value) / mean) : 0.0f;
    return isfinite(pdf) ? pdf : 0.0f;
}

/* The radiance (scale included) at the point (u, v) of a map (width > 0), sin(theta) there
 * `sin_theta`, and in *pdf env_sample's density at that direction: env_radiance_pdf's and
 * env_sample's lookup once the direction is located (the packet paths locate theirs in lanes). */
inline float3 env_map_radiance_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                                   __global const float* dist, float2 uv, float sin_theta, float* pdf) {
    const int2 t = env_texel(env, uv);
    const float3 value = env_lookup(env, texels, uv, t) * load3c(env->scale);
    *pdf = env_point_pdf(env, texels, dist, t, sin_theta, value);
    return value;
}

/* env_map_radiance_pdf at world direction `dir` of a map (width > 0): located, then looked up. */
inline float3 env_map_dir_radiance_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                                       __global const float* dist, float3 dir, float* pdf) {
    float sin_theta;
    const float2 uv = env_map_dir_to_uv_l1(env_dir_to_map(env, dir), &sin_theta);
    return env_map_radiance_pdf(env, texels, dist, uv, sin_theta, pdf);
}

/* Solid-angle density with which env_sample produces `dir`, and the radiance along it, by one
 * lookup (a ray that escaped after a BSDF sample needs both). */
inline float3 env_radiance_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, float3 dir, float* pdf) {
    *pdf = 0.0f;
    if (!env->enabled) return (float3)(0.0f);
    float3 scale = load3c(env->scale);
    if (env->width == 0) {
        *pdf = is_black(scale) ? 0.0f : FC_INV_4PI;
        return scale;
    }
    return env_map_dir_radiance_pdf(env, texels, dist, dir, pdf);
}

/* Solid-angle density with which env_sample produces `dir` (env_radiance_pdf's): a nearest
 * lookup's is its texel's, read from the sampling tables without the texel itself (the glass's
 * choice and the lens guide ask for densities only). */
inline float env_pdf(__constant const FcEnvironment* env, __global const float4* texels, __global const float* dist,
                     float3 dir) {
    if (env->enabled && env->width > 0 && env->filter != FC_ENV_FILTER_BILINEAR) {
        float sin_theta;
        float2 uv;
        const int2 t = env_locate(env, dir, &sin_theta, &uv);
        return env_texel_pdf(env, dist, t, sin_theta);
    }
    float pdf;
    env_radiance_pdf(env, texels, dist, dir, &pdf);
    return pdf;
}

/* The interval i of a non-decreasing cdf with cdf[i] <= u < cdf[i + 1] (never one of zero
 * width), by bisection of [lo, hi): the caller knows cdf[lo] <= u and that i < hi. */
inline int env_bisect(__global const float* cdf, int lo, int hi, float u) {
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* The interval of cdf[0..n] (cdf[0] = 0, cdf[n] = 1) holding u, from the cdf's guide
 * table guide[0..g] in the same buffer (g = env_guide_size(n); entry k the interval holding
 * k / g, as uint bits; Chen & Asau 1974): env_sample_texel's search
 * (kernels/lights/environment_lanes.cl), a step or two of bisection instead of log2(n). The
 * same interval as env_bisect over all of [0, n). */
inline int env_find_interval(__global const float* cdf, __global const float* guide, uint g, float u) {
    return env_find_interval_l1(cdf, 0u, (uint)(guide - cdf), g, u);
}

/* x in [0, 1) with density in proportion to (1 - x) a + x b (a, b >= 0, not both 0), by
 * inverting its cdf (pbrt-v4's SampleLinear); u where both are 0. */
inline float env_sample_linear(float u, float a, float b) {
    if (!(a + b > 0.0f)) return u;
    if (u == 0.0f && a == 0.0f) return 0.0f;
    float x = u * (a + b) / (a + sqrt(mix(a * a, b * b, u)));
    return clamp(x, 0.0f, FC_ONE_MINUS_EPSILON);
}

/* Chooses between two parts of weights a and b with u, and rescales u into the part
 * chosen: returns 1 for b. */
inline int env_choose(float a, float b, float* u) {
    float p = (a + b > 0.0f) ? a / (a + b) : 0.5f;
    if (*u < p) {
        *u = fmin(*u / p, FC_ONE_MINUS_EPSILON);
        return 0;
    }
    *u = clamp((*u - p) / (1.0f - p), 0.0f, FC_ONE_MINUS_EPSILON);
    return 1;
}

/* The point of texel (x, y), in [0, 1)^2 across it, of the bilinear lookup's sample: d
 * uniform in, out with density the interpolated luminance over its mean. The
 * interpolation between the centres of the 3 x 3 texels around is, on each quarter of the
 * texel, bilinear between the values at the quarter's corners: g[b][a] at (a / 2, b / 2)
 * of the texel (a along u, b along v), the mean of the centres around that point. A
 * quarter is chosen by its integral (the mean of its corners), v's half first, then u's,
 * and the point inside it by the bilinear warp: v from the marginal (linear between the
 * corners' row sums), then u from the conditional at that v. Each step is monotone in its
 * coordinate, so the sampler's strata stay together. */
inline float2 env_bilinear_in_texel(__constant const FcEnvironment* env, __global const float4* texels, int x, int y,
                                    float2 d) {
    /* the neighbours' columns wrapped around, their rows clamped, as env_lookup reads them */
    int w = env->width, h = env->height;
    int c0 = x == 0 ? w - 1 : x - 1, c2 = x == w - 1 ? 0 : x + 1;
    __global const float4* r0 = texels + max(y - 1, 0) * w;
    __global const float4* r1 = texels + y * w;
    __global const float4* r2 = texels + min(y + 1, h - 1) * w;
    float3 k = load3c(env->scale) * (float3)(0.2126f, 0.7152f, 0.0722f); /* luminance() with the scale */
    float l00 = dot(r0[c0].xyz, k), l01 = dot(r0[x].xyz, k), l02 = dot(r0[c2].xyz, k);
    float l10 = dot(r1[c0].xyz, k), l11 = dot(r1[x].xyz, k), l12 = dot(r1[c2].xyz, k);
    float l20 = dot(r2[c0].xyz, k), l21 = dot(r2[x].xyz, k), l22 = dot(r2[c2].xyz, k);
    /* g_ba: the value at (a / 2, b / 2) of the texel */
    float g01 = 0.5f * (l01 + l11), g10 = 0.5f * (l10 + l11), g12 = 0.5f * (l11 + l12), g21 = 0.5f * (l11 + l21);
    float g00 = 0.25f * (l00 + l01 + l10 + l11), g02 = 0.25f * (l01 + l02 + l11 + l12);
    float g20 = 0.25f * (l10 + l11 + l20 + l21), g22 = 0.25f * (l11 + l12 + l21 + l22);
    float top = g00 + 2.0f * g01 + g02 + g10 + 2.0f * l11 + g12; /* the two upper quarters' corner sums */
    float bottom = g10 + 2.0f * l11 + g12 + g20 + 2.0f * g21 + g22;
    if (!(top + bottom > 0.0f)) return d;
    float dx = d.x, dy = d.y;
    int qb = env_choose(top, bottom, &dy);
    /* the chosen half's rows of corner values: upper (e0 e1 e2) and lower (f0 f1 f2) */
    float e0 = qb ? g10 : g00, e1 = qb ? l11 : g01, e2 = qb ? g12 : g02;
    float f0 = qb ? g20 : g10, f1 = qb ? g21 : l11, f2 = qb ? g22 : g12;
    int qa = env_choose(e0 + e1 + f0 + f1, e1 + e2 + f1 + f2, &dx);
    float w00 = qa ? e1 : e0, w10 = qa ? e2 : e1, w01 = qa ? f1 : f0, w11 = qa ? f2 : f1;
    float t = env_sample_linear(dy, w00 + w10, w01 + w11);
    float s = env_sample_linear(dx, mix(w00, w01, t), mix(w10, w11, t));
    return (float2)(0.5f * ((float)qa + s), 0.5f * ((float)qb + t));
}

/* The point (u, v) of a map (width > 0, total > 0) that env_sample takes at u of the square:
 * the texel and the point across it (env_sample_texel, kernels/lights/environment_lanes.cl),
 * for the bilinear lookup moved inside the texel. */
inline float2 env_sample_uv(__constant const FcEnvironment* env, __global const float4* texels,
                            __global const float* dist, float2 u) {
    int x, y;
    float du, dv;
    env_sample_texel_l1(env->width, env->height, dist, u.x, u.y, &x, &y, &du, &dv);
    if (env->filter == FC_ENV_FILTER_BILINEAR) {
        float2 in = env_bilinear_in_texel(env, texels, x, y, (float2)(du, dv));
        du = in.x;
        dv = in.y;
    }
    return (float2)(((float)x + du) / (float)env->width, ((float)y + dv) / (float)env->height);
}

/* Samples a direction toward the environment: returns the radiance along it, `dir`
 * (world, unit) and its solid-angle pdf, which is 0 when nothing can be sampled (no
 * environment, a black map, or a direction that landed exactly on a pole). A map's sample
 * is env_sample_uv's point, turned into a direction (env_uv_to_dir) and located again for
 * the lookup (env_map_dir_radiance_pdf), so that its
 * radiance and pdf are those env_radiance_pdf gives that direction; the packet paths run the
 * same steps, the middle two in lanes. */
inline float3 env_sample(__constant const FcEnvironment* env, __global const float4* texels, __global const float* dist,
                         float2 u, float3* dir, float* pdf) {
    *dir = (float3)(0.0f, 1.0f, 0.0f);
    *pdf = 0.0f;
    if (!env->enabled) return (float3)(0.0f);
    if (env->width == 0) {
        if (is_black(load3c(env->scale))) return (float3)(0.0f);
        /* uniform sphere */
        u = clamp(u, 0.0f, FC_ONE_MINUS_EPSILON);
        float z = 1.0f - 2.0f * u.x;
        float r = safe_sqrt(1.0f - z * z);
        float2 sc = sincos_turns(u.y);
        *dir = (float3)(r * sc.y, r * sc.x, z);
        *pdf = FC_INV_4PI;
        return load3c(env->scale);
    }
    if (!(env->total > 0.0f)) return (float3)(0.0f);
    *dir = env_uv_to_dir(env, env_sample_uv(env, texels, dist, u));
    return env_map_dir_radiance_pdf(env, texels, dist, *dir, pdf);
}

#endif
