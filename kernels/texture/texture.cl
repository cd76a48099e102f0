/* Image texture lookups (kernels/shared/texture_layout.h; docs/textures.md): bilinear
 * filtering within a mip level, wrap / clamp / mirror addressing, and trilinear
 * filtering between the two levels around a continuous level of detail.
 *
 * The level of detail comes from a ray cone (Akenine-Möller et al. 2019, "Texture Level
 * of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20, eq. 34):
 * lambda = 0.5 log2(t_a / p_a) + log2(w / |n . d|), with t_a the triangle's area in
 * texels of level 0, p_a its area in world units, w the cone's width at the hit. */
#ifndef FACET_TEXTURE_TEXTURE_CL
#define FACET_TEXTURE_TEXTURE_CL

#include "kernels/shared/texture_layout.h"
#include "kernels/util/math.cl"

/* Integer texel coordinate i of a level n texels wide, addressed by `wrap`. */
inline int texture_wrap(int i, int n, int wrap) {
    if (wrap == FC_WRAP_CLAMP) return clamp(i, 0, n - 1);
    if (wrap == FC_WRAP_MIRROR) {
        int period = 2 * n;
        int m = i % period;
        if (m < 0) m += period;
        return m < n ? m : period - 1 - m;
    }
    int m = i % n;
    return m < 0 ? m + n : m;
}

/* 32-bit words a texel of `format` takes in the pool. */
inline uint texel_words(int format) { return format == FC_TEXEL_RGBA32F ? 4u : format == FC_TEXEL_RGBA16F ? 2u : 1u; }

/* Texel i of a texture of `format` whose level starts at word `base` of the pool, as
 * linear RGBA (kernels/shared/texture_layout.h gives the formats). */
inline float4 texel_fetch(__global const uint* pool, int format, uint base, uint i) {
    if (format == FC_TEXEL_RGBA32F) return as_float4(vload4(0, pool + base + 4u * i));
    if (format == FC_TEXEL_RGBA16F) return vload_half4(0, (__global const half*)(pool + base + 2u * i));
    uint w = pool[base + i];
    uint r = w & 0xffu, g = (w >> 8) & 0xffu, b = (w >> 16) & 0xffu;
    float a = (float)(w >> 24) / 255.0f;
    if (format == FC_TEXEL_RGBA8_SRGB)
        return (float4)(as_float(pool[FC_SRGB_TABLE + r]), as_float(pool[FC_SRGB_TABLE + g]),
                        as_float(pool[FC_SRGB_TABLE + b]), a);
    return (float4)((float)r / 255.0f, (float)g / 255.0f, (float)b / 255.0f, a);
}

/* First word of `level` in the pool, its size and its texel format (level 0 in `format`,
 * the others in `mip_format`). */
inline uint texture_level(__global const FcTexture* t, int level, int* w, int* h, int* format) {
    uint offset = t->offset;
    int lw = t->width, lh = t->height;
    for (int l = 0; l < level; ++l) {
        offset += (uint)(lw * lh) * texel_words(l == 0 ? t->format : t->mip_format);
        lw = max(lw / 2, 1);
        lh = max(lh / 2, 1);
    }
    *w = lw;
    *h = lh;
    *format = level == 0 ? t->format : t->mip_format;
    return offset;
}

/* Bilinear lookup in one level: texel centres sit at ((x + 0.5) / w, (y + 0.5) / h). */
inline float4 texture_bilinear(__global const FcTexture* t, __global const uint* texels, int level, float2 uv) {
    int w, h, f;
    uint base = texture_level(t, level, &w, &h, &f);
    /* Large |uv| (a far repeat) would lose the fraction in float: keep it in [0, 2) periods
     * for repeat and mirror; clamp reads the edge anyway. */
    if (t->wrap_u != FC_WRAP_CLAMP) uv.x -= 2.0f * floor(0.5f * uv.x);
    if (t->wrap_v != FC_WRAP_CLAMP) uv.y -= 2.0f * floor(0.5f * uv.y);
    float x = clamp(uv.x, -4.0f, 4.0f) * (float)w - 0.5f;
    float y = clamp(uv.y, -4.0f, 4.0f) * (float)h - 0.5f;
    float fx = floor(x), fy = floor(y);
    float ax = x - fx, ay = y - fy;
    int x0 = texture_wrap((int)fx, w, t->wrap_u), x1 = texture_wrap((int)fx + 1, w, t->wrap_u);
    int y0 = texture_wrap((int)fy, h, t->wrap_v), y1 = texture_wrap((int)fy + 1, h, t->wrap_v);
    float4 a = texel_fetch(texels, f, base, (uint)(y0 * w + x0)), b = texel_fetch(texels, f, base, (uint)(y0 * w + x1));
    float4 c = texel_fetch(texels, f, base, (uint)(y1 * w + x0)), d = texel_fetch(texels, f, base, (uint)(y1 * w + x1));
    return mix(mix(a, b, ax), mix(c, d, ax), ay);
}

/* uv' = the material's KHR_texture_transform of uv. */
inline float2 tex_transform(__global const FcMaterialTextures* mt, float2 uv) {
    return (float2)(mt->uv_transform[0][0] * uv.x + mt->uv_transform[0][1] * uv.y + mt->uv_transform[0][2],
                    mt->uv_transform[1][0] * uv.x + mt->uv_transform[1][1] * uv.y + mt->uv_transform[1][2]);
}

/* Trilinear lookup at level of detail `lod` (0: level 0; clamped to the pyramid). */
inline float4 texture_sample(__global const FcTexture* textures, __global const uint* texels, int index, float2 uv,
                             float lod) {
    __global const FcTexture* t = &textures[index];
    float l = clamp(isnan(lod) ? 0.0f : lod, 0.0f, (float)(t->levels - 1));
    int l0 = (int)floor(l);
    float f = l - (float)l0;
    float4 v = texture_bilinear(t, texels, l0, uv);
    if (f > 0.0f && l0 + 1 < t->levels) v = mix(v, texture_bilinear(t, texels, l0 + 1, uv), f);
    return v;
}

/* The ray cone's level of detail of a texture of `texel_count` (width x height) texels
 * on a triangle with uv-area `uv_area` and world area `world_area`, hit by a cone of
 * width `cone_width` at cosine `cos_hit` between the ray and the normal. */
inline float texture_lod(int texel_count, float uv_area, float world_area, float cone_width, float cos_hit) {
    if (!(cone_width > 0.0f) || !(uv_area > 0.0f) || !(world_area > 0.0f)) return 0.0f;
    float t_a = (float)texel_count * uv_area;
    return 0.5f * log2(t_a / world_area) + log2(cone_width / fmax(fabs(cos_hit), 1e-3f));
}

#endif
