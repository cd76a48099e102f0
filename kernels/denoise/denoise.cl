/* facet's denoiser: the joint non-local-means filter of denoise_weights.cl applied to both
 * half-images at once, each half with its own colour weights (the feature terms are shared).
 * The output of pixel p is
 *     c_p + sum_q w_q (c_q - c_p) / sum_q w_q
 * over the window of (2 radius + 1)^2 pixels clipped at the image border, written as a
 * correction of c_p so that a constant image comes out exactly (w_p = 1).
 *
 * Offset-wise (as Rousselle et al. 2012, sec. 5, compute NL-means): for each window offset
 * o the colour term image e(u, u + o) is computed once (denoise_terms), and each pixel's
 * patch distance is the box sum of that image around it (denoise_accumulate): the divisions
 * cost O(window) a pixel instead of O(window x patch). One launch of each kernel covers the
 * 2 radius + 1 offsets of one window row. A work item filters 8 neighbouring pixels of a row
 * in float8 lanes, on planes (one a channel) padded with copies of the border
 * (FcDenoiseParams.pad), so that no load needs a bounds check. Kernels:
 *   denoise_variance_rows  the row pass of the variance box: each half's variance source
 *                       (host/denoise/denoise_variance.hpp: its own, from its second moments,
 *                       or the pair's (a - b)^2) summed along rows
 *   denoise_prepare     the padded planes: each half's colour and the variance of its pixel
 *                       mean (the column pass: the mean over channels and over a box of
 *                       (2 variance_radius + 1)^2 pixels, times the half's scale), and the
 *                       features
 *   denoise_terms       the colour terms of one window row's offsets
 *   denoise_accumulate  the weights and weighted sums of one window row
 *   denoise_finish      the denoised halves, 3 floats a pixel, top row first
 * Planes: colour 8 (half a r, g, b, v, then half b), features 7 (albedo r, g, b, normal x,
 * y, z, depth), terms 2 (2 radius + 1) (offset dx, half), all FcDenoiseParams.plane floats;
 * sums 8 (half a r, g, b, weight, then half b) of width8 x height floats. */
#ifndef FACET_DENOISE_DENOISE_CL
#define FACET_DENOISE_DENOISE_CL

#include "kernels/denoise/denoise_weights.cl"

/* The index of image pixel (x, y) in a padded plane. */
inline uint denoise_padded(__constant const FcDenoiseParams* p, int x, int y) {
    return (uint)((y + (int)p->pad) * (int)p->pitch + x + (int)p->pad);
}

/* Half k's colour at padded index `at` and the 7 following. */
inline DenoiseColor denoise_color_at(__constant const FcDenoiseParams* p, __global const float* colour, uint k,
                                     uint at) {
    __global const float* c = colour + 4 * k * p->plane + at;
    DenoiseColor v = {denoise_load8(c), denoise_load8(c + p->plane), denoise_load8(c + 2 * p->plane),
                      denoise_load8(c + 3 * p->plane)};
    return v;
}

/* The features at padded index `at` and the 7 following. */
inline DenoiseFeature denoise_feature_at(__constant const FcDenoiseParams* p, __global const float* features, uint at) {
    __global const float* f = features + at;
    uint n = p->plane;
    DenoiseFeature v = {denoise_load8(f),         denoise_load8(f + n),     denoise_load8(f + 2 * n),
                        denoise_load8(f + 3 * n), denoise_load8(f + 4 * n), denoise_load8(f + 5 * n),
                        denoise_load8(f + 6 * n)};
    return v;
}

/* One pixel's row sum of a half's variance source (denoise_variance_row): both halves,
 * 1 float a pixel, half a's plane then half b's, as `source`. */
__kernel void denoise_variance_rows(__constant const FcDenoiseParams* p, __global const float* source,
                                    __global float* rows) {
    uint gid = get_global_id(0), pixels = p->width * p->height;
    if (gid >= 2u * pixels) return;
    int w = (int)p->width, i = (int)(gid % pixels);
    rows[gid] = denoise_variance_row(source + (gid - (uint)i), w, (int)p->variance_radius, i % w, i / w);
}

