/* The test kernels of trace_kernels.cl over 8-wide nodes (FcBvhNode8): tests/bvh_test.cpp
 * and tests/bvh_width_test.cpp run every traversal test for both node widths. */
#define FC_BVH_WIDTH 8
#include "kernels/test/trace_kernels.cl"
