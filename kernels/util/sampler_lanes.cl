/* Lane-generic body (kernels/lanes/lanes.cl): sampler_get4 of kernels/util/sampler.cl for
 * FC_LW paths at once, one path a lane (that file's sampler_get4 scrambles one path's four
 * coordinates in the lanes of a uint4 instead; the hashes are the same functions). Needs
 * sobol4_reversed (sampler.cl) and hash_lanes.cl of the same width. */
#ifndef FACET_UTIL_SAMPLER_LANES_PASS
#define FACET_UTIL_SAMPLER_LANES_PASS

#if defined(__clang__) && ((FC_LW == 16 && defined(__AVX512F__)) || (FC_LW == 8 && defined(__AVX2__)))
/* Chunk k of dimension d of the Sobol' table for each lane's nibble: the chunk's sixteen
 * entries held in registers and indexed by all lanes at once (vpermd), where a lane-by-lane
 * lookup loads a uint4 a lane and transposes the four dimensions through memory. */
inline LUINT LNAME(sobol_chunk)(int d, int k, LUINT nibble) {
    __constant const uint* t = fc_sobol_reversed_by_dim + 16 * (8 * d + k);
#if FC_LW == 16
    const FcLanesV16si x = __builtin_ia32_permvarsi512(__builtin_convertvector(as_int16(vload16(0, t)), FcLanesV16si),
                                                       __builtin_convertvector(as_int16(nibble), FcLanesV16si));
    return as_uint16(__builtin_convertvector(x, int16));
#else
    /* AVX2's vpermd indexes eight entries: the two halves, picked by the nibble's top bit */
    const FcLanesV8si i = __builtin_convertvector(as_int8(nibble), FcLanesV8si);
    const int8 lo = __builtin_convertvector(
        __builtin_ia32_permvarsi256(__builtin_convertvector(as_int8(vload8(0, t)), FcLanesV8si), i), int8);
    const int8 hi = __builtin_convertvector(
        __builtin_ia32_permvarsi256(__builtin_convertvector(as_int8(vload8(1, t)), FcLanesV8si), i), int8);
    return as_uint8(select(lo, hi, (as_int8(nibble) & 8) != 0));
#endif
}
#define FC_SOBOL_CHUNK_LANES 1
#endif

/* The four coordinates of dimension set `set` of each lane's sample, whose half's seed is
 * pixel_seed (Sampler.seed) and bit-reversed index index_reversed (Sampler.index_reversed),
 * in u[0..3]. */
inline void LNAME(sampler_get4)(LUINT pixel_seed, LUINT index_reversed, LUINT set, LFLOAT u[4]) {
    LUINT seed = LNAME(hash_pair)(pixel_seed, set);
    const LUINT rl = LNAME(laine_karras)(index_reversed, seed);
#ifdef FC_SOBOL_CHUNK_LANES
    /* unrolled, so that the four dimensions stay in registers */
    LUINT c0 = (LUINT)(0u), c1 = (LUINT)(0u), c2 = (LUINT)(0u), c3 = (LUINT)(0u);
#pragma unroll
    for (int k = 0; k < 8; ++k) {
        const LUINT nibble = (rl >> (uint)(4 * k)) & 15u;
        c0 ^= LNAME(sobol_chunk)(0, k, nibble);
        c1 ^= LNAME(sobol_chunk)(1, k, nibble);
        c2 ^= LNAME(sobol_chunk)(2, k, nibble);
        c3 ^= LNAME(sobol_chunk)(3, k, nibble);
    }
#define FC_SOBOL_COORDINATE(k) ((k) == 0u ? c0 : (k) == 1u ? c1 : (k) == 2u ? c2 : c3)
#else
    uint r[FC_LW];
    LSTORE(rl, r);
    /* the Sobol' table read lane by lane (a gather), transposed to one vector a coordinate */
    uint c[4 * FC_LW];
    for (int j = 0; j < FC_LW; ++j) {
        uint4 q = sobol4_reversed(r[j]);
        c[j] = q.x;
        c[FC_LW + j] = q.y;
        c[2 * FC_LW + j] = q.z;
        c[3 * FC_LW + j] = q.w;
    }
#define FC_SOBOL_COORDINATE(k) LLOAD(c + (k)*FC_LW)
#endif
#pragma unroll
    for (uint k = 0; k < 4u; ++k) {
        LUINT x = LNAME(reverse_bits)(
            LNAME(laine_karras)(FC_SOBOL_COORDINATE(k), LNAME(coordinate_seed)(seed, (LUINT)(k + 1u))));
        u[k] = LCONVERT_FLOAT(x >> 8) * 0x1p-24f; /* the top 24 bits: every float in [0, 1) exact */
    }
#undef FC_SOBOL_COORDINATE
}

#ifdef FC_SOBOL_CHUNK_LANES
#undef FC_SOBOL_CHUNK_LANES
#endif
#undef FACET_UTIL_SAMPLER_LANES_PASS
#endif
