/* Lane-generic body (kernels/lanes/lanes.cl): sampler_get4 of kernels/util/sampler.cl for
 * FC_LW paths at once, one path a lane (that file's sampler_get4 scrambles one path's four
 * coordinates in the lanes of a uint4 instead; the hashes are the same functions). Needs
 * sobol4_reversed (sampler.cl) and hash_lanes.cl of the same width. */
#ifndef FACET_UTIL_SAMPLER_LANES_PASS
#define FACET_UTIL_SAMPLER_LANES_PASS

/* The four coordinates of dimension set `set` of each lane's sample, whose half's seed is
 * pixel_seed (Sampler.seed) and bit-reversed index index_reversed (Sampler.index_reversed),
 * in u[0..3]. */
inline void LNAME(sampler_get4)(LUINT pixel_seed, LUINT index_reversed, LUINT set, LFLOAT u[4]) {
    LUINT seed = LNAME(hash_pair)(pixel_seed, set);
    uint r[FC_LW];
    LSTORE(LNAME(laine_karras)(index_reversed, seed), r);
    /* the Sobol' table read lane by lane (a gather), transposed to one vector a coordinate */
    uint c[4 * FC_LW];
    for (int j = 0; j < FC_LW; ++j) {
        uint4 q = sobol4_reversed(r[j]);
        c[j] = q.x;
        c[FC_LW + j] = q.y;
        c[2 * FC_LW + j] = q.z;
        c[3 * FC_LW + j] = q.w;
    }
    for (uint k = 0; k < 4u; ++k) {
        LUINT x = LNAME(reverse_bits)(
            LNAME(laine_karras)(LLOAD(c + k * FC_LW), LNAME(coordinate_seed)(seed, (LUINT)(k + 1u))));
        u[k] = LCONVERT_FLOAT(x >> 8) * 0x1p-24f; /* the top 24 bits: every float in [0, 1) exact */
    }
}

#undef FACET_UTIL_SAMPLER_LANES_PASS
#endif
