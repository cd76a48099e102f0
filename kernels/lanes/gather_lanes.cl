/* Lane-generic body (kernels/lanes/lanes.cl): base[index] for each lane, read from global
 * memory. W = 1 reads the one element. At W = 16 on AVX-512 and W = 8 on AVX2 it is the CPU's
 * gather instruction (vgatherdps), where a loop over the lanes stores each value to a lane
 * array that a vector load then waits for; elsewhere it is that loop. The bits are moved, not
 * converted: a uint field is gathered as its float's bits (as_uint of the result). */
#ifndef FACET_LANES_GATHER_LANES_PASS
#define FACET_LANES_GATHER_LANES_PASS

inline LFLOAT LNAME(gather)(__global const float* base, LUINT index) {
#if FC_LW == 1
    return base[index];
#elif defined(__clang__) && FC_LW == 16 && defined(__AVX512F__)
    /* the builtin takes a pointer of the default address space: on the CPU it is the same
     * memory, so the address passes through an integer */
    const FcLanesV16sf g =
        __builtin_ia32_gathersiv16sf(__builtin_convertvector((float16)(0.0f), FcLanesV16sf), (const void*)(size_t)base,
                                     __builtin_convertvector(as_int16(index), FcLanesV16si), (ushort)0xffffu, 4);
    return __builtin_convertvector(g, float16);
#elif defined(__clang__) && FC_LW == 8 && defined(__AVX2__)
    const FcLanesV8sf g = __builtin_ia32_gatherd_ps256(
        __builtin_convertvector((float8)(0.0f), FcLanesV8sf), (const float*)(size_t)base,
        __builtin_convertvector(as_int8(index), FcLanesV8si), __builtin_convertvector((float8)(-1.0f), FcLanesV8sf), 4);
    return __builtin_convertvector(g, float8);
#else
    uint at[FC_LW];
    float v[FC_LW];
    LSTORE(index, at);
    for (int j = 0; j < FC_LW; ++j) v[j] = base[at[j]];
    return LLOAD(v);
#endif
}

#undef FACET_LANES_GATHER_LANES_PASS
#endif
