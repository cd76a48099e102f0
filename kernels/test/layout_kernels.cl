/* Reports the device's sizeof/offsetof of every shared struct (tests/layout_test.cpp
 * compares them with the host's). Output: sizes first, then offsets, in the order of
 * kernels/shared/layout_fields.h. */
#ifndef FACET_TEST_LAYOUT_KERNELS_CL
#define FACET_TEST_LAYOUT_KERNELS_CL

#include "kernels/shared/all.h"
#include "kernels/shared/layout_fields.h"

__kernel void report_layout(__global int* out) {
    if (get_global_id(0) != 0) return;
    int i = 0;
#define FC_SIZE(T) out[i++] = (int)sizeof(T);
#define FC_OFFSET(T, f) out[i++] = (int)__builtin_offsetof(T, f);
    FC_LAYOUT_STRUCTS(FC_SIZE)
    FC_LAYOUT_FIELDS(FC_OFFSET)
#undef FC_SIZE
#undef FC_OFFSET
}

#endif
