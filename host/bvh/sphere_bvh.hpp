// The analytic spheres of a scene as the kernels read them (kernels/shared/sphere_layout.h):
// a binary BVH (host/bvh/binary_tree.hpp) over the spheres' boxes, and the spheres in
// the order its leaves reference them.
#pragma once

#include <vector>

#include "kernels/shared/binary_node_layout.h"
#include "kernels/shared/sphere_layout.h"

namespace facet {

struct SphereBvh {
    std::vector<FcBinaryNode> nodes;  // nodes[0] is the root
    std::vector<FcSphere> spheres;    // in leaf order; FcSphere::prim is the input index
};

// Builds the tree over `spheres` (FcSphere::prim set here to each sphere's input index).
// Spheres without a positive finite radius or with a non-finite centre are left out (they
// can never be hit). No spheres give a root with two empty children.
SphereBvh build_sphere_bvh(const std::vector<FcSphere>& spheres);

}  // namespace facet
