// build_instance_bvh: the meshes' BLASes, placed after the world's buffers, the instances'
// matrices and world boxes, and the top-level binary SAH tree over those boxes.
#include "host/bvh/instance_bvh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "host/bvh/small_tree.hpp"
#include "host/error.hpp"

namespace facet {
namespace {

// Rows of the 3x4 affine part of a column-major 4x4 matrix.
void store_rows(float (&out)[3][4], const glm::dmat4& m) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out[r][c] = float(m[c][r]);
}

// The instance's world box: the mesh's object box, its corners transformed in double, then
// widened by a few ulps of its largest coordinate and rounded outward, so that the kernel's
// float transform of the ray never puts a hit outside it.
void world_box(std::span<const glm::vec3> v, const glm::dmat4& m, FcInstance& out) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : v) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    glm::dvec3 wlo(std::numeric_limits<double>::max()), whi(-std::numeric_limits<double>::max());
    for (int k = 0; k < 8; ++k) {
        const glm::dvec4 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z, 1.0);
        const glm::dvec3 p(m * c);
        wlo = glm::min(wlo, p);
        whi = glm::max(whi, p);
    }
    for (int a = 0; a < 3; ++a) {
        const double pad = 1e-5 * std::max({std::fabs(wlo[a]), std::fabs(whi[a]), whi[a] - wlo[a]});
        out.lo[a] = std::nextafter(float(wlo[a] - pad), -INFINITY);
        out.hi[a] = std::nextafter(float(whi[a] + pad), INFINITY);
    }
}

}  // namespace

InstanceBvh build_instance_bvh(const Bvh& world, std::span<const InstancedMesh> meshes,
                               std::span<const InstancePlacement> instances) {
    const auto start = std::chrono::steady_clock::now();
    InstanceBvh out;

    // Each mesh's BLAS, appended: its root and first triangle.
    BvhOptions options;
    options.width = world.stats.width;
    options.quantised = world.stats.quantised;  // one node layout per program (FC_BVH_QUANTISED)
    std::vector<std::int32_t> roots, tri_offsets;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const InstancedMesh& mesh = meshes[i];
        Bvh blas = build_bvh(std::vector<glm::vec3>(mesh.vertices.begin(), mesh.vertices.end()), options);
        const std::size_t root = world.nodes.size() + out.nodes.size();
        const std::size_t first = world.triangles.size() + out.triangles.size();
        if (root > std::size_t(INT32_MAX) || first > std::size_t(INT32_MAX))
            throw Error("build_instance_bvh: the node buffer outgrows 32-bit indices at shared mesh " +
                        std::to_string(i));
        roots.push_back(std::int32_t(root));
        tri_offsets.push_back(std::int32_t(first));
        for (FcTriangle& t : blas.triangles) t.prim += mesh.prim_offset;
        out.blas_bytes += blas.nodes.size() * sizeof(FcBvhNode) + blas.triangles.size() * sizeof(FcTriangle);
        out.nodes.insert(out.nodes.end(), blas.nodes.begin(), blas.nodes.end());
        out.triangles.insert(out.triangles.end(), blas.triangles.begin(), blas.triangles.end());
    }

    // The instances' matrices and boxes, and the top level over the boxes.
    std::vector<FcInstance> placed;
    std::vector<bvh_detail::PrimRef> refs;
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const InstancePlacement& p = instances[i];
        if (p.mesh < 0 || std::size_t(p.mesh) >= meshes.size())
            throw Error("build_instance_bvh: instance " + std::to_string(i) + " places mesh " + std::to_string(p.mesh) +
                        " of " + std::to_string(meshes.size()));
        const std::span<const glm::vec3> v = meshes[std::size_t(p.mesh)].vertices;
        if (v.empty()) continue;
        const glm::dmat4 m(p.object_to_world);
        FcInstance in{};
        store_rows(in.object_to_world, m);
        store_rows(in.world_to_object, glm::inverse(m));
        in.root = roots[std::size_t(p.mesh)];
        in.tri_offset = tri_offsets[std::size_t(p.mesh)];
        world_box(v, m, in);
        bvh_detail::PrimRef& r = refs.emplace_back();
        for (int a = 0; a < 3; ++a) r.lo[a] = in.lo[a], r.hi[a] = in.hi[a];
        r.id = std::uint32_t(placed.size());
        r.pad = 0.0f;
        placed.push_back(in);
        out.order.push_back(std::int32_t(i));
    }
    out.tree = build_small_tree(refs, SmallTreeCosts{2, 1.0f}, world.stats.width);
    std::vector<std::int32_t> order;
    order.reserve(refs.size());
    out.instances.reserve(refs.size());
    for (const bvh_detail::PrimRef& r : refs) {
        out.instances.push_back(placed[r.id]);
        order.push_back(out.order[r.id]);
    }
    out.order = std::move(order);
    out.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace facet
