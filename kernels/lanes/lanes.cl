/* Lane-generic kernel code (issue 29): formulas written once over a lane type and compiled
 * at several widths, so that one work-item can run W paths at once in vector lanes (W = 8
 * on AVX CPUs) while every other kernel, and every GPU, runs the same source at W = 1.
 *
 * A generic body is a file of this folder that is included between lanes_open.cl and
 * lanes_close.cl with FC_LW set to the width (1, 4, 8 or 16). Inside it:
 * - LFLOAT, LINT, LUINT, LULONG are the lane types (float, float4, float8 or float16, ...);
 * - LVEC3 is a 3-vector of lanes: float3 at W = 1, FcVec3x4 / FcVec3x8 (three vectors of
 *   lanes, structure of arrays) above, with the members .x, .y, .z either way; LVEC2 the
 *   same with two;
 * - LNAME(f) is f's name at this width: f_l1, f_l4, f_l8, f_l16;
 * - a comparison gives a lane mask (1 or -1 where true, 0 where false): combine masks
 *   with & and | only, pick with select(), and test with LNAME(lanes_any) (OpenCL's any()
 *   reads a scalar's sign bit, which a scalar comparison's 1 does not set). A mask is
 *   negated by the opposite comparison (NaN-aware: !(a >= b) is (a < b) | isnan(a)), never by
 *   ~ or == 0: at W = 1 ~1 is -2, still true, and Oclgrind 21.10 evaluates the vector NOT of
 *   comparison lanes that LLVM makes of either to 1 or -2 instead of -1 and 0;
 * - a structure of the body's own (beyond LVEC2 and LVEC3) is returned through a pointer:
 *   returned by value, a pair of float8 lanes (plain_base_lanes.cl's view) left an
 *   llvm.experimental.noalias.scope.decl that Oclgrind 21.10 cannot run.
 * Branches on lane values become selects, so a width-8 call computes what eight width-1
 * calls compute, the same operations in the same order: the tests demand the same bits
 * (tests/lanes_test.cpp). The scalar kernels call the W = 1 forms through their usual
 * functions (kernels/lanes/scalar.cl); kernels/lanes/packet.cl instantiates W = FC_PACKET_WIDTH (8 or 16). */
#ifndef FACET_LANES_LANES_CL
#define FACET_LANES_LANES_CL

#include "kernels/util/math.cl"

typedef struct {
    float4 x, y;
} FcVec2x4;

typedef struct {
    float8 x, y;
} FcVec2x8;

typedef struct {
    float16 x, y;
} FcVec2x16;

typedef struct {
    float4 x, y, z;
} FcVec3x4;

typedef struct {
    float16 x, y, z;
} FcVec3x16;

typedef struct {
    float8 x, y, z;
} FcVec3x8;

#if defined(__AVX__) && defined(__clang__)
/* eight and sixteen floats as clang's x86 builtins take them (vec3_lanes.cl's lanes_any,
 * gather_lanes.cl) */
typedef float FcLanesV8sf __attribute__((__vector_size__(32)));
typedef float FcLanesV16sf __attribute__((__vector_size__(64)));
/* eight and sixteen ints as clang's AVX2 and AVX-512 builtins take them */
typedef int FcLanesV8si __attribute__((__vector_size__(32)));
typedef int FcLanesV16si __attribute__((__vector_size__(64)));
#endif

#define FC_LANES_PASTE(f, w) f##_l##w
#define FC_LANES_NAME(f, w) FC_LANES_PASTE(f, w)

#endif
