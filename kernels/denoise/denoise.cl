/* facet's denoiser: the joint non-local-means filter of denoise_weights.cl applied to both
 * half-images at once, each half with its own colour weights (the feature terms are shared).
 * The output of pixel p is
 *     c_p + sum_q w_q (c_q - c_p) / sum_q w_q
 * over the window of (2 radius + 1)^2 pixels clipped at the image border, written as a
 * correction of c_p so that a constant image comes out exactly (w_p = 1).
 *
 * Offset-wise (as Rousselle et al. 2012, sec. 5, compute NL-means): for each window offset
 * o the per-pixel colour term image e(i, clamp(i + o)) is computed once (denoise_terms),
 * and each pixel's patch distance is the box sum of that image around it
 * (denoise_accumulate), so the divisions cost O(window) a pixel instead of
 * O(window x patch). One launch of each kernel covers the 2 radius + 1 offsets of one window
 * row. Kernels:
 *   denoise_variance    each half's colour with the variance of its pixel mean
 *   denoise_terms       the colour terms of one window row's offsets
 *   denoise_accumulate  weights and weighted sums of one window row
 *   denoise_finish      the denoised halves
 * The variance comes from the two half-images: E[(a - b)^2] = Var(a) + Var(b), the mean over
 * channels and over a box of (2 variance_radius + 1)^2 pixels. One work item a pixel, top
 * row first. */
#ifndef FACET_DENOISE_DENOISE_CL
#define FACET_DENOISE_DENOISE_CL

#include "kernels/denoise/denoise_weights.cl"

/* ca, cb: the halves a and b (rgb) with the variance of each one's pixel mean in w. */
__kernel void denoise_variance(__constant const FcDenoiseParams* p, __global const float4* a, __global const float4* b,
                               __global float4* ca, __global float4* cb) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int w = (int)p->width, h = (int)p->height, r = (int)p->variance_radius;
    int x = (int)gid % w, y = (int)gid / w;
    int x0 = max(x - r, 0), x1 = min(x + r, w - 1), y0 = max(y - r, 0), y1 = min(y + r, h - 1);
    float sum = 0.0f;
    for (int qy = y0; qy <= y1; ++qy)
        for (int qx = x0; qx <= x1; ++qx) {
            uint q = (uint)(qy * w + qx);
            float3 d = a[q].xyz - b[q].xyz;
            sum += dot(d, d);
        }
    float mean = sum / (3.0f * (float)((x1 - x0 + 1) * (y1 - y0 + 1)));
    ca[gid] = (float4)(a[gid].xyz, p->variance_scale_a * mean);
    cb[gid] = (float4)(b[gid].xyz, p->variance_scale_b * mean);
}

/* terms[(dx + radius) pixels + i] = (e_a, e_b): the colour terms of both halves between
 * pixel i and clamp(i + (dx, dy)), for dx = -radius..radius. */
__kernel void denoise_terms(__constant const FcDenoiseParams* p, __global const float4* ca, __global const float4* cb,
                            __global float2* terms, int dy) {
    uint gid = get_global_id(0), pixels = p->width * p->height;
    if (gid >= pixels) return;
    int w = (int)p->width, r = (int)p->radius, x = (int)gid % w, y = (int)gid / w;
    float k2 = p->k_color * p->k_color;
    float4 pa = ca[gid], pb = cb[gid];
    uint row = (uint)clamp(y + dy, 0, (int)p->height - 1) * p->width;
    for (int dx = -r; dx <= r; ++dx) {
        uint j = row + (uint)clamp(x + dx, 0, w - 1);
        terms[(uint)(dx + r) * pixels + gid] =
            (float2)(denoise_color_term(pa, ca[j], k2), denoise_color_term(pb, cb[j], k2));
    }
}

/* Adds the neighbours of window row dy to each half's sums: (sum w (c_q - c_p), sum w).
 * terms: denoise_terms of the same dy (not read without the colour guide). */
__kernel void denoise_accumulate(__constant const FcDenoiseParams* p, __global const float4* ca,
                                 __global const float4* cb, __global const float4* albedo_depth,
                                 __global const float4* normal, __global const float2* terms, __global float4* sum_a,
                                 __global float4* sum_b, int dy) {
    uint gid = get_global_id(0), pixels = p->width * p->height;
    if (gid >= pixels) return;
    int w = (int)p->width, h = (int)p->height, r = (int)p->radius, x = (int)gid % w, y = (int)gid / w;
    if (y + dy < 0 || y + dy >= h) return;
    int pr = (int)p->patch_radius;
    float inv_patch = 1.0f / (float)((2 * pr + 1) * (2 * pr + 1));
    bool color = (p->guides & FC_DENOISE_GUIDE_COLOR) != 0u;
    float4 pa = ca[gid], pb = cb[gid], fa = albedo_depth[gid], fn = normal[gid];
    float4 sa = sum_a[gid], sb = sum_b[gid];
    uint row = (uint)((y + dy) * w);
    for (int dx = max(-r, -x); dx <= min(r, w - 1 - x); ++dx) {
        uint q = row + (uint)(x + dx);
        float f = denoise_feature_distance(p, fa, fn, albedo_depth[q], normal[q]);
        float2 d = (float2)(f);
        if (color) {
            /* The patch distance: the box sum of the offset's term image around p */
            __global const float2* t = terms + (uint)(dx + r) * pixels;
            float2 s = (float2)(0.0f);
            for (int sy = -pr; sy <= pr; ++sy)
                for (int sx = -pr; sx <= pr; ++sx) s += t[denoise_clamped(p, x + sx, y + sy)];
            d += fmax(s * inv_patch, (float2)(0.0f));
        }
        float wa = exp(-d.x), wb = exp(-d.y);
        sa += wa * (float4)(ca[q].xyz - pa.xyz, 1.0f);
        sb += wb * (float4)(cb[q].xyz - pb.xyz, 1.0f);
    }
    sum_a[gid] = sa;
    sum_b[gid] = sb;
}

/* The denoised halves, 3 floats a pixel: c_p + the weighted mean correction. */
__kernel void denoise_finish(__constant const FcDenoiseParams* p, __global const float4* ca, __global const float4* cb,
                             __global const float4* sum_a, __global const float4* sum_b, __global float* out_a,
                             __global float* out_b) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    float4 sa = sum_a[gid], sb = sum_b[gid];
    vstore3(ca[gid].xyz + sa.xyz / sa.w, gid, out_a);
    vstore3(cb[gid].xyz + sb.xyz / sb.w, gid, out_b);
}

#endif
