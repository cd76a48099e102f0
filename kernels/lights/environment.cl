/* The environment light: radiance from infinitely far away, seen by escaping rays and
 * sampled by next-event estimation. Layout and direction convention: FcEnvironment in
 * kernels/shared/environment_layout.h; the host side (loading, sanitising, the distribution) is
 * host/scene/environment_map.cpp; docs/environment.md explains the whole.
 *
 * - Constant environment (width == 0): radiance `scale` from every direction, sampled
 *   uniformly over the sphere, pdf 1 / (4 pi) (0 when the radiance is black).
 * - Equirectangular map: nearest-texel lookup (the default: the radiance piecewise
 *   constant over the texels, like the sampling density) or bilinear between texel
 *   centres (`filter`, opt-in: smooth reflections, as Mitsuba 3 and Cycles look maps
 *   up; docs/environment.md says what it costs in noise). Sampling picks a texel from a
 *   piecewise-constant 2D distribution over luminance x sin(theta) (for the bilinear
 *   lookup the luminance integrated over the texel; a marginal cdf over
 *   rows, a conditional cdf per row; pbrt-v3 section 14.2.4, Pharr, Jakob, Humphreys
 *   2016) and a uniform point in it. The density in (u, v) converts to solid angle with
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

#define FC_INV_2PI 0.15915494309189533577f
#define FC_INV_4PI 0.07957747154594766788f
#define FC_INV_2PI2 0.05066059182116888572f /* 1 / (2 pi^2) */

/* World direction to the map's frame (rows of to_map). */
inline float3 env_dir_to_map(__constant const FcEnvironment* env, float3 d) {
    return (float3)(dot(load3c(env->to_map[0]), d), dot(load3c(env->to_map[1]), d), dot(load3c(env->to_map[2]), d));
}

/* The map's frame back to world (the transpose: to_map is a rotation). */
inline float3 env_map_to_dir(__constant const FcEnvironment* env, float3 m) {
    return m.x * load3c(env->to_map[0]) + m.y * load3c(env->to_map[1]) + m.z * load3c(env->to_map[2]);
}

/* Map-frame direction to (u, v) in [0, 1]^2:
 * d = (sin theta sin phi, cos theta, -sin theta cos phi), u = phi / 2pi, v = theta / pi.
 * Both angles by atan2_fast (kernels/util/trig.cl; theta from the horizontal length,
 * accurate near the poles where acos is not). */
inline float2 env_map_dir_to_uv(float3 m) {
    float phi = atan2_fast(m.x, -m.z);
    if (phi < 0.0f) phi += 2.0f * FC_PI;
    float theta = atan2_fast(sqrt(m.x * m.x + m.z * m.z), m.y);
    return (float2)(phi * FC_INV_2PI, theta * FC_INV_PI);
}

