/* Opens an instantiation of lane-generic bodies at width FC_LW (kernels/lanes/lanes.cl);
 * kernels/lanes/lanes_close.cl ends it. Included once per instantiation: its guard is
 * released at its end. */
#ifndef FACET_LANES_OPEN_PASS
#define FACET_LANES_OPEN_PASS

#include "kernels/lanes/lanes.cl"

#if FC_LW == 1
#define LFLOAT float
#define LINT int
#define LUINT uint
#define LULONG ulong
#define LVEC2 float2
#define LVEC3 float3
#define LCONVERT_FLOAT convert_float
#define LCONVERT_INT convert_int
#define LCONVERT_UINT convert_uint
#define LCONVERT_ULONG convert_ulong
#define LAS_FLOAT as_float
#define LAS_INT as_int
#define LLOAD(a) (*(a))
#define LSTORE(v, a) (*(a) = (v))
#elif FC_LW == 4
#define LFLOAT float4
#define LINT int4
#define LUINT uint4
#define LULONG ulong4
#define LVEC2 FcVec2x4
#define LVEC3 FcVec3x4
#define LCONVERT_FLOAT convert_float4
#define LCONVERT_INT convert_int4
#define LCONVERT_UINT convert_uint4
#define LCONVERT_ULONG convert_ulong4
#define LAS_FLOAT as_float4
#define LAS_INT as_int4
#define LLOAD(a) vload4(0, a)
#define LSTORE(v, a) vstore4(v, 0, a)
#elif FC_LW == 8
#define LFLOAT float8
#define LINT int8
#define LUINT uint8
#define LULONG ulong8
#define LVEC2 FcVec2x8
#define LVEC3 FcVec3x8
#define LCONVERT_FLOAT convert_float8
#define LCONVERT_INT convert_int8
#define LCONVERT_UINT convert_uint8
#define LCONVERT_ULONG convert_ulong8
#define LAS_FLOAT as_float8
#define LAS_INT as_int8
#define LLOAD(a) vload8(0, a)
#define LSTORE(v, a) vstore8(v, 0, a)
#elif FC_LW == 16
#define LFLOAT float16
#define LINT int16
#define LUINT uint16
#define LULONG ulong16
#define LVEC2 FcVec2x16
#define LVEC3 FcVec3x16
#define LCONVERT_FLOAT convert_float16
#define LCONVERT_INT convert_int16
#define LCONVERT_UINT convert_uint16
#define LCONVERT_ULONG convert_ulong16
#define LAS_FLOAT as_float16
#define LAS_INT as_int16
#define LLOAD(a) vload16(0, a)
#define LSTORE(v, a) vstore16(v, 0, a)
#else
#error "FC_LW must be 1, 4, 8 or 16"
#endif
#define LNAME(f) FC_LANES_NAME(f, FC_LW)

#undef FACET_LANES_OPEN_PASS
#endif
