/* The path tracer's sample generator: for sample `index` of a pixel it hands out
 * 4-dimensional points of numbered "dimension sets", each set used for one fixed
 * purpose (the camera, a bounce's light sample, a bounce's BSDF sample), so that a
 * dimension means the same thing in every path whatever happened before it.
 *
 * FC_SAMPLER_SOBOL (the default): Owen-scrambled Sobol' points, padded and shuffled
 * per dimension set by hashing, after Burley, "Practical Hash-based Owen Scrambling",
 * JCGT 9(4), 2020 (the sampler Cycles calls Sobol-Burley). Each set draws a 4-D Sobol'
 * point at a shuffled index (a nested uniform scramble of the sample index) and Owen-
 * scrambles each coordinate with its own hashed seed: every point is uniformly
 * distributed (so estimates stay unbiased), successive samples of a pixel are
 * stratified in every set's 1-D to 4-D projections, and different sets are
 * decorrelated.
 *
 * The even and odd samples of a pixel form the film's two half-images, whose
 * difference estimates the error without a reference (host/film/error_metrics.hpp).
 * That estimate needs two independent estimators, so each half is its own sequence,
 * indexed by sample >> 1 and scrambled with a seed of its own: never two interleaved
 * halves of one stratified sequence (tests/sampler_test.cpp checks the independence).
 *
 * FC_SAMPLER_INDEPENDENT: independent uniform numbers from the per-sample PCG32
 * stream (kernels/util/rng.cl). */
#ifndef FACET_UTIL_SAMPLER_CL
#define FACET_UTIL_SAMPLER_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/shared/render_layout.h"
#include "kernels/util/rng.cl"
#include "kernels/util/sobol_table.cl"

typedef struct {
    Rng rng;             /* FC_SAMPLER_INDEPENDENT's stream */
    uint index_reversed; /* the bit-reversed index of the sample within its half */
    uint seed;           /* the scramble seed of this pixel's half */
    uint kind;           /* FC_SAMPLER_* */
} Sampler;

/* The dimension sets. The camera's; then two per bounce (depth 0 = the first hit). */
#define FC_SET_CAMERA 0u
inline uint sampler_set_light(uint depth) { return 1u + 2u * depth; } /* pick, u, v, - */
inline uint sampler_set_bsdf(uint depth) { return 2u + 2u * depth; }  /* u, v, lobe, roulette */

/* Sobol' dimensions 0..3, bit-reversed, of the index whose bit reversal is r, from the
 * reversed chunk table: one uint4 load a chunk, written out (PoCL keeps the 8-step loop
 * rolled, at twice the instructions). */
inline uint4 sobol4_reversed(uint r) {
    __constant const uint4* t = fc_sobol4_reversed;
    return t[r & 15u] ^ t[16u + ((r >> 4) & 15u)] ^ t[32u + ((r >> 8) & 15u)] ^ t[48u + ((r >> 12) & 15u)] ^
           t[64u + ((r >> 16) & 15u)] ^ t[80u + ((r >> 20) & 15u)] ^ t[96u + ((r >> 24) & 15u)] ^ t[112u + (r >> 28)];
}

/* The Owen scramble seeds of a set's four coordinates, from the set's seed
 * (coordinate_seed of kernels/util/hash_lanes.cl, the coordinates in the lanes). */
inline uint4 coordinate_seeds(uint set_seed) { return coordinate_seed_l4((uint4)(set_seed), (uint4)(1u, 2u, 3u, 4u)); }

/* The independent sampler's stream is seeded only for it: the Sobol' sampler never reads it. */
inline Sampler sampler_init(uint kind, uint seed, uint pixel, uint sample) {
    Sampler s;
    s.kind = kind;
    s.index_reversed = reverse_bits_l1(sample >> 1);
    s.seed = (uint)mix64(mix64((ulong)seed ^ 0x5a17e5eedUL) ^ (((ulong)(sample & 1u) << 32) | (ulong)pixel));
    s.rng.state = 0UL;
    s.rng.inc = 0UL;
    if (kind == FC_SAMPLER_INDEPENDENT) s.rng = rng_init(seed, pixel, sample);
    return s;
}

/* The point of dimension set `set`, each coordinate in [0, 1). Burley's scrambles,
 * nested_uniform_scramble(x) = reverse(laine_karras(reverse(x))), are chained in the
 * reversed domain: the index is reversed once in sampler_init, its scramble is the
 * reversed shuffled index, which the reversed Sobol' table takes as it is, and the four
 * coordinates (scrambled together as one uint4) are reversed once at the end. The
 * values are those of scrambling each step on its own. */
inline float4 sampler_get4(Sampler* s, uint set) {
    if (s->kind == FC_SAMPLER_INDEPENDENT) {
        float2 a = rng_float2(&s->rng);
        return (float4)(a, rng_float2(&s->rng));
    }
    uint seed = hash_pair_l1(s->seed, set);
    uint r = laine_karras_l1(s->index_reversed, seed);
    uint4 x = reverse_bits_l4(laine_karras_l4(sobol4_reversed(r), coordinate_seeds(seed)));
    return convert_float4(x >> 8) * 0x1p-24f; /* the top 24 bits: every float in [0, 1) exact */
}

#endif
