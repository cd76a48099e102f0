/* microfacet_kernels.cl built as a program of a scene without clearcoat and sheen
 * (FC_HAS_CLEARCOAT and FC_HAS_SHEEN 0), for tests/clearcoat_sheen_test.cpp: the layers
 * off give the material of before, bit for bit. */
#define FC_HAS_CLEARCOAT 0
#define FC_HAS_SHEEN 0
#include "kernels/test/microfacet_kernels.cl"
