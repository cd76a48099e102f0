// Quantised 8-wide nodes (FcBvhNodeQ in kernels/shared/bvh_layout.h; Ylitie, Karras & Laine
// 2017, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs"): a node of
// the collapsed 8-wide tree, its leaves already pointing at their blocks, in 80 bytes, every
// child box rounded outward onto a grid of the node.
#pragma once

#include "kernels/shared/bvh_layout.h"

namespace facet::bvh_detail {

// A decoded plane: origin + q * 2^(biased_exp - 127), rounded once, as the kernels decode it
// (q * scale is exact, so a fused multiply-add gives the same float).
float quantised_plane(float origin, unsigned biased_exp, unsigned q);

// Encodes `node`, whose inner children are consecutive nodes in slot order and whose leaves'
// blocks are consecutive rows in slot order (as build_bvh lays them out). Every decoded box
// contains the slot's box. Throws an Error naming the slot when a leaf has more than 7 blocks
// or starts more than 31 blocks after the node's first leaf block.
FcBvhNodeQ quantise_node(const FcBvhNode8& node);

// The slots of `node` as the traversal sees them, in the float layout: the decoded boxes
// (empty slots with the inverted infinite box, index 0, count 0), inner children's node
// indices, leaves' first rows and, as count, four triangles a block (the last block's unused
// lanes included).
FcBvhNode8 dequantise_node(const FcBvhNodeQ& node);

}  // namespace facet::bvh_detail
