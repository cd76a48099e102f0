/* Test entry point for kernels/denoise/denoise.cl (tests/denoiser_test.cpp): the same filter
 * written directly, one pixel at a time, its whole window and every patch (O(window x
 * patch) colour terms a pixel), and the variance estimate as one 2-D box of its source,
 * reading only the colours and features of the planes denoise_prepare makes, to check the
 * offset-wise kernels and the separable variance box against. */
#include "kernels/denoise/denoise.cl"

/* The variance of half k's pixel mean at image pixel (x, y): the mean over channels and
 * over the box of (2 variance_radius + 1)^2 pixels clipped at the border of half k's
 * variance source (`source`: 1 float a pixel summed over channels, half a's plane then
 * half b's), times the half's scale. */
inline float direct_variance(__constant const FcDenoiseParams* p, __global const float* source, uint k, int x, int y) {
    int w = (int)p->width, h = (int)p->height, r = (int)p->variance_radius;
    int x0 = max(x - r, 0), x1 = min(x + r, w - 1), y0 = max(y - r, 0), y1 = min(y + r, h - 1);
    __global const float* plane = source + k * (uint)(w * h);
    float sum = 0.0f;
    for (int qy = y0; qy <= y1; ++qy)
        for (int qx = x0; qx <= x1; ++qx) sum += plane[qy * w + qx];
    float mean = sum / (3.0f * (float)((x1 - x0 + 1) * (y1 - y0 + 1)));
    return (k == 0u ? p->variance_scale_a : p->variance_scale_b) * mean;
}

/* Half k's colour and variance at image pixel (x, y) clamped into the image, in every
 * lane. */
inline DenoiseColor direct_color(__constant const FcDenoiseParams* p, __global const float* colour,
                                 __global const float* source, uint k, int x, int y) {
    x = clamp(x, 0, (int)p->width - 1), y = clamp(y, 0, (int)p->height - 1);
    __global const float* c = colour + 4 * k * p->plane + denoise_padded(p, x, y);
    DenoiseColor v = {(float8)(c[0]), (float8)(c[p->plane]), (float8)(c[2 * p->plane]),
                      (float8)(direct_variance(p, source, k, x, y))};
    return v;
}

/* The features at image pixel (x, y), in every lane. */
inline DenoiseFeature direct_feature(__constant const FcDenoiseParams* p, __global const float* features, int x,
                                     int y) {
    __global const float* f = features + denoise_padded(p, x, y);
    uint n = p->plane;
    DenoiseFeature v = {(float8)(f[0]),     (float8)(f[n]),     (float8)(f[2 * n]), (float8)(f[3 * n]),
                        (float8)(f[4 * n]), (float8)(f[5 * n]), (float8)(f[6 * n])};
    return v;
}

/* One pixel of half k denoised directly, 3 floats a pixel. */
__kernel void denoise_direct(__constant const FcDenoiseParams* p, __global const float* colour,
                             __global const float* features, __global const float* source, uint k,
                             __global float* out) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int w = (int)p->width, h = (int)p->height, r = (int)p->radius, pr = (int)p->patch_radius;
    int x = (int)gid % w, y = (int)gid / w;
    float k2 = p->k_color * p->k_color, inv_patch = 1.0f / (float)((2 * pr + 1) * (2 * pr + 1));
    DenoiseColor cp = direct_color(p, colour, source, k, x, y);
    float3 correction = (float3)(0.0f);
    float weights = 0.0f;
    for (int qy = max(y - r, 0); qy <= min(y + r, h - 1); ++qy)
        for (int qx = max(x - r, 0); qx <= min(x + r, w - 1); ++qx) {
            float d = denoise_feature_distance(denoise_feature_scale(p), direct_feature(p, features, x, y),
                                               direct_feature(p, features, qx, qy))
                          .s0;
            if (p->guides & FC_DENOISE_GUIDE_COLOR) {
                float s = 0.0f;
                for (int sy = -pr; sy <= pr; ++sy)
                    for (int sx = -pr; sx <= pr; ++sx)
                        s += denoise_color_term(direct_color(p, colour, source, k, x + sx, y + sy),
                                                direct_color(p, colour, source, k, qx + sx, qy + sy), k2)
                                 .s0;
                d += fmax(s * inv_patch, 0.0f);
            }
            float wq = exp(-d);
            DenoiseColor cq = direct_color(p, colour, source, k, qx, qy);
            correction += wq * (float3)(cq.r.s0 - cp.r.s0, cq.g.s0 - cp.g.s0, cq.b.s0 - cp.b.s0);
            weights += wq;
        }
    vstore3((float3)(cp.r.s0, cp.g.s0, cp.b.s0) + correction / weights, gid, out);
}
