#include "host/scene/sphere_bvh.hpp"

#include <cmath>
#include <cstdint>

#include "host/bvh/sah_builder.hpp"

namespace facet {
namespace {

static_assert(bvh_detail::kMaxLeafDepth + 1 <= FC_SPHERE_STACK_SIZE,
              "the sphere traversal pushes one child per level of the binary tree");

bool usable(const FcSphere& s) {
    return std::isfinite(s.center[0]) && std::isfinite(s.center[1]) && std::isfinite(s.center[2]) &&
           std::isfinite(s.radius) && s.radius > 0.0f;
}

// The box around a sphere, rounded outward so that rounding in the kernel's slab test and
// intersection never puts a hit outside it.
bvh_detail::PrimRef sphere_ref(const FcSphere& s, std::uint32_t id) {
    bvh_detail::PrimRef r{};
    for (int a = 0; a < 3; ++a) {
        const double c = double(s.center[a]), rad = double(s.radius) * (1.0 + 1e-5);
        r.lo[a] = std::nextafter(float(c - rad), -INFINITY);
        r.hi[a] = std::nextafter(float(c + rad), INFINITY);
    }
    r.id = id;
    return r;
}

FcSphereNode device_node(const bvh_detail::BinaryNode& b) {
    FcSphereNode n{};
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
    return n;
}

}  // namespace

SphereBvh build_sphere_bvh(const std::vector<FcSphere>& spheres) {
    std::vector<bvh_detail::PrimRef> refs;
    refs.reserve(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i)
        if (usable(spheres[i])) refs.push_back(sphere_ref(spheres[i], std::uint32_t(i)));
    BvhOptions options;
    options.max_leaf_size = 4;
    options.block_size = 1;  // spheres are tested one at a time
    const bvh_detail::BuildOutput built = bvh_detail::build_sah(refs, options);
    SphereBvh out;
    out.nodes.reserve(built.nodes.size());
    for (const bvh_detail::BinaryNode& b : built.nodes) out.nodes.push_back(device_node(b));
    out.spheres.reserve(refs.size());
    for (const bvh_detail::PrimRef& r : refs) {
        FcSphere s = spheres[r.id];
        s.prim = fc_int(r.id);
        out.spheres.push_back(s);
    }
    return out;
}

}  // namespace facet
