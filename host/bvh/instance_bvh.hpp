// The two-level tree of instancing (kernels/shared/instance_layout.h): one bottom-level
// tree (BLAS) per shared mesh, built by build_bvh over its object-space triangles, to be
// appended to the world tree's node buffer and triangle array (so kernels/trace's
// traversal serves it from its root), and a top-level small tree over the instances'
// world boxes (host/bvh/small_tree.hpp, as the spheres' tree is), as wide as the world tree.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "host/bvh/bvh.hpp"
#include "kernels/shared/instance_layout.h"

namespace facet {

// A mesh stored once: object-space vertices (3 per triangle) and the index of its first
// triangle in the device's shading arrays (FcTriangle::prim of its triangles counts from it).
struct InstancedMesh {
    std::span<const glm::vec3> vertices;
    std::int32_t prim_offset = 0;
};

// One use of a mesh: its index in the mesh list and an invertible affine transform.
struct InstancePlacement {
    int mesh = 0;
    glm::mat4 object_to_world{1.0f};
};

struct InstanceBvh {
    std::vector<FcBvhNode> nodes;       // each mesh's BLAS, to follow the world tree's buffer
    std::vector<FcTriangle> triangles;  // each mesh's, to follow the world tree's
    std::vector<FcInstance> instances;  // in the top-level tree's leaf order
    std::vector<FcBvhNode> tree;        // the top level, float wide nodes as FcBvhNode units, the root first
    std::vector<std::int32_t> order;    // order[k]: the placement FcInstance k came from
    std::size_t blas_bytes = 0;         // the meshes' nodes, leaf blocks and triangles
    double build_seconds = 0.0;         // BLASes, top level and the copies
};

// Builds the BLASes (with the world tree's node width), to be appended after `world`'s
// node buffer and triangles, and the top level. Instances whose mesh has no vertices are
// left out (they can never be hit). No instances give a top level whose root has two empty
// children, which every ray misses.
InstanceBvh build_instance_bvh(const Bvh& world, std::span<const InstancedMesh> meshes,
                               std::span<const InstancePlacement> instances);

}  // namespace facet