/* The sums of 3 neighbouring terms from t, for 8 pixels: one row of a 3 x 3 patch. */
inline float8 denoise_box3(__global const float* t) {
    return denoise_load8(t) + denoise_load8(t + 1) + denoise_load8(t + 2);
}

/* One padded pixel of the colour and feature planes, from the halves a and b, their
 * variance sources' row sums (denoise_variance_rows) and the features as the host holds
 * them (3 floats a pixel, depth 1). */
__kernel void denoise_prepare(__constant const FcDenoiseParams* p, __global const float* a, __global const float* b,
                              __global const float* rows, __global const float* albedo, __global const float* normal,
                              __global const float* depth, __global float* colour, __global float* features) {
    uint gid = get_global_id(0), n = p->plane;
    if (gid >= n) return;
    int w = (int)p->width, h = (int)p->height;
    int x = clamp((int)(gid % p->pitch) - (int)p->pad, 0, w - 1),
        y = clamp((int)(gid / p->pitch) - (int)p->pad, 0, h - 1);
    uint i = (uint)(y * w + x);
    int vr = (int)p->variance_radius;
    float va = denoise_box_variance(rows, w, h, vr, x, y), vb = denoise_box_variance(rows + w * h, w, h, vr, x, y);
    for (uint c = 0; c < 3; ++c) {
        colour[c * n + gid] = a[3 * i + c];
        colour[(4 + c) * n + gid] = b[3 * i + c];
        features[c * n + gid] = albedo[3 * i + c];
        features[(3 + c) * n + gid] = normal[3 * i + c];
    }
    colour[3 * n + gid] = p->variance_scale_a * va;
    colour[7 * n + gid] = p->variance_scale_b * vb;
    features[6 * n + gid] = depth[i];
}

/* The colour terms of both halves between the 8 pixels u (from (x, y)) and u + (dx, dy),
 * dx = -radius..radius, over the image widened by the patch radius. */
__kernel void denoise_terms(__constant const FcDenoiseParams* p, __global const float* colour, __global float* terms,
                            int dy) {
    uint gid = get_global_id(0);
    int pr = (int)p->patch_radius, r = (int)p->radius, groups = ((int)p->width8 + 2 * pr + 7) / 8;
    if (gid >= (uint)(groups * ((int)p->height + 2 * pr))) return;
    int x = -pr + 8 * ((int)gid % groups), y = -pr + (int)gid / groups;
    float k2 = p->k_color * p->k_color;
    uint at = denoise_padded(p, x, y);
    DenoiseColor pa = denoise_color_at(p, colour, 0, at), pb = denoise_color_at(p, colour, 1, at);
    for (int dx = -r; dx <= r; ++dx) {
        uint bt = denoise_padded(p, x + dx, y + dy), plane = 2 * (uint)(dx + r) * p->plane;
        denoise_store8(denoise_color_term(pa, denoise_color_at(p, colour, 0, bt), k2), terms + plane + at);
        denoise_store8(denoise_color_term(pb, denoise_color_at(p, colour, 1, bt), k2), terms + plane + p->plane + at);
    }
}

/* Adds the neighbours of window row dy to both halves' sums, for 8 pixels of a row.
 * terms: denoise_terms of the same dy (not read without the colour guide). */
