// Compile-time checks of the shared layouts on the host: every struct is a multiple
// of 16 bytes and free of padding the device might lay out differently. The run-time
// comparison with the device is tests/layout_test.cpp; each struct's size and offset checks
// sit beside the struct in its kernels/shared/ header.
#include <cstddef>
#include <type_traits>

#include "kernels/shared/all.h"
#include "kernels/shared/layout_fields.h"

namespace facet {

#define FC_CHECK_STRUCT(T)                                                                                          \
    static_assert(sizeof(T) % 16 == 0, #T " must be a multiple of 16 bytes");                                       \
    static_assert(std::is_standard_layout_v<T> && std::is_trivially_copyable_v<T>, #T " must be a plain C struct"); \
    static_assert(alignof(T) == 4, #T " must contain only 4-byte scalars");
FC_LAYOUT_STRUCTS(FC_CHECK_STRUCT)
#undef FC_CHECK_STRUCT

}  // namespace facet
