/* Test entry point for kernels/denoise/denoise.cl (tests/denoiser_test.cpp): the same filter
 * written directly, one pixel's whole window and every patch at once (O(window x patch)
 * colour terms a pixel), to check the offset-wise kernels against. */
#include "kernels/denoise/denoise.cl"

/* One half c (rgb, variance: as denoise_variance writes) denoised pixel by pixel. */
__kernel void denoise_direct(__constant const FcDenoiseParams* p, __global const float4* c,
                             __global const float4* albedo_depth, __global const float4* normal, __global float* out) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int w = (int)p->width, h = (int)p->height, r = (int)p->radius, pr = (int)p->patch_radius;
    int x = (int)gid % w, y = (int)gid / w;
    float k2 = p->k_color * p->k_color;
    float4 cp = c[gid];
    float3 correction = (float3)(0.0f);
    float weights = 0.0f;
    for (int qy = max(y - r, 0); qy <= min(y + r, h - 1); ++qy)
        for (int qx = max(x - r, 0); qx <= min(x + r, w - 1); ++qx) {
            uint q = (uint)(qy * w + qx);
            float d = denoise_feature_distance(p, albedo_depth[gid], normal[gid], albedo_depth[q], normal[q]);
            if (p->guides & FC_DENOISE_GUIDE_COLOR) {
                float s = 0.0f;
                for (int sy = -pr; sy <= pr; ++sy)
                    for (int sx = -pr; sx <= pr; ++sx) {
                        uint i = denoise_clamped(p, x + sx, y + sy);
                        int ix = (int)(i % p->width), iy = (int)(i / p->width);
                        s += denoise_color_term(c[i], c[denoise_clamped(p, ix + qx - x, iy + qy - y)], k2);
                    }
                d += fmax(s / (float)((2 * pr + 1) * (2 * pr + 1)), 0.0f);
            }
            float wq = exp(-d);
            correction += wq * (c[q].xyz - cp.xyz);
            weights += wq;
        }
    vstore3(cp.xyz + correction / weights, gid, out);
}
