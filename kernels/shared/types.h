/* Scalar types shared by the host (C++) and the kernels (OpenCL C).
 *
 * Rules for every struct in kernels/shared/ (see docs/conventions.md):
 *  - only 4-byte scalars (float, fc_int, fc_uint) and arrays of them;
 *  - grouped so each struct is a multiple of 16 bytes, with explicit padding;
 *  - never float3/cl_float3/glm types, bool, size_t or enums (their sizes differ
 *    between host and device).
 * The host checks sizes and offsets with static_assert beside each struct (FC_STATIC_ASSERT) and a
 * test asks a kernel for sizeof/offsetof (tests/layout_test.cpp). */
#ifndef FACET_SHARED_TYPES_H
#define FACET_SHARED_TYPES_H

#if defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
typedef int fc_int;
typedef uint fc_uint;
#define FC_STATIC_ASSERT(cond, msg)
#else
#include <stddef.h>
#include <stdint.h>
typedef int32_t fc_int;
typedef uint32_t fc_uint;
#define FC_STATIC_ASSERT(cond, msg) static_assert(cond, msg)
#endif

#endif
