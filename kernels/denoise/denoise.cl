/* A feature-guided denoiser for one half-image: a joint non-local-means filter whose
 * weights read the colour, its variance and the AOV features (albedo, normal, depth).
 *   colour   the variance-normalised patch distance of Rousselle, Knaus and Zwicker,
 *            "Adaptive Rendering with Non-Local Means Filtering" (SIGGRAPH Asia 2012),
 *            eq. 6: d = mean over the patch of
 *                (du^2 - (v_p + min(v_p, v_q))) / (eps + k^2 (v_p + v_q)),
 *            with du^2 the mean over channels of the squared colour difference and v the
 *            variance of the half's pixel mean; weight exp(-max(d, 0))
 *   features Gaussian weights on the albedo and normal differences (Euclidean, RGB and
 *            XYZ) and on the depth difference relative to the larger depth, as the
 *            feature terms of Rousselle et al. 2013 and Bitterli et al. 2016 ("Nonlinearly
 *            Weighted First-order Regression for Denoising Monte Carlo Renderings")
 * The window is (2 radius + 1)^2 pixels, clipped at the image border. The output is
 *     c_p + sum_q w_q (c_q - c_p) / sum_q w_q,
 * written as a correction of c_p so that a constant image comes out exactly (w_p = 1, so
 * the sum of weights is at least 1). The variance comes from the two half-images:
 * E[(a - b)^2] = Var(a) + Var(b), smoothed over a box (denoise_variance). Images are 3
 * floats a pixel (variance and depth 1), top row first. */
#ifndef FACET_DENOISE_DENOISE_CL
#define FACET_DENOISE_DENOISE_CL

#include "kernels/shared/denoise_layout.h"
#include "kernels/util/math.cl"

/* The pixel index of (x, y) clamped into the image. */
inline uint denoise_clamped(__constant const FcDenoiseParams* p, int x, int y) {
    uint cx = (uint)clamp(x, 0, (int)p->width - 1), cy = (uint)clamp(y, 0, (int)p->height - 1);
    return cy * p->width + cx;
}

/* The variance of one half's pixel means (mean over channels), from the halves a and b:
 * variance_scale x the box mean of (a - b)^2 over (2 variance_radius + 1)^2 pixels. */
__kernel void denoise_variance(__constant const FcDenoiseParams* p, __global const float* a, __global const float* b,
                               __global float* variance) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int x = (int)(gid % p->width), y = (int)(gid / p->width), r = (int)p->variance_radius;
    float sum = 0.0f;
    int count = 0;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= (int)p->width || qy >= (int)p->height) continue;
            uint q = (uint)qy * p->width + (uint)qx;
            float3 d = load3(a + 3 * q) - load3(b + 3 * q);
            sum += dot(d, d) * (1.0f / 3.0f);
            ++count;
        }
    variance[gid] = p->variance_scale * sum / (float)max(count, 1);
}

/* The colour term's distance between the patches around pixels (px, py) and (qx, qy). */
inline float denoise_color_distance(__constant const FcDenoiseParams* p, __global const float* color,
                                    __global const float* variance, int px, int py, int qx, int qy) {
    int r = (int)p->patch_radius;
    float k2 = p->k_color * p->k_color, sum = 0.0f;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            uint i = denoise_clamped(p, px + dx, py + dy), j = denoise_clamped(p, qx + dx, qy + dy);
            float3 d = load3(color + 3 * i) - load3(color + 3 * j);
            float vp = variance[i], vq = variance[j];
            sum += (dot(d, d) * (1.0f / 3.0f) - (vp + fmin(vp, vq))) / (1e-10f + k2 * (vp + vq));
        }
    return fmax(sum / (float)((2 * r + 1) * (2 * r + 1)), 0.0f);
}

/* The feature terms' distance between pixels i and j (the exponent of their weight). */
inline float denoise_feature_distance(__constant const FcDenoiseParams* p, __global const float* albedo,
                                      __global const float* normal, __global const float* depth, uint i, uint j) {
    float d = 0.0f;
    if (p->guides & FC_DENOISE_GUIDE_ALBEDO) {
        float3 e = load3(albedo + 3 * i) - load3(albedo + 3 * j);
        d += dot(e, e) / (2.0f * p->sigma_albedo * p->sigma_albedo);
    }
    if (p->guides & FC_DENOISE_GUIDE_NORMAL) {
        float3 e = load3(normal + 3 * i) - load3(normal + 3 * j);
        d += dot(e, e) / (2.0f * p->sigma_normal * p->sigma_normal);
    }
    if (p->guides & FC_DENOISE_GUIDE_DEPTH) {
        float zi = depth[i], zj = depth[j], s = p->sigma_depth * fmax(zi, zj);
        if (s > 0.0f) d += (zi - zj) * (zi - zj) / (2.0f * s * s);
    }
    return d;
}

/* One pixel of the denoised half: the weighted mean over its window (one work item a pixel). */
__kernel void denoise_filter(__constant const FcDenoiseParams* p, __global const float* color,
                             __global const float* variance, __global const float* albedo, __global const float* normal,
                             __global const float* depth, __global float* out) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int x = (int)(gid % p->width), y = (int)(gid / p->width), r = (int)p->radius;
    float3 c = load3(color + 3 * gid), correction = (float3)(0.0f);
    float weights = 0.0f;
    for (int qy = max(y - r, 0); qy <= min(y + r, (int)p->height - 1); ++qy)
        for (int qx = max(x - r, 0); qx <= min(x + r, (int)p->width - 1); ++qx) {
            uint q = (uint)qy * p->width + (uint)qx;
            float d = denoise_feature_distance(p, albedo, normal, depth, gid, q);
            if (p->guides & FC_DENOISE_GUIDE_COLOR) d += denoise_color_distance(p, color, variance, x, y, qx, qy);
            float w = exp(-d);
            correction += w * (load3(color + 3 * q) - c);
            weights += w;
        }
    float3 v = c + correction / weights;
    out[3 * gid + 0] = v.x;
    out[3 * gid + 1] = v.y;
    out[3 * gid + 2] = v.z;
}

#endif
