/* Test entry point for kernels/denoise/denoise.cl (tests/denoiser_test.cpp): the same filter
 * written directly, one pixel at a time, its whole window and every patch (O(window x
 * patch) colour terms a pixel), on the planes denoise_prepare makes, to check the
 * offset-wise kernels against. */
#include "kernels/denoise/denoise.cl"

/* Half k's colour at image pixel (x, y) clamped into the image, in every lane. */
inline DenoiseColor direct_color(__constant const FcDenoiseParams* p, __global const float* colour, uint k, int x,
                                 int y) {
    uint at = denoise_padded(p, clamp(x, 0, (int)p->width - 1), clamp(y, 0, (int)p->height - 1));
    __global const float* c = colour + 4 * k * p->plane + at;
    DenoiseColor v = {(float8)(c[0]), (float8)(c[p->plane]), (float8)(c[2 * p->plane]), (float8)(c[3 * p->plane])};
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
                             __global const float* features, uint k, __global float* out) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int w = (int)p->width, h = (int)p->height, r = (int)p->radius, pr = (int)p->patch_radius;
    int x = (int)gid % w, y = (int)gid / w;
    float k2 = p->k_color * p->k_color, inv_patch = 1.0f / (float)((2 * pr + 1) * (2 * pr + 1));
    DenoiseColor cp = direct_color(p, colour, k, x, y);
    float3 correction = (float3)(0.0f);
    float weights = 0.0f;
    for (int qy = max(y - r, 0); qy <= min(y + r, h - 1); ++qy)
        for (int qx = max(x - r, 0); qx <= min(x + r, w - 1); ++qx) {
            float d =
                denoise_feature_distance(p, direct_feature(p, features, x, y), direct_feature(p, features, qx, qy)).s0;
            if (p->guides & FC_DENOISE_GUIDE_COLOR) {
                float s = 0.0f;
                for (int sy = -pr; sy <= pr; ++sy)
                    for (int sx = -pr; sx <= pr; ++sx)
                        s += denoise_color_term(direct_color(p, colour, k, x + sx, y + sy),
                                                direct_color(p, colour, k, qx + sx, qy + sy), k2)
                                 .s0;
                d += fmax(s * inv_patch, 0.0f);
            }
            float wq = exp(-d);
            DenoiseColor cq = direct_color(p, colour, k, qx, qy);
            correction += wq * (float3)(cq.r.s0 - cp.r.s0, cq.g.s0 - cp.g.s0, cq.b.s0 - cp.b.s0);
            weights += wq;
        }
    vstore3((float3)(cp.r.s0, cp.g.s0, cp.b.s0) + correction / weights, gid, out);
}
