// facet's small trees (the analytic spheres' and the instances' top level): host/bvh's SAH
// builder over primitive boxes, collapsed into float wide nodes of the program's width
// (FcBvhNode or FcBvhNode8, as FcBvhNode units), each leaf a range of the primitives,
// traversed by kernels/trace/small_tree_traverse.cl.
#pragma once

#include <vector>

#include "host/bvh/sah_builder.hpp"
#include "kernels/shared/bvh_layout.h"

namespace facet {

// How the kernels test a tree's leaves, for its SAH: at most `max_leaf_size` primitives a
// leaf, each tested alone, a test costing `intersection_cost` node visits.
struct SmallTreeCosts {
    int max_leaf_size = 2;
    float intersection_cost = 1.0f;
};

// Builds the tree over `refs` (reordered in place: leaf [index, index + count) is
// refs[index...]) with nodes of `width` (4 or 8). No refs give a root whose slots are all
// empty. Throws (an Error) on a width other than 4 or 8.
std::vector<FcBvhNode> build_small_tree(std::vector<bvh_detail::PrimRef>& refs, const SmallTreeCosts& costs, int width);

}  // namespace facet
