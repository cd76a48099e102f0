// Binned SAH builder (Wald 2007, "On fast construction of SAH-based bounding volume
// hierarchies"): reorders an array of primitive references (with one scratch copy) and writes a
// binary tree of BinaryNode, which bvh.cpp collapses into the 4-wide FcBvhNode of
// kernels/shared/bvh_layout.h.
#pragma once

#include <cstdint>
#include <vector>

#include "host/bvh/bvh.hpp"

namespace facet::bvh_detail {

// A primitive's bounds and its index in the caller's triangle list (32 bytes, so the
// partition moves whole references and every pass reads memory in order).
struct PrimRef {
    float lo[3];
    std::uint32_t id;
    float hi[3];
    float pad;
};

// Two children per node: a child reference is an inner node (count 0, index = node
// index), a leaf (count > 0, index = first reference) or empty (count 0, index 0,
// inverted box).
struct BinaryNode {
    float a_min[3];
    std::int32_t a_index;
    float a_max[3];
    std::int32_t a_count;
    float b_min[3];
    std::int32_t b_index;
    float b_max[3];
    std::int32_t b_count;
};

struct BuildOutput {
    std::vector<BinaryNode> nodes;
    double sah_cost = 0.0;  // normalised by the root's surface area
    std::size_t leaves = 0;
    int max_depth = 0;  // binary nodes on the longest root-to-leaf path
    int max_leaf_size = 0;
};

// Deepest leaf the builder makes; below this it switches to median splits, so the
// 4-wide tree is at most kMaxLeafDepth / 2 nodes deep and the traversal stack (three
// pushes per node, FC_BVH_STACK_SIZE entries) never overflows.
constexpr int kMaxLeafDepth = 42;
static_assert(3 * (kMaxLeafDepth / 2) <= FC_BVH_STACK_SIZE);

// Builds over `refs` (reordered in place: leaf [index, index+count) is refs[index...]).
BuildOutput build_sah(std::vector<PrimRef>& refs, const BvhOptions& options);

// The child reference of an empty tree or of the root's unused slot: an inner-node
// reference (count 0) whose box is inverted (lo = +inf, hi = -inf), which the slab
// test in kernels/trace/bvh_traverse.cl never reports as hit.
void set_empty_child(BinaryNode& node, int side);

}  // namespace facet::bvh_detail