/* (u, v) to the map-frame direction: phi = 2 pi u and theta = pi v in turns. */
inline float3 env_uv_to_map_dir(float2 uv) {
    float2 sc_phi = sincos_turns(uv.x);
    float2 sc_theta = sincos_turns(0.5f * uv.y);
    return (float3)(sc_theta.x * sc_phi.x, sc_theta.y, -sc_theta.x * sc_phi.y);
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
    float3 m = env_dir_to_map(env, dir);
    *sin_theta = sqrt(m.x * m.x + m.z * m.z);
    *uv = env_map_dir_to_uv(m);
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

/* The solid-angle pdf of texel t at sin(theta) `sin_theta` (0 at the poles). */
inline float env_texel_pdf(__constant const FcEnvironment* env, __global const float* dist, int2 t, float sin_theta) {
    if (!(env->total > 0.0f) || !(sin_theta > 0.0f)) return 0.0f;
    __global const float* cond = dist + (env->height + 1) + t.y * (env->width + 1);
    float p_row = dist[t.y + 1] - dist[t.y];
    float p_col = cond[t.x + 1] - cond[t.x];
    float pdf = p_row * (float)env->height * p_col * (float)env->width * FC_INV_2PI2 / sin_theta;
    return isfinite(pdf) ? pdf : 0.0f;
}

/* Solid-angle density with which env_sample produces `dir`. The texel buffer is not
 * needed: the density lives in the cdfs. */
inline float env_pdf(__constant const FcEnvironment* env, __global const float* dist, float3 dir) {
    if (!env->enabled) return 0.0f;
    if (env->width == 0) return is_black(load3c(env->scale)) ? 0.0f : FC_INV_4PI;
    float sin_theta;
    float2 uv;
    int2 t = env_locate(env, dir, &sin_theta, &uv);
    return env_texel_pdf(env, dist, t, sin_theta);
}

/* env_radiance and env_pdf of one direction by one lookup (a ray that escaped after a
 * BSDF sample needs both). */
inline float3 env_radiance_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, float3 dir, float* pdf) {
    *pdf = 0.0f;
    if (!env->enabled) return (float3)(0.0f);
    float3 scale = load3c(env->scale);
    if (env->width == 0) {
        *pdf = is_black(scale) ? 0.0f : FC_INV_4PI;
        return scale;
    }
    float sin_theta;
    float2 uv;
    int2 t = env_locate(env, dir, &sin_theta, &uv);
    *pdf = env_texel_pdf(env, dist, t, sin_theta);
    return env_lookup(env, texels, uv, t) * scale;
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
 * table guide[0..g] (g = env_guide_size(n); entry k the interval holding k / g, as uint
 * bits; Chen & Asau 1974): floor(u g) / g <= u < (floor(u g) + 1) / g, so the answer lies
 * between entries k and k + 1, a step or two of bisection instead of log2(n). The same
 * interval as bisecting all of [0, n). */
inline int env_find_interval(__global const float* cdf, __global const float* guide, uint g, float u) {
    uint k = min((uint)(u * (float)g), g - 1u);
    return env_bisect(cdf, (int)as_uint(guide[k]), (int)as_uint(guide[k + 1u]) + 1, u);
}

/* u's position inside interval i of cdf, in [0, 1). */
inline float env_remap(__global const float* cdf, int i, float u) {
    float w = cdf[i + 1] - cdf[i];
    float t = (w > 0.0f) ? (u - cdf[i]) / w : 0.5f;
    return clamp(t, 0.0f, FC_ONE_MINUS_EPSILON);
}

/* Samples a direction toward the environment: returns the radiance along it, `dir`
 * (world, unit) and its solid-angle pdf, which is 0 when nothing can be sampled (no
 * environment, a black map, or a direction that landed exactly on a pole). */
inline float3 env_sample(__constant const FcEnvironment* env, __global const float4* texels, __global const float* dist,
                         float2 u, float3* dir, float* pdf) {
    u = clamp(u, 0.0f, FC_ONE_MINUS_EPSILON);
    *dir = (float3)(0.0f, 1.0f, 0.0f);
    *pdf = 0.0f;
    if (!env->enabled) return (float3)(0.0f);
    if (env->width == 0) {
        if (is_black(load3c(env->scale))) return (float3)(0.0f);
        /* uniform sphere */
        float z = 1.0f - 2.0f * u.x;
        float r = safe_sqrt(1.0f - z * z);
        float2 sc = sincos_turns(u.y);
        *dir = (float3)(r * sc.y, r * sc.x, z);
        *pdf = FC_INV_4PI;
        return load3c(env->scale);
    }
    if (!(env->total > 0.0f)) return (float3)(0.0f);
    /* row from the marginal cdf, column from the row's conditional cdf */
    int w = env->width, h = env->height;
    uint gm = env_guide_size((uint)h), gc = env_guide_size((uint)w);
    __global const float* guides = dist + (h + 1) + h * (w + 1);
    int y = env_find_interval(dist, guides, gm, u.y);
    float dv = env_remap(dist, y, u.y);
    __global const float* cond = dist + (h + 1) + y * (w + 1);
    int x = env_find_interval(cond, guides + (gm + 1u) + (uint)y * (gc + 1u), gc, u.x);
    float du = env_remap(cond, x, u.x);
    float2 uv = (float2)(((float)x + du) / (float)w, ((float)y + dv) / (float)h);
    *dir = normalize_or(env_map_to_dir(env, env_uv_to_map_dir(uv)), (float3)(0.0f, 1.0f, 0.0f));
    /* radiance and pdf of the direction produced, by the lookup of env_radiance/env_pdf */
    float sin_theta;
    float2 uv_back;
    int2 t = env_locate(env, *dir, &sin_theta, &uv_back);
    *pdf = env_texel_pdf(env, dist, t, sin_theta);
    return env_lookup(env, texels, uv_back, t) * load3c(env->scale);
}

#endif
