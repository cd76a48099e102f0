/* Lane-generic body (kernels/lanes/lanes.cl): the integer hashes of the sampler
 * (kernels/util/sampler.cl) and the random streams (kernels/util/rng.cl). */
#ifndef FACET_UTIL_HASH_LANES_PASS
#define FACET_UTIL_HASH_LANES_PASS

/* SplitMix64's finaliser (Steele, Lea & Flood 2014; Stafford's "Mix13" constants). */
inline LULONG LNAME(mix64)(LULONG z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9UL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebUL;
    return z ^ (z >> 31);
}

/* A 32-bit hash of the pair (a, b): mix64 of a << 32 | b, its low word. */
inline LUINT LNAME(hash_pair)(LUINT a, LUINT b) {
    return LCONVERT_UINT(LNAME(mix64)((LCONVERT_ULONG(a) << 32) | LCONVERT_ULONG(b)));
}

/* The Laine-Karras hash of Burley 2020, listing 3: applied to bit-reversed x it is an Owen
 * scramble of x's bits from the most significant down (nested uniform scrambling), and
 * stays in the reversed domain. */
inline LUINT LNAME(laine_karras)(LUINT x, LUINT seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    return x ^ (x * 0x8d22f6e6u);
}

/* Chris Wellons' "lowbias32" integer hash (hash-prospector, 2018: a bijection of 32-bit
 * words with a bias of 0.17 against an ideal avalanche). Two 32-bit multiplies a lane,
 * one vector instruction each on CPUs and GPUs, where SplitMix64's 64-bit products cost
 * three 32-bit ones a lane on AVX2. */
inline LUINT LNAME(hash32)(LUINT x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

/* The 32-bit fraction of the golden ratio: seeds k = 1, 2, ... spaced by it are distinct. */
#ifndef FC_GOLDEN_32
#define FC_GOLDEN_32 0x9e3779b9u
#endif

/* The Owen scramble seed of coordinate `number` (1 to 4) of a dimension set with seed
 * set_seed. */
inline LUINT LNAME(coordinate_seed)(LUINT set_seed, LUINT number) {
    return LNAME(hash32)(set_seed + number * FC_GOLDEN_32);
}

/* The bits of each lane reversed, by swapping halves, bytes, nibbles, pairs and bits:
 * vector shifts and masks. Oclgrind has no llvm.bitreverse, which LLVM makes of them: for
 * it (FC_NO_BITREVERSE_INTRINSIC, set by host/cl/runtime.cpp) the byte table of
 * kernels/util/sobol_table.cl, lane by lane. */
inline LUINT LNAME(reverse_bits)(LUINT x) {
#ifdef FC_NO_BITREVERSE_INTRINSIC
    uint v[FC_LW];
    LSTORE(x, v);
    for (int j = 0; j < FC_LW; ++j)
        v[j] = ((uint)fc_reverse_byte[v[j] & 0xffu] << 24) | ((uint)fc_reverse_byte[(v[j] >> 8) & 0xffu] << 16) |
               ((uint)fc_reverse_byte[(v[j] >> 16) & 0xffu] << 8) | (uint)fc_reverse_byte[v[j] >> 24];
    return LLOAD(v);
#else
    x = (x >> 16) | (x << 16);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
#endif
}

#undef FACET_UTIL_HASH_LANES_PASS
#endif
