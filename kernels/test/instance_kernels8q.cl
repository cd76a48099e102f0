/* The test kernels of instance_kernels.cl over quantised 8-wide nodes (FcBvhNodeQ, the
 * default for 8-wide trees): tests/instancing_test.cpp traces every node layout. */
#define FC_BVH_WIDTH 8
#define FC_BVH_QUANTISED 1
#include "kernels/test/instance_kernels.cl"
