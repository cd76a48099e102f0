// The BVH node width for a device (kernels/shared/bvh_layout.h: FcBvhNode or FcBvhNode8),
// defined in host/bvh/bvh.cpp.
#pragma once

namespace facet {

// The node width for a device: FACET_BVH_WIDTH when set; else 8 on a CPU whose native
// float vectors are 8 wide or more (AVX2 and up: PoCL emits one ymm operation per float8,
// and 8-wide nodes traced 25-30% more diffuse rays per CPU-second on the full dragon,
// docs/performance.md), 4 elsewhere (GPUs, where one work-item's float8 is eight lanes'
// scalar work, and narrower CPUs).
int bvh_width_for(bool gpu, unsigned native_float_vector_width);

}  // namespace facet
