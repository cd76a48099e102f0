/* The test kernels of instance_kernels.cl over 8-wide nodes (FcBvhNode8): the instanced
 * meshes' trees have the world tree's width, and tests/instancing_test.cpp traces both. */
#define FC_BVH_WIDTH 8
#include "kernels/test/instance_kernels.cl"
