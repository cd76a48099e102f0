/* Test kernels for tests/environment_test.cpp and tests/environment_chi2_test.cpp:
 * batches of env_sample / env_radiance / env_pdf, the chi-square binning of samples in
 * the map's texel grid, the rotation round trip and a throughput loop. */
#include "kernels/lights/environment.cl"
#include "kernels/util/rng.cl"

/* One sample per work-item: (dir, pdf) and radiance as returned by env_sample, and
 * (env_radiance, env_pdf) evaluated again at the sampled direction. */
__kernel void env_sample_batch(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, uint seed, __global float4* dir_pdf,
                               __global float4* radiance, __global float4* eval) {
    uint i = (uint)get_global_id(0);
    Rng rng = rng_init(seed, i, 0x656eu);
    float3 dir;
    float pdf;
    float3 L = env_sample(env, texels, dist, rng_float2(&rng), &dir, &pdf);
    dir_pdf[i] = (float4)(dir, pdf);
    radiance[i] = (float4)(L, 0.0f);
    eval[i] = (float4)(env_radiance(env, texels, dir), env_pdf(env, texels, dist, dir));
}

/* (env_radiance, env_pdf) at each direction of `dirs` (xyz). */
__kernel void env_eval_batch(__constant const FcEnvironment* env, __global const float4* texels,
                             __global const float* dist, __global const float4* dirs, __global float4* out) {
    uint i = (uint)get_global_id(0);
    float3 d = dirs[i].xyz;
    out[i] = (float4)(env_radiance(env, texels, d), env_pdf(env, texels, dist, d));
}

/* At each direction of `dirs` (xyz): (env_pdf, its row's bound env_row_pdf_bound, the row, 0). */
__kernel void env_row_bounds(__constant const FcEnvironment* env, __global const float4* texels,
                             __global const float* dist, __global const float4* dirs, __global float4* out) {
    uint i = (uint)get_global_id(0);
    float3 d = dirs[i].xyz;
    float sin_theta;
    float2 uv;
    const int2 t = env_locate(env, d, &sin_theta, &uv);
    out[i] = (float4)(env_pdf(env, texels, dist, d), env_row_pdf_bound(env, dist, t.y, sin_theta), (float)t.y, 0.0f);
}

/* `per_item` samples per work-item, each binned by its texel in blocks of bu x bv
 * texels: bin = (y / bv) * (width / bu) + x / bu, with `cells` = the number of bins for
 * a refused sample (pdf 0) and cells + 1 for an invalid one (non-finite or negative).
 * The texel is found from the map-frame direction by the documented convention; with
 * sub > 1 the "texels" are those of a grid sub times finer (sub x sub cells a texel). */
__kernel void env_sample_bins(__constant const FcEnvironment* env, __global const float4* texels,
                              __global const float* dist, uint seed, uint per_item, int bu, int bv, __global uint* bins,
                              int sub) {
    uint g = (uint)get_global_id(0);
    Rng rng = rng_init(seed, g, 0x6368u);
    int w = env->width * sub, h = env->height * sub;
    uint cells = (uint)((w / bu) * (h / bv));
    for (uint k = 0; k < per_item; ++k) {
        float3 dir;
        float pdf;
        float3 L = env_sample(env, texels, dist, rng_float2(&rng), &dir, &pdf);
        uint bin;
        if (!isfinite(pdf) || pdf < 0.0f || !all_finite(L) || !all_finite(dir) || L.x < 0.0f || L.y < 0.0f ||
            L.z < 0.0f) {
            bin = cells + 1u;
        } else if (pdf == 0.0f) {
            bin = cells;
        } else {
            float3 m = env_dir_to_map(env, dir);
            float phi = atan2(m.x, -m.z);
            phi = phi < 0.0f ? phi + 2.0f * FC_PI : phi;
            int x = clamp((int)(phi / (2.0f * FC_PI) * (float)w), 0, w - 1);
            int y = clamp((int)(acos(clamp(m.y, -1.0f, 1.0f)) / FC_PI * (float)h), 0, h - 1);
            bin = (uint)((y / bv) * (w / bu) + x / bu);
        }
        bins[g * per_item + k] = bin;
    }
}

