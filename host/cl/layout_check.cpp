// Compile-time checks of the shared layouts on the host: every struct is a multiple
// of 16 bytes and free of padding the device might lay out differently. The run-time
// comparison with the device is tests/layout_test.cpp.
#include <cstddef>
#include <type_traits>

#include "shared/all.h"
#include "shared/layout_fields.h"

namespace facet {

#define FC_CHECK_STRUCT(T)                                                            \
    static_assert(sizeof(T) % 16 == 0, #T " must be a multiple of 16 bytes");        \
    static_assert(std::is_standard_layout_v<T> && std::is_trivially_copyable_v<T>,  \
                  #T " must be a plain C struct");                                   \
    static_assert(alignof(T) == 4, #T " must contain only 4-byte scalars");
FC_LAYOUT_STRUCTS(FC_CHECK_STRUCT)
#undef FC_CHECK_STRUCT

static_assert(offsetof(FcBvhNode, hi_x) == 48 && offsetof(FcBvhNode, index) == 96);
static_assert(offsetof(FcTriangle, v1) == 16 && offsetof(FcTriangle, v2) == 32);
static_assert(offsetof(FcTriShading, n1) == 16 && offsetof(FcTriShading, n2) == 32);
static_assert(offsetof(FcMaterial, emission) == 32 && offsetof(FcMaterial, flags) == 104);
static_assert(offsetof(FcLight, e1) == 16 && offsetof(FcLight, pick_pdf) == 60);
static_assert(offsetof(FcCamera, up) == 48);
static_assert(offsetof(FcRenderParams, width) == 64 && offsetof(FcRenderParams, row_count) == 100);

}  // namespace facet
