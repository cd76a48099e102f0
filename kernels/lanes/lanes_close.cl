/* Closes an instantiation opened by kernels/lanes/lanes_open.cl. */
#ifndef FACET_LANES_CLOSE_PASS
#define FACET_LANES_CLOSE_PASS

#undef LFLOAT
#undef LINT
#undef LUINT
#undef LULONG
#undef LVEC2
#undef LVEC3
#undef LNAME
#undef LCONVERT_FLOAT
#undef LCONVERT_INT
#undef LCONVERT_UINT
#undef LCONVERT_ULONG
#undef LAS_FLOAT
#undef LAS_INT
#undef LLOAD
#undef LSTORE
#undef FC_LW

#undef FACET_LANES_CLOSE_PASS
#endif
