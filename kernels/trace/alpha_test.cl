/* Alpha cut-outs and stochastic transparency: the any-hit test that traversal applies to
 * each triangle a ray meets, before the hit may shorten the ray (closest hit) or end it
 * (shadow rays), so that every ray, camera, bounce or shadow, sees through the same
 * cut-away texels and a cut-out casts the shadow of its shape, never of its card
 * (pbrt-v4's shape `alpha`, Mitsuba's `mask`, Falcor's alpha test do the same).
 *
 * A triangle's material (kernels/shared/material_layout.h) gives the coverage
 * a = alpha x (the alpha texture's A, or R with FC_MAT_ALPHA_RED) at the hit's uv, read at
 * full resolution (level 0: traversal has no ray cone, and every ray must agree):
 *   FC_MAT_ALPHA_MASK   the hit counts where a >= alpha_cutoff (glTF's MASK);
 *   FC_MAT_ALPHA_BLEND  the hit counts with probability a (glTF's BLEND, OBJ's d / map_d):
 *                       stochastic transparency (Enderton et al. 2010), unbiased in
 *                       expectation: a shaded surface plus 1 - a of what lies behind.
 * BLEND's random number is a hash of the ray's seed (per pixel, sample, bounce and ray
 * kind), the triangle and the hit distance: deterministic, so renders are reproducible.
 * Programs built without FC_HAS_ALPHA leave the test out; spheres have no uv alpha. */
#ifndef FACET_TRACE_ALPHA_TEST_CL
#define FACET_TRACE_ALPHA_TEST_CL

#include "kernels/scene/scene_view.cl"
#include "kernels/texture/texture.cl"
#include "kernels/util/rng.cl"

/* What the test needs at a traversal: the scene, the offset of the tree's triangle
 * indices in the FcTriangle array (an instanced mesh's, kernels/trace/instance.cl), and the
 * ray's seed. Traversals without one (a null pointer) keep every hit. */
typedef struct {
    const SceneView* sc;
    int tri_offset;
    uint seed;
} AlphaTest;

/* The coverage of material `m` (index `material`) on scene triangle `prim` at
 * barycentrics (b1, b2) of v1 and v2. */
inline float alpha_coverage(const SceneView* sc, __global const FcMaterial* m, int material, int prim, float b1,
                            float b2) {
    float a = m->alpha;
    if (m->alpha_texture < 0) return a;
    __global const FcTriTexcoords* t = &sc->texcoords[prim];
    float2 uv0 = (float2)(t->uv[0][0], t->uv[0][1]);
    float2 uv = uv0 + b1 * ((float2)(t->uv[1][0], t->uv[1][1]) - uv0) + b2 * ((float2)(t->uv[2][0], t->uv[2][1]) - uv0);
    float4 texel = texture_sample(sc->textures, sc->texels, m->alpha_texture,
                                  tex_transform(&sc->material_textures[material], uv), 0.0f);
    return a * ((m->flags & FC_MAT_ALPHA_RED) ? texel.x : texel.w);
}

/* A uniform number in [0, 1) from the ray's seed, the triangle and the hit distance. */
inline float alpha_random(uint seed, int tri, float t) {
    ulong h = mix64(((ulong)seed << 32) | (ulong)(uint)tri);
    return (float)((uint)(mix64(h ^ (ulong)as_uint(t)) >> 40)) * 0x1p-24f;
}

/* Whether the hit of triangle `tri` (the tree's index) at distance t and barycentrics
 * (b1, b2) counts. */
inline bool alpha_keeps(const AlphaTest* at, int tri, float t, float b1, float b2) {
    const SceneView* sc = at->sc;
    const int scene_tri = tri + at->tri_offset;
    const int prim = sc->tris[scene_tri].prim;
    const int material = sc->shading[prim].material;
    __global const FcMaterial* m = &sc->materials[material];
    const uint mode = m->flags & (FC_MAT_ALPHA_MASK | FC_MAT_ALPHA_BLEND);
    if (!mode) return true;
    const float a = alpha_coverage(sc, m, material, prim, b1, b2);
    if (mode & FC_MAT_ALPHA_MASK) return a >= m->alpha_cutoff;
    return alpha_random(at->seed, scene_tri, t) < a;
}

/* The expected coverage of emitting scene triangle `prim` at a light sample's barycentrics b
 * along the light's edges (FcLight e1, e2): MASK's 0 or 1, BLEND's alpha. Light sampling
 * weighs the card's emission by it, as BSDF sampling meets the card's hits with that
 * probability, so that the two strategies estimate the same light. */
inline float alpha_light_coverage(const SceneView* sc, int prim, float2 b) {
    const int material = sc->shading[prim].material;
    __global const FcMaterial* m = &sc->materials[material];
    const uint mode = m->flags & (FC_MAT_ALPHA_MASK | FC_MAT_ALPHA_BLEND);
    if (!mode) return 1.0f;
    if (m->alpha_texture >= 0 && sc->texcoords[prim].light_swapped) b = b.yx;
    const float a = alpha_coverage(sc, m, material, prim, b.x, b.y);
    if (mode & FC_MAT_ALPHA_MASK) return a >= m->alpha_cutoff ? 1.0f : 0.0f;
    return a;
}

/* The seed of one ray of a path: per sample (the sampler's pixel seed and index), bounce
 * `depth` and `kind` (0: the bounce's closest-hit ray, 1: its shadow ray). */
inline uint alpha_ray_seed(uint sample_seed, uint sample_index, uint depth, uint kind) {
    return (uint)mix64(((ulong)sample_seed << 32) ^ ((ulong)sample_index << 8) ^ (ulong)(2u * depth + kind));
}

#endif
