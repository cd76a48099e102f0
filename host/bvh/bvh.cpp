// build_bvh: filters the triangle soup, runs the binned SAH builder
// (bvh/sah_builder.cpp) and lays the triangles out in leaf order.
#include "bvh/bvh.hpp"

#include <chrono>
#include <cmath>

#include "bvh/sah_builder.hpp"
#include "error.hpp"

namespace facet {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A triangle that can be hit: finite vertices and a non-zero cross product of its
// edges (exactly zero covers repeated vertices and exactly collinear ones).
bool usable(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return false;
    glm::vec3 e1 = b - a, e2 = c - a;
    float nx = e1.y * e2.z - e1.z * e2.y;
    float ny = e1.z * e2.x - e1.x * e2.z;
    float nz = e1.x * e2.y - e1.y * e2.x;
    return nx != 0.0f || ny != 0.0f || nz != 0.0f;
}

}  // namespace

Bvh build_bvh(const std::vector<glm::vec3>& vertices, const BvhOptions& options, std::size_t* skipped) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    if (vertices.size() % 3 != 0)
        throw Error("build_bvh: the vertex count " + std::to_string(vertices.size()) +
                    " is not a multiple of 3");
    const std::size_t count = vertices.size() / 3;
    if (count > static_cast<std::size_t>(INT32_MAX))
        throw Error("build_bvh: too many triangles (" + std::to_string(count) + ")");

    // Per-triangle bounds for the builder.
    std::vector<bvh_detail::PrimRef> refs;
    refs.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3& a = vertices[3 * i];
        const glm::vec3& b = vertices[3 * i + 1];
        const glm::vec3& c = vertices[3 * i + 2];
        if (!usable(a, b, c)) continue;
        bvh_detail::PrimRef r;
        for (int k = 0; k < 3; ++k) {
            r.lo[k] = std::fmin(a[k], std::fmin(b[k], c[k]));
            r.hi[k] = std::fmax(a[k], std::fmax(b[k], c[k]));
        }
        r.id = static_cast<std::uint32_t>(i);
        r.pad = 0.0f;
        refs.push_back(r);
    }
    if (skipped) *skipped = count - refs.size();

    bvh_detail::BuildOutput built = bvh_detail::build_sah(refs, options);

    Bvh bvh;
    bvh.nodes = std::move(built.nodes);
    bvh.triangles.resize(refs.size());
    for (std::size_t k = 0; k < refs.size(); ++k) {
        const std::uint32_t i = refs[k].id;
        FcTriangle& t = bvh.triangles[k];
        for (int j = 0; j < 3; ++j) {
            t.v0[j] = vertices[3 * i][j];
            t.v1[j] = vertices[3 * i + 1][j];
            t.v2[j] = vertices[3 * i + 2][j];
        }
        t.prim = static_cast<fc_int>(i);
        t.pad0 = t.pad1 = 0;
    }

    BvhStats& st = bvh.stats;
    st.triangles = bvh.triangles.size();
    st.nodes = bvh.nodes.size();
    st.leaves = built.leaves;
    st.max_depth = built.max_depth;
    st.max_leaf_size = built.max_leaf_size;
    st.sah_cost = built.sah_cost;
    st.device_bytes = bvh.nodes.size() * sizeof(FcBvhNode) + bvh.triangles.size() * sizeof(FcTriangle);
    st.build_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return bvh;
}

}  // namespace facet
