// Bounding volume hierarchy over a triangle soup: a binned SAH build on the host,
// flattened into the layout of kernels/shared/bvh_layout.h for the traversal kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "kernels/shared/bvh_layout.h"

namespace facet {

struct BvhOptions {
    int bins = 12;                     // SAH bins per axis
    int max_leaf_size = 8;             // a leaf never holds more triangles than this
    int exact_max = 16;                // ranges up to this size get the exact SAH sweep (0: bin everywhere)
    float traversal_cost = 1.0f;       // SAH cost of visiting a node, relative to...
    float intersection_cost = 4.0f;    // ...the cost of one ray/triangle block test: fitted to the
                                       // trace kernels' instructions on PoCL (docs/performance.md,
                                       // "The SAH's block test cost"), flat from 4 on
    int block_size = 4;                // triangles tested at once (FcTriBlock lanes): a leaf of n costs
                                       // ceil(n / block_size) tests (Embree's blocked SAH); 1, 2, 4 or 8
    int width = 0;                     // node width, 4 (FcBvhNode) or 8 (FcBvhNode8); 0: FACET_BVH_WIDTH
                                       // when set, else 4 (bvh_width_for picks one for a device)
    int quantised = -1;                // 8-wide trees: 1 quantised child boxes (FcBvhNodeQ, 80-byte
                                       // nodes), 0 float boxes (FcBvhNode8); -1: FACET_BVH_QUANTISED
                                       // when set, else by size (kQuantiseAboveTriangles, where the
                                       // leaves fit)
    std::size_t layout_triangles = 0;  // the triangles that choice counts: 0, the tree's own; a
                                       // scene with instances passes all it stores, since its
                                       // instanced meshes' trees take the world tree's layout
};

// Whether 8-wide trees are quantised when neither BvhOptions::quantised nor
// FACET_BVH_QUANTISED says: above this many triangles. Quantised boxes take a third of the
// float nodes' bytes, which pays on large meshes (the full dragon's closest-hit rays 8 %
// faster), but their decoding costs instructions, which small trees pay for with nothing
// (the Cornell box's render kernel 8.8 % fewer instructions with float boxes, 6 % more
// samples per second; the bunny's and dragon_res2's rays as fast or faster):
// docs/performance.md, "Float or quantised boxes, by size".
inline constexpr std::size_t kQuantiseAboveTriangles = 150000;

struct BvhStats {
    std::size_t triangles = 0;
    int width = 4;                 // node width: 4 (FcBvhNode) or 8 (FcBvhNode8 or FcBvhNodeQ)
    int quantised = 0;             // 1: the 8-wide nodes are FcBvhNodeQ
    std::size_t nodes = 0;         // wide node count (FcBvhNode, FcBvhNode8 or FcBvhNodeQ)
    std::size_t leaf_blocks = 0;   // FcTriBlock count (four triangle lanes each)
    std::size_t binary_nodes = 0;  // nodes of the binary SAH tree it was collapsed from
    std::size_t leaves = 0;
    int max_depth = 0;   // wide nodes on the longest root-to-leaf path
    int stack_need = 0;  // most traversal stack entries a root-to-leaf path can push
    int max_leaf_size = 0;
    double sah_cost = 0.0;         // of the binary SAH tree (leaves counted in blocks of
                                   // BvhOptions::block_size), normalised by the root's surface area
    double build_seconds = 0.0;    // all of build_bvh: filtering and per-triangle bounds, the
                                   // binary SAH build, the 4-wide collapse, the packed
                                   // triangles in leaf order, freeing the builder's buffers
    std::size_t device_bytes = 0;  // node buffer (nodes + leaf blocks) + triangles as uploaded
};

struct Bvh {
    // The node buffer as uploaded, in 128-byte units: the stats.nodes wide nodes of the
    // tree first (the root first; an FcBvhNode8 takes two units, an FcBvhNodeQ 80 bytes),
    // then the leaves' FcTriBlock, addressed in 16-byte rows from the start
    // (kernels/shared/bvh_layout.h); read them with wide_node4/8() and leaf_block().
    // Programs that trace it are built with bvh_prelude(*this).
    std::vector<FcBvhNode> nodes;
    std::vector<FcTriangle> triangles;  // reordered; FcTriangle::prim is the input index
    BvhStats stats;
};

namespace bvh_detail {
struct BinaryNode;
// The binary tree `bin` (host/bvh/sah_builder.hpp) collapsed into float wide nodes of
// `width` (4: FcBvhNode, 8: FcBvhNode8), as the FcBvhNode units a node buffer holds, each
// leaf keeping its primitive range (index, count) as the builder left it: the small trees'
// layout (host/bvh/small_tree.hpp). Throws when a path would push more than the
// traversal's stack holds.
std::vector<FcBvhNode> collapse_float_tree(const std::vector<BinaryNode>& bin, int width);
}  // namespace bvh_detail

// The node width that `options.width` asks for (0: FACET_BVH_WIDTH when set, else 4);
// throws an Error naming the bad value.
int resolve_width(int width);

// Whether an 8-wide tree of `triangles` triangles built with `options` is quantised
// (BvhOptions::quantised, else FACET_BVH_QUANTISED, else when BvhOptions::layout_triangles,
// or without it `triangles`, exceeds kQuantiseAboveTriangles, and every leaf fits
// FcBvhNodeQ's bytes: max_leaf_size <= 16); throws an Error naming the bad value or the
// leaf size that does not fit.
bool resolve_quantised(const BvhOptions& options, std::size_t triangles);

// The i-th wide node of an 8-wide (FcBvhNode8) or 4-wide (FcBvhNode) tree. A quantised
// node comes decoded (bvh_detail::dequantise_node: the boxes the traversal tests), with
// each leaf's triangle count read from its blocks.
FcBvhNode8 wide_node8(const Bvh& bvh, std::size_t i);
// The i-th node of a quantised tree, as stored.
FcBvhNodeQ wide_node_q(const Bvh& bvh, std::size_t i);
const FcBvhNode& wide_node4(const Bvh& bvh, std::size_t i);

// The line a program that traces `bvh` is assembled after ("#define FC_BVH_WIDTH 8"
// or 4, and "#define FC_BVH_QUANTISED 1" on a second line for FcBvhNodeQ), so that
// kernels/trace/bvh_traverse.cl reads its node layout.
std::string bvh_prelude(const Bvh& bvh);

// The leaf block at 16-byte row `row` of the node buffer (a leaf's FcBvhNode::index,
// plus 10 rows per further block); throws an Error naming the row when it is outside.
FcTriBlock leaf_block(const Bvh& bvh, std::int64_t row);

// Builds the tree over `vertices`, three consecutive entries per triangle
// (vertices.size() must be a multiple of 3). Degenerate (zero-area) and non-finite
// triangles are kept out of the tree (they can never be hit) and counted in
// `skipped` when it is not null. An empty input gives a tree whose root has two
// empty leaves, which every ray misses.
Bvh build_bvh(const std::vector<glm::vec3>& vertices, const BvhOptions& options = {}, std::size_t* skipped = nullptr);

}  // namespace facet
