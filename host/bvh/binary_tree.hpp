// The binary BVHs of kernels/shared/binary_node_layout.h (the analytic spheres' tree and the
// instances' top level): host/bvh's SAH builder over primitive boxes, its nodes stored as
// FcBinaryNode, traversed by kernels/trace/binary_traverse.cl.
#pragma once

#include <vector>

#include "host/bvh/sah_builder.hpp"
#include "kernels/shared/binary_node_layout.h"

namespace facet {

static_assert(bvh_detail::kMaxLeafDepth + 1 <= FC_BINARY_STACK_SIZE,
              "the binary traversal pushes one child per level of the tree");

// Builds the tree over `refs` (reordered in place: leaf [index, index + count) is
// refs[index...]), at most `max_leaf_size` primitives a leaf, each tested alone. No refs
// give a root with two empty children.
std::vector<FcBinaryNode> build_binary_tree(std::vector<bvh_detail::PrimRef>& refs, int max_leaf_size);

}  // namespace facet
