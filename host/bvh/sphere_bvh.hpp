// The analytic spheres of a scene as the kernels read them (kernels/shared/sphere_layout.h):
// a small tree (host/bvh/small_tree.hpp) over the spheres' boxes, and the spheres in the
// order its leaves reference them.
#pragma once

#include <vector>

#include "kernels/shared/bvh_layout.h"
#include "kernels/shared/sphere_layout.h"

namespace facet {

struct SphereBvh {
    std::vector<FcBvhNode> nodes;   // float wide nodes as FcBvhNode units, the root first
    std::vector<FcSphere> spheres;  // in leaf order; FcSphere::prim is the input index
};

// Builds the tree over `spheres` (FcSphere::prim set here to each sphere's input index).
// Spheres without a positive finite radius or with a non-finite centre are left out (they
// can never be hit). Its nodes are `width` wide (4 or 8: the triangles' tree's width, which
// every program that reads it is built for). No spheres give a root with every slot empty.
SphereBvh build_sphere_bvh(const std::vector<FcSphere>& spheres, int width);

}  // namespace facet
