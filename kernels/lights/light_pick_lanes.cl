/* Lane-generic body (kernels/lanes/lanes.cl): the light pick of kernels/lights/light.cl
 * (pick_light, its W = 1 form) for FC_LW points at once. Needs gather_lanes.cl of the same
 * width. The search's length depends on the light count alone, so every lane takes the same
 * steps; each step reads the lanes' cdf entries by a gather. */
#ifndef FACET_LIGHTS_LIGHT_PICK_LANES_PASS
#define FACET_LIGHTS_LIGHT_PICK_LANES_PASS

/* A comparison's lanes as every bit set where true: a scalar comparison gives 1, a vector
 * one -1. */
#if FC_LW == 1
#define FC_PICK_ALL_BITS(m) (0u - (uint)(m))
#else
#define FC_PICK_ALL_BITS(m) LCONVERT_UINT(m)
#endif

/* The light k with cdf[k] <= u < cdf[k + 1] for each lane (pick_light's contract). */
inline LUINT LNAME(pick_light)(__global const float* cdf, uint light_count, LFLOAT u) {
    if (light_count <= 8u) {
        LUINT k = (LUINT)(0u);
        for (uint i = 1u; i < light_count; ++i) k += FC_PICK_ALL_BITS(cdf[i] <= u) & 1u;
        return k;
    }
    LUINT base = (LUINT)(0u); /* invariant: cdf[base] <= u < cdf[base + n] */
    uint n = light_count;
    while (n > 1u) {
        const uint step = n / 2u;
        /* a mask, not a select LLVM makes a branch */
        base += step & FC_PICK_ALL_BITS(LNAME(gather)(cdf, base + step) <= u);
        n -= step;
    }
    return base;
}

#undef FC_PICK_ALL_BITS
#undef FACET_LIGHTS_LIGHT_PICK_LANES_PASS
#endif
