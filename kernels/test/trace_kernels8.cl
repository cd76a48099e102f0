/* The test kernels of trace_kernels.cl over 8-wide nodes (FcBvhNode8): tests/bvh_test.cpp
 * runs every traversal test for each node layout. */
#define FC_BVH_WIDTH 8
#include "kernels/test/trace_kernels.cl"
