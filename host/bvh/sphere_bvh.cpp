#include "host/bvh/sphere_bvh.hpp"

#include <cmath>
#include <cstdint>

#include "host/bvh/small_tree.hpp"

namespace facet {
namespace {

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

}  // namespace

SphereBvh build_sphere_bvh(const std::vector<FcSphere>& spheres, int width) {
    std::vector<bvh_detail::PrimRef> refs;
    refs.reserve(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i)
        if (usable(spheres[i])) refs.push_back(sphere_ref(spheres[i], std::uint32_t(i)));
    SphereBvh out;
    out.nodes = build_small_tree(refs, SmallTreeCosts{4, 1.0f}, width);
    out.spheres.reserve(refs.size());
    for (const bvh_detail::PrimRef& r : refs) {
        FcSphere s = spheres[r.id];
        s.prim = fc_int(r.id);
        out.spheres.push_back(s);
    }
    return out;
}

}  // namespace facet
