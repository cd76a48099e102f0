/* The per-sample random stream.
 *
 * Every sample of every pixel owns an independent PCG32 generator (O'Neill 2014,
 * "PCG: A Family of Simple Fast Space-Efficient Statistically Good Algorithms for
 * Random Number Generation", the pcg32 variant XSH-RR). Its state is derived from
 * (pixel index, sample index) through the SplitMix64 finaliser and its stream (the
 * LCG increment) from the user's seed. So an image is a pure function of the scene,
 * the settings and the seed: independent of the device, of how samples are split
 * into passes and of the order in which work-items run. */
#ifndef FACET_UTIL_RNG_CL
#define FACET_UTIL_RNG_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/util/math.cl"

typedef struct {
    ulong state;
    ulong inc;
} Rng;

/* SplitMix64's output mixer (Steele, Lea, Flood 2014). */
inline ulong mix64(ulong z) { return mix64_l1(z); } /* kernels/util/hash_lanes.cl */

inline uint rng_next(Rng* r) {
    ulong old = r->state;
    r->state = old * 6364136223846793005UL + r->inc;
    uint xorshifted = (uint)(((old >> 18) ^ old) >> 27);
    uint rot = (uint)(old >> 59);
    return (xorshifted >> rot) | (xorshifted << ((0u - rot) & 31u));
}

/* A float uniformly distributed in [0, 1): 24 random bits. */
inline float rng_float(Rng* r) { return (float)(rng_next(r) >> 8) * 0x1p-24f; }

inline float2 rng_float2(Rng* r) {
    float a = rng_float(r);
    return (float2)(a, rng_float(r));
}

inline Rng rng_init(uint seed, uint pixel, uint sample) {
    Rng r;
    r.state = 0UL;
    r.inc = (mix64((ulong)seed ^ 0x9e3779b97f4a7c15UL) << 1) | 1UL;
    rng_next(&r);
    r.state += mix64(((ulong)pixel << 32) | (ulong)sample);
    rng_next(&r);
    return r;
}

#endif