/* World -> map -> world and world -> (u, v) -> world: the larger error of the two. */
__kernel void env_round_trip(__constant const FcEnvironment* env, __global const float4* dirs, __global float* err) {
    uint i = (uint)get_global_id(0);
    float3 d = dirs[i].xyz;
    float3 m = env_dir_to_map(env, d);
    float3 back = env_map_to_dir(env, m);
    float3 via_uv = env_map_to_dir(env, env_uv_to_map_dir(env_map_dir_to_uv(m)));
    err[i] = fmax(length(back - d), length(via_uv - d));
}

/* For each u: the interval env_find_interval finds through the guide tables and the one
 * bisecting the whole cdf finds, for the marginal cdf and for the middle row's conditional
 * cdf; and env_guide_size(i + 1), which the host computes in its own form. */
__kernel void env_guided_search(__constant const FcEnvironment* env, __global const float* dist,
                                __global const float* us, __global int4* found, __global uint* sizes) {
    uint i = (uint)get_global_id(0);
    int w = env->width, h = env->height;
    __global const float* guides = dist + (h + 1) + h * (w + 1);
    __global const float* cond = dist + (h + 1) + (h / 2) * (w + 1);
    uint gm = env_guide_size((uint)h), gc = env_guide_size((uint)w);
    float u = us[i];
    found[i] = (int4)(env_find_interval(dist, guides, gm, u), env_bisect(dist, 0, h, u),
                      env_find_interval(cond, guides + (gm + 1u) + (uint)(h / 2) * (gc + 1u), gc, u),
                      env_bisect(cond, 0, w, u));
    sizes[i] = env_guide_size(i + 1u);
}

/* env_sample_texel at the packets' widths, 8 and 16 (kernels/lights/environment_lanes.cl, its
 * gathers those of the CPU where it has them), beside its W = 1 form. */
#define FC_LW 8
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/vec3_lanes.cl"
#include "kernels/util/trig_lanes.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/environment_lanes.cl"
#include "kernels/lanes/lanes_close.cl"
#define FC_LW 16
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/vec3_lanes.cl"
#include "kernels/util/trig_lanes.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/environment_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

/* Work-item i finds the texels of the points (ux, uy)[16 i .. 16 i + 15]: texel[3 k + m] and
 * across[3 k + m] ((x, y) and (du, dv) of point k) at W = 1 (m = 0), 8 (m = 1) and 16 (m = 2). */
__kernel void env_sample_texel_lanes(__constant const FcEnvironment* env, __global const float* dist,
                                     __global const float* ux, __global const float* uy, __global int2* texel,
                                     __global float2* across) {
    const uint i = (uint)get_global_id(0);
    const int w = env->width, h = env->height;
    int xa[3][16], ya[3][16];
    float ua[3][16], va[3][16];
    for (int j = 0; j < 16; ++j)
        env_sample_texel_l1(w, h, dist, ux[16u * i + j], uy[16u * i + j], &xa[0][j], &ya[0][j], &ua[0][j], &va[0][j]);
    for (uint part = 0u; part < 2u; ++part) {
        int8 x, y;
        float8 du, dv;
        env_sample_texel_l8(w, h, dist, vload8(2u * i + part, ux), vload8(2u * i + part, uy), &x, &y, &du, &dv);
        vstore8(x, part, xa[1]), vstore8(y, part, ya[1]), vstore8(du, part, ua[1]), vstore8(dv, part, va[1]);
    }
    int16 x, y;
    float16 du, dv;
    env_sample_texel_l16(w, h, dist, vload16(i, ux), vload16(i, uy), &x, &y, &du, &dv);
    vstore16(x, 0, xa[2]), vstore16(y, 0, ya[2]), vstore16(du, 0, ua[2]), vstore16(dv, 0, va[2]);
    for (int j = 0; j < 16; ++j)
        for (int m = 0; m < 3; ++m) {
            texel[3u * (16u * i + j) + m] = (int2)(xa[m][j], ya[m][j]);
            across[3u * (16u * i + j) + m] = (float2)(ua[m][j], va[m][j]);
        }
}
