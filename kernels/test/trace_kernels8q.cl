/* The test kernels of trace_kernels.cl over quantised 8-wide nodes (FcBvhNodeQ):
 * tests/bvh_test.cpp runs every traversal test for each node layout. */
#define FC_BVH_WIDTH 8
#define FC_BVH_QUANTISED 1
#include "kernels/test/trace_kernels.cl"
