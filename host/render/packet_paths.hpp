// Which renders run their paths in packets (issue 29): 8 or 16 paths a work-item in float8 or
// float16 lanes (kernels/integrator/packet_paths.cl), where one path a work-item (render_pass)
// leaves a CPU's vector units scalar. Policy only: the kernel computes render_pass's
// samples (PacketRender.* checks it).
#pragma once

#include <cstddef>
#include <cstdint>

#include "host/bvh/bvh.hpp"
#include "host/cl/runtime.hpp"
#include "host/render/features.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {

// packet_pass's work-items for a row of `width` pixels in a launch of `samples` samples per
// pixel: one for every fc_packet_pixels (kernels/shared/render_layout.h) pixels.
inline std::uint32_t packet_items_per_row(std::uint32_t width, std::uint32_t packet_width, std::uint32_t samples) {
    const std::uint32_t run = fc_packet_pixels(packet_width, width, samples);
    return (width + run - 1u) / run;
}

// The packets' width on a device whose native float vectors are this wide: 16 where they are
// 16 wide or more (AVX-512), else 8 (the program's FC_PACKET_WIDTH). FACET_PACKET_WIDTH=8 or
// 16 chooses it (for comparisons, and for tests of the 16-wide form on any CPU).
std::uint32_t packet_width_for(unsigned native_float_vector_width);

// The features packet_pass covers: triangle area lights, punctual lights and the environment
// (the lights it samples; a program needs one of them), spheres, textures and alpha
// (cut-outs), and every material: a Lambertian lobe in the lanes, any other BSDF per lane
// (layers, metal, anisotropy, glass and absorbing volumes included). Not instances.
FeatureMask packet_features();

// Whether every light of `scene` is one packet_pass samples: an emitting triangle, a point,
// spot or directional light, or the environment (emitting spheres are area lights too, of
// another shape, which it does not sample).
bool lights_in_packets(const Scene& scene);

// Whether every material the scene's surfaces use is a Lambertian lobe alone (diffuse model
// lambert, no specular lobe, no layer): then packet_pass runs the BSDF in its lanes only; else
// the renderer defines FC_PACKET_BSDF_PER_LANE and the other materials' BSDFs run per lane
// (EON, the Lambert x (1 - F0) base and a lobe-less material among them, which have no feature
// of their own).
bool lambertian_materials(const Scene& scene);

// Whether a program with these features, for this sampler (FC_SAMPLER_*), runs packets on
// this device: its features are within packet_features() and include a light, every light is
// one packet_pass samples (`packet_lights`: lights_in_packets), the sampler is Sobol' (the
// lanes' sampler), the program is specialised, and the device is a CPU whose native float
// vectors are 8 wide or more (where the BVH is 8-wide too: host/bvh/bvh_width.hpp; on GPUs a
// work-item's float8 is eight lanes' scalar work). FACET_PACKET_PATHS=0 turns packets off (for
// comparisons); FACET_PACKET_PATHS=1 runs them on any device where the rest holds (for checks:
// the Oclgrind tier runs packet_pass on its simulated device, whose vectors are 1 wide).
bool packet_paths_for(const DeviceDesc& device, unsigned native_float_vector_width, FeatureMask features,
                      bool packet_lights, std::uint32_t sampler, bool generic);

// The largest triangles' tree whose rays packet_pass traces in packets
// (kernels/trace/packet_trace.cl). A packet meets every leaf one of its rays needs, so its
// gain falls as the tree grows and its rays part: Cornell box (32 triangles) +3-6 %, Spot
// (5.9 k) +19 %, the bunny (69 k) even, dragon_res2 (203 k) -13 % samples per second
// (docs/performance.md, "Rays traced in packets").
inline constexpr std::size_t kPacketTraceUpToTriangles = 50000;

// Whether packet_pass traces its rays in packets, where it can (on 8-wide nodes, without
// cut-outs), for a triangles' tree of this size: up to kPacketTraceUpToTriangles.
// FACET_PACKET_TRACE=0 or 1 says so whatever the size (for comparisons and checks).
bool packet_trace_for(std::size_t tree_triangles);

// The largest triangles' tree in which every ray of a packet stays in it down to the leaves
// (FC_PACKET_TRACE_MIN 1): at most two levels of 8-wide nodes over leaves of a few
// triangles, where a subtree left to the rays that still need it is a leaf or two and the
// hand-over to single rays (kernels/trace/packet_trace.cl) costs more than it saves: the
// Cornell box (32 triangles) +4 % samples per second, Spot (5.9 k) -5 %
// (docs/performance.md, "Every ray of a packet to the leaves in the smallest trees").
inline constexpr std::size_t kPacketTraceTogetherUpToTriangles = 64;

// The fewest of a packet's rays that enter a node together (FC_PACKET_TRACE_MIN); fewer
// finish its subtree one by one. 1 (never by one) in trees of up to
// kPacketTraceTogetherUpToTriangles, else 4. FACET_PACKET_TRACE_MIN=N, 1 to 16, says N
// whatever the size (for comparisons).
std::uint32_t packet_trace_min_for(std::size_t tree_triangles);

// The SAH's cost of a leaf triangle, in node visits, in a tree whose rays packet_pass traces
// to the leaves together (FC_PACKET_TRACE_MIN 1). A packet meets a leaf's triangles one after
// another, each in all its lanes, where a single ray meets a block of four in one test; so
// there the SAH counts triangles, not blocks (BvhOptions::block_size 1), and a triangle test
// costs about two visits of an 8-wide node (eight child boxes in all lanes). Its leaves come
// out smaller (the Cornell box: 17 leaves of at most 2 triangles, where blocks of 4 made 11
// of up to 8), and a packet skips the triangles of the boxes none of its rays meet: the
// Cornell box +3-4 % samples per second (docs/performance.md, "The SAH of the trees packets
// trace to the leaves"). Larger trees, whose rays part and finish alone on blocks of four,
// keep the blocked SAH (Suzanne's 970 triangles -9 % with it).
inline constexpr float kPacketLeafTriangleCost = 2.0f;

// Sets `options` (block size and intersection cost) for a tree of `triangles` triangles whose
// packets keep every ray to the leaves (packet_trace_min_for 1), when `packets` (the device
// that renders runs packet_pass: packet_paths_for) and packet_pass traces such a tree
// (packet_trace_for); leaves them as they are otherwise.
void packet_tree_options(BvhOptions& options, std::size_t triangles, bool packets);

// What packet_paths_for asks, said for `facet info` when a program does not run packets.
const char* packet_paths_requirements();

}  // namespace facet
