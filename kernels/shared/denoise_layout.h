/* Parameters of the feature-guided denoiser (kernels/denoise/denoise.cl), passed as one
 * __constant struct. */
#ifndef FACET_SHARED_DENOISE_H
#define FACET_SHARED_DENOISE_H

#include "kernels/shared/types.h"

/* The guides a weight reads, as bits of FcDenoiseParams.guides; all on by default. The
 * tests turn them off one by one to show what each keeps. */
#define FC_DENOISE_GUIDE_ALBEDO 1u
#define FC_DENOISE_GUIDE_NORMAL 2u
#define FC_DENOISE_GUIDE_DEPTH 4u
#define FC_DENOISE_GUIDE_COLOR 8u /* the variance-normalised patch distance of the colour */
#define FC_DENOISE_GUIDE_ALL 15u

typedef struct FcDenoiseParams {
    fc_uint width;
    fc_uint height;
    fc_uint radius;          /* the window: (2 radius + 1)^2 pixels */
    fc_uint patch_radius;    /* the colour distance's patch: (2 patch_radius + 1)^2 pixels */
    fc_uint guides;          /* FC_DENOISE_GUIDE_* bits */
    fc_uint variance_radius; /* the box that smooths the half's variance estimate */
    float variance_scale_a;  /* half a's variance over the box mean of its variance source / 3
                                (host/denoise/denoise_variance.hpp) */
    float k_color;           /* the colour distance's scale, in standard deviations (Rousselle et al. 2012's k) */
    float sigma_albedo;      /* albedo difference (Euclidean, RGB) at one standard deviation of the weight */
    float sigma_normal;      /* normal difference (Euclidean) at one standard deviation */
    float sigma_depth;       /* depth difference relative to the larger depth, at one standard deviation */
    float variance_scale_b;  /* half b's */
    /* The planes the filter reads (kernels/denoise/denoise.cl): the image widened to
     * width8 (a multiple of 8) and padded by `pad` pixels on every side with copies of its
     * border, so that no load of the filter needs a bounds check */
    fc_uint width8; /* the width rounded up to a multiple of 8 */
    fc_uint pad;    /* radius + patch_radius + 8 */
    fc_uint pitch;  /* width8 + 2 pad: floats from one padded row to the next */
    fc_uint plane;  /* pitch (height + 2 pad): floats in one plane */
} FcDenoiseParams;
FC_STATIC_ASSERT(sizeof(FcDenoiseParams) == 64, "FcDenoiseParams layout");
FC_STATIC_ASSERT(offsetof(FcDenoiseParams, variance_scale_a) == 24, "FcDenoiseParams layout");
FC_STATIC_ASSERT(offsetof(FcDenoiseParams, sigma_depth) == 40, "FcDenoiseParams layout");
FC_STATIC_ASSERT(offsetof(FcDenoiseParams, variance_scale_b) == 44, "FcDenoiseParams layout");
FC_STATIC_ASSERT(offsetof(FcDenoiseParams, plane) == 60, "FcDenoiseParams layout");

#endif
