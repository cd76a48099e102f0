/* The weights of facet's denoiser (kernels/denoise/denoise.cl), for 8 pixel pairs at once
 * (float8 lanes; the direct test filter broadcasts one pair). A joint non-local-means
 * filter: the weight of neighbour q for pixel p is exp(-(f + c)), with
 *   c  the colour term: the variance-normalised patch distance of Rousselle, Knaus and
 *      Zwicker, "Adaptive Rendering with Non-Local Means Filtering" (SIGGRAPH Asia 2012),
 *      eq. 6: max(0, the mean over the patch offsets s of e(p + s, q + s)), with
 *          e(i, j) = (du^2 - (v_i + min(v_i, v_j))) / (eps + k^2 (v_i + v_j)),
 *      du^2 the mean over channels of the squared colour difference and v the variance of
 *      the half's pixel mean; pixels outside the image read the nearest border pixel
 *   f  Gaussian terms on the albedo and normal differences (Euclidean, RGB and XYZ) and on
 *      the depth difference relative to the larger depth, as the feature terms of
 *      Rousselle et al. 2013 and Bitterli et al. 2016 ("Nonlinearly Weighted First-order
 *      Regression for Denoising Monte Carlo Renderings"). */
#ifndef FACET_DENOISE_DENOISE_WEIGHTS_CL
#define FACET_DENOISE_DENOISE_WEIGHTS_CL

#include "kernels/shared/denoise_layout.h"

/* 8 floats from any 4-byte-aligned address, and back. PoCL 3.1's vload8 became four
 * 64-bit loads, two shuffles and an insert (objdump of denoise_accumulate: 288 vmovsd, 72
 * vmovlhps, 36 vinsertf128); a float8 type aligned to 4 bytes (a clang extension) is read
 * and written as one unaligned vector access. Other compilers take vload8 / vstore8. */
#if defined(__clang__)
typedef float8 denoise_float8_u __attribute__((aligned(4)));
inline float8 denoise_load8(__global const float* p) { return *(__global const denoise_float8_u*)p; }
inline void denoise_store8(float8 v, __global float* p) { *(__global denoise_float8_u*)p = v; }
#else
inline float8 denoise_load8(__global const float* p) { return vload8(0, p); }
inline void denoise_store8(float8 v, __global float* p) { vstore8(v, 0, p); }
#endif

/* One half's colour and the variance of its pixel mean. */
typedef struct DenoiseColor {
    float8 r, g, b, v;
} DenoiseColor;

/* The guides: albedo, normal, depth. */
typedef struct DenoiseFeature {
    float8 ar, ag, ab, nx, ny, nz, z;
} DenoiseFeature;

/* The colour term e(i, j) of pixels i and j (k2: k^2). */
inline float8 denoise_color_term(DenoiseColor i, DenoiseColor j, float k2) {
    float8 dr = i.r - j.r, dg = i.g - j.g, db = i.b - j.b;
    float8 du2 = (dr * dr + dg * dg + db * db) * (1.0f / 3.0f);
    return (du2 - (i.v + fmin(i.v, j.v))) / (1e-10f + k2 * (i.v + j.v));
}

/* The feature terms' scales, 1 / (2 sigma^2) of each guide that is on (0 where it is off),
 * computed once per work item, not once per neighbour (a sigma not above 0 turns its
 * guide off). */
typedef struct DenoiseFeatureScale {
    float albedo, normal, depth;
} DenoiseFeatureScale;

inline DenoiseFeatureScale denoise_feature_scale(__constant const FcDenoiseParams* p) {
    DenoiseFeatureScale s = {0.0f, 0.0f, 0.0f};
    if ((p->guides & FC_DENOISE_GUIDE_ALBEDO) && p->sigma_albedo > 0.0f)
        s.albedo = 1.0f / (2.0f * p->sigma_albedo * p->sigma_albedo);
    if ((p->guides & FC_DENOISE_GUIDE_NORMAL) && p->sigma_normal > 0.0f)
        s.normal = 1.0f / (2.0f * p->sigma_normal * p->sigma_normal);
    if ((p->guides & FC_DENOISE_GUIDE_DEPTH) && p->sigma_depth > 0.0f)
        s.depth = 1.0f / (2.0f * p->sigma_depth * p->sigma_depth);
    return s;
}

/* The feature terms' distance f between pixels i and j: the depth difference is relative
 * to the larger depth (0 where both are 0, nothing hit). */
inline float8 denoise_feature_distance(DenoiseFeatureScale s, DenoiseFeature i, DenoiseFeature j) {
    float8 er = i.ar - j.ar, eg = i.ag - j.ag, eb = i.ab - j.ab;
    float8 ex = i.nx - j.nx, ey = i.ny - j.ny, ez = i.nz - j.nz;
    float8 z = fmax(i.z, j.z), dz = i.z - j.z;
    float8 depth = select((float8)(0.0f), dz * dz / (z * z), z > 0.0f);
    return (er * er + eg * eg + eb * eb) * s.albedo + (ex * ex + ey * ey + ez * ez) * s.normal + depth * s.depth;
}

/* The variance estimate's box, split into a row pass and a column pass: the sum over the
 * row segment of (2 r + 1) pixels around (x, y), clipped at the border, of a half's
 * variance source (1 float a pixel, width w: summed over channels,
 * host/denoise/denoise_variance.hpp)... */
inline float denoise_variance_row(__global const float* source, int w, int r, int x, int y) {
    int x0 = max(x - r, 0), x1 = min(x + r, w - 1);
    float sum = 0.0f;
    for (int qx = x0; qx <= x1; ++qx) sum += source[y * w + qx];
    return sum;
}

/* ... and the mean over channels and over the box of (2 r + 1)^2 pixels around (x, y) from
 * those row sums (`rows`, 1 float a pixel, width w, height h). */
inline float denoise_box_variance(__global const float* rows, int w, int h, int r, int x, int y) {
    int x0 = max(x - r, 0), x1 = min(x + r, w - 1), y0 = max(y - r, 0), y1 = min(y + r, h - 1);
    float sum = 0.0f;
    for (int qy = y0; qy <= y1; ++qy) sum += rows[qy * w + x];
    return sum / (3.0f * (float)((x1 - x0 + 1) * (y1 - y0 + 1)));
}

#endif