__kernel void denoise_accumulate(__constant const FcDenoiseParams* p, __global const float* colour,
                                 __global const float* features, __global const float* terms, __global float* sums,
                                 int dy) {
    uint gid = get_global_id(0);
    int w = (int)p->width, h = (int)p->height, r = (int)p->radius, pr = (int)p->patch_radius;
    int groups = (int)p->width8 / 8;
    if (gid >= (uint)(groups * h)) return;
    int x = 8 * ((int)gid % groups), y = (int)gid / groups;
    if (y + dy < 0 || y + dy >= h) return;
    float inv_patch = 1.0f / (float)((2 * pr + 1) * (2 * pr + 1));
    bool color = (p->guides & FC_DENOISE_GUIDE_COLOR) != 0u;
    uint at = denoise_padded(p, x, y);
    DenoiseColor pa = denoise_color_at(p, colour, 0, at), pb = denoise_color_at(p, colour, 1, at);
    DenoiseFeature fp = denoise_feature_at(p, features, at);
    DenoiseFeatureScale scale = denoise_feature_scale(p);
    __global float* s = sums + (uint)(y * (int)p->width8 + x);
    uint sn = p->width8 * p->height;
    float8 ar = denoise_load8(s), ag = denoise_load8(s + sn), ab = denoise_load8(s + 2 * sn),
           aw = denoise_load8(s + 3 * sn);
    float8 br = denoise_load8(s + 4 * sn), bg = denoise_load8(s + 5 * sn), bb = denoise_load8(s + 6 * sn),
           bw = denoise_load8(s + 7 * sn);
    int8 lane = (int8)(0, 1, 2, 3, 4, 5, 6, 7) + x;
    for (int dx = -r; dx <= r; ++dx) {
        uint q = denoise_padded(p, x + dx, y + dy);
        float8 f = denoise_feature_distance(scale, fp, denoise_feature_at(p, features, q)), da = f, db = f;
        if (color) {
            /* The patch distance: the box sum of the offset's term image around p (the
             * 3 x 3 patch, the default, written out) */
            __global const float* ta = terms + 2 * (uint)(dx + r) * p->plane;
            __global const float* tb = ta + p->plane;
            float8 sa = (float8)(0.0f), sb = (float8)(0.0f);
            if (pr == 1) {
                uint t = denoise_padded(p, x - 1, y - 1), t2 = t + p->pitch, t3 = t2 + p->pitch;
                sa = denoise_box3(ta + t) + denoise_box3(ta + t2) + denoise_box3(ta + t3);
                sb = denoise_box3(tb + t) + denoise_box3(tb + t2) + denoise_box3(tb + t3);
            } else {
                for (int sy = -pr; sy <= pr; ++sy)
                    for (int sx = -pr; sx <= pr; ++sx) {
                        uint t = denoise_padded(p, x + sx, y + sy);
                        sa += denoise_load8(ta + t);
                        sb += denoise_load8(tb + t);
                    }
            }
            da += fmax(sa * inv_patch, 0.0f);
            db += fmax(sb * inv_patch, 0.0f);
        }
        /* Neighbours outside the image weigh nothing */
        int8 inside = (lane + dx >= 0) & (lane + dx < w);
        float8 wa = select((float8)(0.0f), exp(-da), inside), wb = select((float8)(0.0f), exp(-db), inside);
        DenoiseColor qa = denoise_color_at(p, colour, 0, q), qb = denoise_color_at(p, colour, 1, q);
        ar += wa * (qa.r - pa.r), ag += wa * (qa.g - pa.g), ab += wa * (qa.b - pa.b), aw += wa;
        br += wb * (qb.r - pb.r), bg += wb * (qb.g - pb.g), bb += wb * (qb.b - pb.b), bw += wb;
    }
    denoise_store8(ar, s), denoise_store8(ag, s + sn), denoise_store8(ab, s + 2 * sn), denoise_store8(aw, s + 3 * sn);
    denoise_store8(br, s + 4 * sn), denoise_store8(bg, s + 5 * sn), denoise_store8(bb, s + 6 * sn),
        denoise_store8(bw, s + 7 * sn);
}

/* One pixel of both denoised halves, 3 floats a pixel: c_p + the weighted mean correction. */
__kernel void denoise_finish(__constant const FcDenoiseParams* p, __global const float* colour,
                             __global const float* sums, __global float* out_a, __global float* out_b) {
    uint gid = get_global_id(0);
    if (gid >= p->width * p->height) return;
    int x = (int)(gid % p->width), y = (int)(gid / p->width);
    uint at = denoise_padded(p, x, y), sn = p->width8 * p->height, st = (uint)y * p->width8 + (uint)x;
    float wa = sums[3 * sn + st], wb = sums[7 * sn + st];
    for (uint c = 0; c < 3; ++c) {
        out_a[3 * gid + c] = colour[c * p->plane + at] + sums[c * sn + st] / wa;
        out_b[3 * gid + c] = colour[(4 + c) * p->plane + at] + sums[(4 + c) * sn + st] / wb;
    }
}

#endif
