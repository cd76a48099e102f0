/* Lane-generic body (kernels/lanes/lanes.cl): 3-vectors of lanes and lane masks. At W = 1
 * these are float3's own operations written out by component, so that every width rounds
 * alike. */
#ifndef FACET_LANES_VEC3_PASS
#define FACET_LANES_VEC3_PASS

#if FC_LW == 1
inline LVEC2 LNAME(vec2)(LFLOAT x, LFLOAT y) { return (float2)(x, y); }
inline LVEC3 LNAME(vec3)(LFLOAT x, LFLOAT y, LFLOAT z) { return (float3)(x, y, z); }
/* Whether any lane of a mask is set. */
inline bool LNAME(lanes_any)(LINT m) { return m != 0; }
#else
inline LVEC2 LNAME(vec2)(LFLOAT x, LFLOAT y) {
    LVEC2 v;
    v.x = x;
    v.y = y;
    return v;
}
inline LVEC3 LNAME(vec3)(LFLOAT x, LFLOAT y, LFLOAT z) {
    LVEC3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
#if defined(__AVX__) && defined(__clang__) && FC_LW >= 8
/* Whether any lane of a mask is set: its sign bits in one movmskps. PoCL 3.1 lowers any() to
 * a test of each lane's pair in turn, with a branch each (about a quarter of the instructions
 * of packet_sphere.cl's box tests, read in PoCL's code under callgrind). */
#if FC_LW == 8
inline bool LNAME(lanes_any)(LINT m) {
    return __builtin_ia32_movmskps256(__builtin_convertvector(as_float8(m), FcLanesV8sf)) != 0;
}
#elif defined(__AVX512DQ__)
/* With AVX-512 the sixteen lanes' sign bits are one mask register (vpmovd2m), which LLVM
 * folds into the comparison that made m: one kortest, where the movmskps form widens the
 * comparison's mask to a vector, halves it and ors the halves first. */
inline bool LNAME(lanes_any)(LINT m) {
    return __builtin_ia32_cvtd2mask512(__builtin_convertvector(m, FcLanesV16si)) != 0;
}
#else
inline bool LNAME(lanes_any)(LINT m) {
    return __builtin_ia32_movmskps256(__builtin_convertvector(as_float8(m.lo | m.hi), FcLanesV8sf)) != 0;
}
#endif
#else
inline bool LNAME(lanes_any)(LINT m) { return any(m); }
#endif
#endif

inline LFLOAT LNAME(vec3_dot)(LVEC3 a, LVEC3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline LVEC3 LNAME(vec3_add)(LVEC3 a, LVEC3 b) { return LNAME(vec3)(a.x + b.x, a.y + b.y, a.z + b.z); }
inline LVEC3 LNAME(vec3_sub)(LVEC3 a, LVEC3 b) { return LNAME(vec3)(a.x - b.x, a.y - b.y, a.z - b.z); }
inline LVEC3 LNAME(vec3_mul)(LVEC3 a, LVEC3 b) { return LNAME(vec3)(a.x * b.x, a.y * b.y, a.z * b.z); }
inline LVEC3 LNAME(vec3_scale)(LVEC3 a, LFLOAT s) { return LNAME(vec3)(a.x * s, a.y * s, a.z * s); }
inline LVEC3 LNAME(vec3_neg)(LVEC3 a) { return LNAME(vec3)(-a.x, -a.y, -a.z); }
/* b where the mask is set, a elsewhere (OpenCL's select, per component). */
inline LVEC3 LNAME(vec3_select)(LVEC3 a, LVEC3 b, LINT m) {
    return LNAME(vec3)(select(a.x, b.x, m), select(a.y, b.y, m), select(a.z, b.z, m));
}
/* The combination x s + y t + z n of three 3-vectors (a local direction to world). */
inline LVEC3 LNAME(vec3_combine)(LFLOAT x, LVEC3 s, LFLOAT y, LVEC3 t, LFLOAT z, LVEC3 n) {
    return LNAME(vec3)(x * s.x + y * t.x + z * n.x, x * s.y + y * t.y + z * n.y, x * s.z + y * t.z + z * n.z);
}

#undef FACET_LANES_VEC3_PASS
#endif
