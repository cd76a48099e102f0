#include "host/bvh/binary_tree.hpp"

namespace facet {

std::vector<FcBinaryNode> build_binary_tree(std::vector<bvh_detail::PrimRef>& refs, int max_leaf_size) {
    BvhOptions options;
    options.max_leaf_size = max_leaf_size;
    options.block_size = 1;  // the kernels test a leaf's primitives one at a time
    // A primitive test (a sphere, an instance's box) against a node visit (two boxes): 1, as
    // measured for the spheres' tree; the triangles' 4-lane block test costs 4
    // (docs/performance.md, "The SAH's block test cost")
    options.intersection_cost = 1.0f;
    const bvh_detail::BuildOutput built = bvh_detail::build_sah(refs, options);
    std::vector<FcBinaryNode> nodes;
    nodes.reserve(built.nodes.size());
    for (const bvh_detail::BinaryNode& b : built.nodes) {
        FcBinaryNode& n = nodes.emplace_back();
        for (int a = 0; a < 3; ++a) {
            n.a_lo[a] = b.a_min[a];
            n.a_hi[a] = b.a_max[a];
            n.b_lo[a] = b.b_min[a];
            n.b_hi[a] = b.b_max[a];
        }
        n.a_index = b.a_index;
        n.a_count = b.a_count;
        n.b_index = b.b_index;
        n.b_count = b.b_count;
    }
    return nodes;
}

}  // namespace facet
