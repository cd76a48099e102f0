// Which renders run their paths in packets (issue 29): eight paths a work-item in float8
// lanes (kernels/integrator/packet_paths.cl), where one path a work-item (render_pass)
// leaves a CPU's vector units scalar. Policy only: the kernel computes render_pass's
// samples (PacketRender.* checks it).
#pragma once

#include <cstdint>

#include "host/cl/runtime.hpp"
#include "host/render/features.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {

// packet_pass's work-items: one for every FC_PACKET_WIDTH pixels of a row (a pixel a lane).
inline std::uint32_t packet_items_per_row(std::uint32_t width) {
    return (width + FC_PACKET_WIDTH - 1u) / FC_PACKET_WIDTH;
}

// Whether a program with these features, for this sampler (FC_SAMPLER_*), runs packets on
// this device: its features are the packet kernel's (triangle area lights and Lambertian
// materials: no other flag of kernels/shared/feature_flags.h), the sampler is Sobol' (the
// lanes' sampler), the program is specialised, and the device is a CPU whose native float
// vectors are 8 wide or more (where the BVH is 8-wide too: host/bvh/bvh_width.hpp; on GPUs
// a work-item's float8 is eight lanes' scalar work). FACET_PACKET_PATHS=0 turns packets off
// (for comparisons); FACET_PACKET_PATHS=1 runs them on any device where the rest holds (for
// checks: the Oclgrind tier runs packet_pass on its simulated device, whose vectors are 1 wide).
bool packet_paths_for(const DeviceDesc& device, unsigned native_float_vector_width, FeatureMask features,
                      std::uint32_t sampler, bool generic);

}  // namespace facet
