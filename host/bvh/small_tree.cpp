#include "host/bvh/small_tree.hpp"

#include "host/bvh/bvh.hpp"

namespace facet {

std::vector<FcBvhNode> build_small_tree(std::vector<bvh_detail::PrimRef>& refs, const SmallTreeCosts& costs,
                                        int width) {
    BvhOptions options;
    options.max_leaf_size = costs.max_leaf_size;
    options.block_size = 1;  // the kernels test a leaf's primitives one at a time
    options.intersection_cost = costs.intersection_cost;
    return bvh_detail::collapse_float_tree(bvh_detail::build_sah(refs, options).nodes, width);
}

}  // namespace facet
