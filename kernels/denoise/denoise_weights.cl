/* The weights of facet's denoiser (kernels/denoise/denoise.cl), pair by pair: a joint
 * non-local-means filter whose weight for neighbour q of pixel p is exp(-(f + c)), with
 *   c  the colour term: the variance-normalised patch distance of Rousselle, Knaus and
 *      Zwicker, "Adaptive Rendering with Non-Local Means Filtering" (SIGGRAPH Asia 2012),
 *      eq. 6: max(0, the mean over the patch offsets s of e(p + s, q + s)), with
 *          e(i, j) = (du^2 - (v_i + min(v_i, v_j))) / (eps + k^2 (v_i + v_j)),
 *      du^2 the mean over channels of the squared colour difference and v the variance of
 *      the half's pixel mean. Pixels outside the image are clamped to its border, pixel
 *      and partner alike: the term at patch offset s is e(i, clamp(i + q - p)) with
 *      i = clamp(p + s), which makes the patch distance a box filter of the per-pixel term
 *      image of the offset q - p (the offset-wise formulation of denoise.cl)
 *   f  Gaussian terms on the albedo and normal differences (Euclidean, RGB and XYZ) and on
 *      the depth difference relative to the larger depth, as the feature terms of
 *      Rousselle et al. 2013 and Bitterli et al. 2016 ("Nonlinearly Weighted First-order
 *      Regression for Denoising Monte Carlo Renderings").
 * Colours are float4 (rgb, the variance of the half's pixel mean); features are two float4
 * a pixel: (albedo rgb, depth) and (normal xyz, 0). */
#ifndef FACET_DENOISE_DENOISE_WEIGHTS_CL
#define FACET_DENOISE_DENOISE_WEIGHTS_CL

#include "kernels/shared/denoise_layout.h"

/* The pixel index of (x, y) clamped into the image. */
inline uint denoise_clamped(__constant const FcDenoiseParams* p, int x, int y) {
    uint cx = (uint)clamp(x, 0, (int)p->width - 1), cy = (uint)clamp(y, 0, (int)p->height - 1);
    return cy * p->width + cx;
}

/* The colour term e(i, j) of pixels i and j (k2: k^2). */
inline float denoise_color_term(float4 ci, float4 cj, float k2) {
    float3 d = ci.xyz - cj.xyz;
    float vi = ci.w, vj = cj.w;
    return (dot(d, d) * (1.0f / 3.0f) - (vi + fmin(vi, vj))) / (1e-10f + k2 * (vi + vj));
}

/* The feature terms' distance f between pixels i and j (albedo_depth and normal of each). */
inline float denoise_feature_distance(__constant const FcDenoiseParams* p, float4 ai, float4 ni, float4 aj, float4 nj) {
    float d = 0.0f;
    if (p->guides & FC_DENOISE_GUIDE_ALBEDO) {
        float3 e = ai.xyz - aj.xyz;
        d += dot(e, e) / (2.0f * p->sigma_albedo * p->sigma_albedo);
    }
    if (p->guides & FC_DENOISE_GUIDE_NORMAL) {
        float3 e = ni.xyz - nj.xyz;
        d += dot(e, e) / (2.0f * p->sigma_normal * p->sigma_normal);
    }
    if (p->guides & FC_DENOISE_GUIDE_DEPTH) {
        float s = p->sigma_depth * fmax(ai.w, aj.w);
        if (s > 0.0f) d += (ai.w - aj.w) * (ai.w - aj.w) / (2.0f * s * s);
    }
    return d;
}

#endif
