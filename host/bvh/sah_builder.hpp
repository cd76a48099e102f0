// Binned SAH builder (Wald 2007, "On fast construction of SAH-based bounding volume
// hierarchies"): works in place on an array of primitive references and writes the
// two-children-per-node layout of kernels/shared/bvh.h directly.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/bvh.hpp"

namespace facet::bvh_detail {

// A primitive's bounds and its index in the caller's triangle list (32 bytes, so the
// partition moves whole references and every pass reads memory in order).
struct PrimRef {
    float lo[3];
    std::uint32_t id;
    float hi[3];
    float pad;
};

struct BuildOutput {
    std::vector<FcBvhNode> nodes;
    double sah_cost = 0.0;      // normalised by the root's surface area
    std::size_t leaves = 0;
    int max_depth = 0;          // nodes on the longest root-to-leaf path
    int max_leaf_size = 0;
};

// Deepest leaf the builder makes; below this it switches to median splits, so the
// traversal stack (FC_BVH_STACK_SIZE entries) never overflows.
constexpr int kMaxLeafDepth = 56;

// Builds over `refs` (reordered in place: leaf [index, index+count) is refs[index...]).
BuildOutput build_sah(std::vector<PrimRef>& refs, const BvhOptions& options);

// The child reference of an empty tree or of the root's unused slot: an inner-node
// reference (count 0) whose box is inverted (lo = +inf, hi = -inf), which the slab
// test in kernels/trace/bvh.cl never reports as hit.
void set_empty_child(FcBvhNode& node, int side);

}  // namespace facet::bvh_detail
