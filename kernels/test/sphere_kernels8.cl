/* The test kernels of sphere_kernels.cl over 8-wide nodes (FcBvhNode8): the spheres' tree
 * has the triangles' tree's width, and tests/sphere_test.cpp traces both. */
#define FC_BVH_WIDTH 8
#include "kernels/test/sphere_kernels.cl"
