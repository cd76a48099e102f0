// Helpers of the BVH tests (tests/bvh_test.cpp: structure, traversal against brute force;
// tests/bvh_wide_test.cpp: the 8-wide and quantised layouts against the others): the tree
// walk that checks a built tree, every node layout, rays, and the device runs of the trace
// kernels.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>

#include "host/bvh/bvh.hpp"
#include "host/bvh/bvh_width.hpp"
#include "tests/bvh_meshes.hpp"
#include "tests/cl_test_env.hpp"
#include "host/error.hpp"

namespace facet::bvh_test {

using test::IndexedMesh;

// ---- host-side structure ------------------------------------------------------------

struct Walk {
    std::vector<int> seen;                 // leaf visits per triangle
    std::vector<std::array<float, 6>> up;  // the boxes of the inner children on the path (lo, hi)
    int max_depth = 0;
    std::size_t leaves = 0;
    int pushes = 0;      // stack entries pushed on the path to the node being walked
    int stack_need = 0;  // most over every path
};

inline bool encloses(const float* lo, const float* hi, const float* p) {
    for (int a = 0; a < 3; ++a)
        if (!(lo[a] <= p[a] && p[a] <= hi[a])) return false;
    return true;
}

// Every node layout, for every test that builds a tree.
struct Layout {
    int width;
    int quantised;
    const char* name;
};
constexpr Layout kLayouts[] = {{4, 0, "4-wide"}, {8, 0, "8-wide"}, {8, 1, "8-wide quantised"}};
constexpr Layout kFloat8 = kLayouts[1], kQuantised8 = kLayouts[2];

inline BvhOptions with_layout(BvhOptions o, const Layout& layout) {
    o.width = layout.width;
    o.quantised = layout.quantised;
    return o;
}

// A wide node of either width, as plain arrays.
struct NodeView {
    int width = 4;
    float lo[3][8], hi[3][8];
    int index[8], count[8];
};

template <typename Node>
inline NodeView view_of(const Node& n, int width) {
    NodeView v;
    v.width = width;
    for (int k = 0; k < width; ++k) {
        v.lo[0][k] = n.lo_x[k], v.lo[1][k] = n.lo_y[k], v.lo[2][k] = n.lo_z[k];
        v.hi[0][k] = n.hi_x[k], v.hi[1][k] = n.hi_y[k], v.hi[2][k] = n.hi_z[k];
        v.index[k] = n.index[k], v.count[k] = n.count[k];
    }
    return v;
}

inline NodeView node_view(const Bvh& bvh, std::size_t i) {
    return bvh.stats.width == 8 ? view_of(wide_node8(bvh, i), 8) : view_of(wide_node4(bvh, i), 4);
}

inline void walk_child(const Bvh& bvh, const float* lo, const float* hi, int index, int count, int depth, Walk& w);

// Pushes at most (width - 1) entries a node; the 4-wide tree's depth bounds its stack,
// the 8-wide tree's stack_need (checked against the walk below).
inline int stack_size(const Bvh& bvh) { return bvh.stats.width == 8 ? FC_BVH8_STACK_SIZE : FC_BVH_STACK_SIZE; }

inline void walk_node(const Bvh& bvh, int node, int depth, int pushes, Walk& w) {
    ASSERT_GE(node, 0);
    ASSERT_LT(static_cast<std::size_t>(node), bvh.stats.nodes);
    if (bvh.stats.width == 4) {
        ASSERT_LE(3 * (depth + 1), FC_BVH_STACK_SIZE) << "deeper than the traversal stack allows";
    }
    const NodeView n = node_view(bvh, static_cast<std::size_t>(node));
    int inner = 0;
    for (int k = 0; k < n.width; ++k) inner += n.count[k] == 0 && n.lo[0][k] <= n.hi[0][k];
    pushes += std::max(0, inner - 1);
    w.stack_need = std::max(w.stack_need, pushes);
    ASSERT_LE(pushes, stack_size(bvh)) << "more stack entries than the traversal has";
    for (int k = 0; k < n.width; ++k) {
        const float lo[3] = {n.lo[0][k], n.lo[1][k], n.lo[2][k]}, hi[3] = {n.hi[0][k], n.hi[1][k], n.hi[2][k]};
        w.pushes = pushes;
        walk_child(bvh, lo, hi, n.index[k], n.count[k], depth + 1, w);
    }
}

// Whether box [lo, hi] encloses all child boxes of node `c` that are not empty.
inline bool encloses_children(const float* lo, const float* hi, const NodeView& c) {
    for (int k = 0; k < c.width; ++k) {
        if (!(c.lo[0][k] <= c.hi[0][k])) continue;
        const float clo[3] = {c.lo[0][k], c.lo[1][k], c.lo[2][k]}, chi[3] = {c.hi[0][k], c.hi[1][k], c.hi[2][k]};
        if (!encloses(lo, hi, clo) || !encloses(lo, hi, chi)) return false;
    }
    return true;
}

inline void walk_child(const Bvh& bvh, const float* lo, const float* hi, int index, int count, int depth, Walk& w) {
    if (lo[0] > hi[0]) {  // empty slot
        EXPECT_EQ(count, 0);
        EXPECT_EQ(index, 0);
        EXPECT_TRUE(std::isinf(lo[0]) && std::isinf(hi[0]));
        return;
    }
    if (count == 0) {
        ASSERT_GT(index, 0) << "an inner child never refers back to the root";
        ASSERT_LT(static_cast<std::size_t>(index), bvh.stats.nodes);
        // Float boxes nest; quantised ones, each rounded outward on its own node's grid, need
        // not, but must hold every triangle below them (checked at the leaves).
        if (!bvh.stats.quantised) {
            EXPECT_TRUE(encloses_children(lo, hi, node_view(bvh, static_cast<std::size_t>(index))));
        }
        w.up.push_back({lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]});
        walk_node(bvh, index, depth, w.pushes, w);
        w.up.pop_back();
        return;
    }
    ++w.leaves;
    w.max_depth = std::max(w.max_depth, depth);
    // The leaf's blocks: consecutive triangles of the FcTriangle array, four lanes a
    // block, the unused lanes of the last block at 0 with index -1.
    const FcTriBlock first = leaf_block(bvh, index);
    ASSERT_GE(first.tri[0], 0);
    ASSERT_LE(static_cast<std::size_t>(first.tri[0]) + static_cast<std::size_t>(count), bvh.triangles.size());
    for (int b = 0; 4 * b < count; ++b) {
        const FcTriBlock blk = leaf_block(bvh, index + 10 * static_cast<std::int64_t>(b));
        for (int lane = 0; lane < 4; ++lane) {
            const int i = 4 * b + lane;
            const float p0[3] = {blk.x0[lane], blk.y0[lane], blk.z0[lane]};
            const float p1[3] = {blk.x1[lane], blk.y1[lane], blk.z1[lane]};
            const float p2[3] = {blk.x2[lane], blk.y2[lane], blk.z2[lane]};
            if (i >= count) {
                EXPECT_EQ(blk.tri[lane], -1);
                for (int a = 0; a < 3; ++a) EXPECT_TRUE(p0[a] == 0.0f && p1[a] == 0.0f && p2[a] == 0.0f);
                continue;
            }
            ASSERT_EQ(blk.tri[lane], first.tri[0] + i);
            const FcTriangle& t = bvh.triangles[static_cast<std::size_t>(blk.tri[lane])];
            ++w.seen[static_cast<std::size_t>(blk.tri[lane])];
            EXPECT_EQ(std::memcmp(p0, t.v0, sizeof p0), 0);
            EXPECT_EQ(std::memcmp(p1, t.v1, sizeof p1), 0);
            EXPECT_EQ(std::memcmp(p2, t.v2, sizeof p2), 0);
            EXPECT_TRUE(encloses(lo, hi, t.v0) && encloses(lo, hi, t.v1) && encloses(lo, hi, t.v2));
            for (const auto& b : w.up)
                ASSERT_TRUE(encloses(&b[0], &b[3], t.v0) && encloses(&b[0], &b[3], t.v1) &&
                            encloses(&b[0], &b[3], t.v2))
                    << "triangle " << blk.tri[lane] << " outside an ancestor's box";
        }
    }
}

// Every kept triangle in exactly one leaf, boxes enclosing their contents, stats true.
inline void check_structure(const Bvh& bvh, const std::vector<glm::vec3>& input, std::size_t skipped) {
    ASSERT_GE(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.triangles.size() + skipped, input.size() / 3);
    Walk w;
    w.seen.assign(bvh.triangles.size(), 0);
    walk_node(bvh, 0, 0, 0, w);
    for (std::size_t i = 0; i < w.seen.size(); ++i) ASSERT_EQ(w.seen[i], 1) << "triangle " << i;
    std::vector<char> prim_seen(input.size() / 3, 0);
    for (const FcTriangle& t : bvh.triangles) {
        ASSERT_GE(t.prim, 0);
        ASSERT_EQ(prim_seen[static_cast<std::size_t>(t.prim)]++, 0);
        const glm::vec3& v0 = input[3 * static_cast<std::size_t>(t.prim)];
        EXPECT_TRUE(v0.x == t.v0[0] && v0.y == t.v0[1] && v0.z == t.v0[2]);
    }
    EXPECT_EQ(w.max_depth, bvh.stats.max_depth);
    EXPECT_EQ(w.stack_need, bvh.stats.stack_need);
    if (bvh.stats.width == 4) {
        EXPECT_LE(3 * bvh.stats.max_depth, FC_BVH_STACK_SIZE);
    }
    EXPECT_LE(bvh.stats.stack_need, stack_size(bvh));
    EXPECT_EQ(w.leaves, bvh.stats.leaves);
    const std::size_t node_bytes = bvh.stats.quantised ? 80 : 32 * static_cast<std::size_t>(bvh.stats.width);
    EXPECT_EQ(bvh.nodes.size(), (bvh.stats.nodes * node_bytes + bvh.stats.leaf_blocks * 160 + 127) / 128);
    EXPECT_EQ(bvh.stats.triangles, bvh.triangles.size());
    EXPECT_EQ(bvh.stats.device_bytes, bvh.nodes.size() * 128 + bvh.triangles.size() * 48);
}

// ---- device: BVH against brute force -------------------------------------------------

struct Rays {
    std::vector<glm::vec4> o;  // xyz
    std::vector<glm::vec4> d;  // xyz, w = tmax
    void add(glm::vec3 origin, glm::vec3 dir, float tmax = INFINITY) {
        o.emplace_back(origin, 0.0f);
        d.emplace_back(dir, tmax);
    }
};

struct Result {
    std::vector<glm::vec4> hit;  // t, u, v, as_float(prim)
    std::vector<int> any;
    int prim(std::size_t i) const {
        int p;
        std::memcpy(&p, &hit[i].w, sizeof p);
        return p;
    }
};

template <typename T>
inline cl::Buffer upload(const std::vector<T>& v) {
    auto& ctx = test::context();
    std::size_t bytes = std::max<std::size_t>(v.size() * sizeof(T), 64);  // never 0 bytes
    cl::Buffer b(ctx.context(), CL_MEM_READ_ONLY, bytes);
    if (!v.empty()) ctx.queue().enqueueWriteBuffer(b, CL_TRUE, 0, v.size() * sizeof(T), v.data());
    return b;
}

// The next rays' origins from surface points leaving along their normals, by the
// kernels' own offset (kernels/test/trace_kernels.cl, offset_origins).
inline std::vector<glm::vec4> offset_origins(const std::vector<glm::vec4>& points,
                                             const std::vector<glm::vec4>& normals) {
    auto& ctx = test::context();
    cl::Kernel k(test::program("kernels/test/trace_kernels.cl"), "offset_origins");
    cl::Buffer pb = upload(points), nb = upload(normals);
    cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, points.size() * sizeof(glm::vec4));
    k.setArg(0, pb), k.setArg(1, nb), k.setArg(2, ob);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(points.size()));
    std::vector<glm::vec4> origins(points.size());
    ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, origins.size() * sizeof(glm::vec4), origins.data());
    return origins;
}

// The test kernels built for the tree's node width.
inline const char* trace_program(const Bvh& bvh) {
    if (bvh.stats.quantised) return "kernels/test/trace_kernels8q.cl";
    return bvh.stats.width == 8 ? "kernels/test/trace_kernels8.cl" : "kernels/test/trace_kernels.cl";
}

inline Result run(const char* kernel_name, const Bvh& bvh, const Rays& rays) {
    auto& ctx = test::context();
    cl::Kernel k(test::program(trace_program(bvh)), kernel_name);
    const std::size_t n = rays.o.size();
    cl::Buffer nodes = upload(bvh.nodes), tris = upload(bvh.triangles);
    cl::Buffer o = upload(rays.o), d = upload(rays.d);
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(glm::vec4));
    cl::Buffer any(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
    int arg = 0;
    if (std::string(kernel_name) == "trace_rays_brute") {
        k.setArg(arg++, tris);
        k.setArg(arg++, static_cast<cl_int>(bvh.triangles.size()));
    } else {
        k.setArg(arg++, nodes);
        k.setArg(arg++, tris);
    }
    k.setArg(arg++, o);
    k.setArg(arg++, d);
    k.setArg(arg++, out);
    k.setArg(arg++, any);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    Result r;
    r.hit.resize(n);
    r.any.resize(n);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(glm::vec4), r.hit.data());
    ctx.queue().enqueueReadBuffer(any, CL_TRUE, 0, n * sizeof(int), r.any.data());
    return r;
}

// Distance along the ray to the plane of scene triangle `prim`, in double precision.
inline double plane_t(const std::vector<glm::vec3>& soup, int prim, glm::vec3 o, glm::vec3 d) {
    glm::dvec3 a(soup[3 * static_cast<std::size_t>(prim)]), b(soup[3 * static_cast<std::size_t>(prim) + 1]),
        c(soup[3 * static_cast<std::size_t>(prim) + 2]);
    glm::dvec3 n = glm::cross(b - a, c - a);
    return glm::dot(n, a - glm::dvec3(o)) / glm::dot(n, glm::dvec3(d));
}

// BVH and brute force agree on hit/miss, any-hit, and the nearest distance; the
// triangle may differ only where the two triangles' exact distances tie (duplicates,
// coplanar overlaps). Returns the BVH's result.
inline Result expect_agreement(const Bvh& bvh, const std::vector<glm::vec3>& soup, const Rays& rays) {
    Result b = run("trace_rays_bvh", bvh, rays), f = run("trace_rays_brute", bvh, rays);
    int failures = 0;
    for (std::size_t i = 0; i < rays.o.size() && failures < 10; ++i) {
        bool bh = b.prim(i) >= 0, fh = f.prim(i) >= 0;
        float tb = b.hit[i].x, tf = f.hit[i].x;
        bool ok = bh == fh && b.any[i] == (fh ? 1 : 0) && f.any[i] == b.any[i];
        if (ok && fh && b.prim(i) == f.prim(i))
            ok = std::fabs(tb - tf) <= 1e-5f * tf && std::fabs(b.hit[i].y - f.hit[i].y) <= 1e-5f &&
                 std::fabs(b.hit[i].z - f.hit[i].z) <= 1e-5f;
        if (ok && fh && b.prim(i) != f.prim(i)) {  // a tie, in exact arithmetic
            glm::vec3 o(rays.o[i]), d(rays.d[i]);
            double pb = plane_t(soup, b.prim(i), o, d), pf = plane_t(soup, f.prim(i), o, d);
            ok = std::fabs(pb - pf) <= 1e-5 * std::fabs(pf) && std::fabs(tb - tf) <= 1e-3f * tf;
        }
        if (!ok) {
            ++failures;
            ADD_FAILURE() << "ray " << i << ": bvh prim " << b.prim(i) << " t " << tb << " any " << b.any[i]
                          << ", brute prim " << f.prim(i) << " t " << tf << " any " << f.any[i];
        }
    }
    return b;
}

// Random rays through the scene's bounds: random origins and directions, and rays
// aimed at points on random triangles; some with a finite tmax.
inline Rays random_rays(const std::vector<glm::vec3>& soup, std::size_t count, float extent, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), u01(0.0f, 1.0f);
    Rays rays;
    const std::size_t tris = soup.size() / 3;
    for (std::size_t i = 0; i < count; ++i) {
        glm::vec3 o(u(rng) * extent, u(rng) * extent, u(rng) * extent);
        glm::vec3 d(u(rng), u(rng), u(rng));
        if (i % 2 == 0 && tris > 0) {  // aim at a triangle
            std::size_t t = std::uniform_int_distribution<std::size_t>(0, tris - 1)(rng);
            float a = u01(rng), b = u01(rng) * (1.0f - a);
            glm::vec3 p = soup[3 * t] + a * (soup[3 * t + 1] - soup[3 * t]) + b * (soup[3 * t + 2] - soup[3 * t]);
            if (std::isfinite(p.x + p.y + p.z)) d = p - o;
        }
        if (i % 16 == 3) d = glm::vec3(0.0f, 0.0f, u(rng) < 0.0f ? -1.0f : 1.0f);  // zero components
        float tmax = (i % 5 == 0) ? u01(rng) * 2.0f : INFINITY;
        rays.add(o, d, tmax);
    }
    return rays;
}

// Nine small triangles in a 3 x 3 grid, each a little higher than the last: scenes of their
// first 1, 7, 8 or 9 fill an 8-wide root with leaves or need a second node.
inline std::vector<glm::vec3> nine_triangles() {
    std::vector<glm::vec3> all;
    for (int i = 0; i < 9; ++i) {
        const glm::vec3 at(static_cast<float>(i % 3) * 1.5f, static_cast<float>(i / 3) * 1.5f,
                           0.2f * static_cast<float>(i));
        all.insert(all.end(), {at, at + glm::vec3(1.0f, 0.0f, 0.1f), at + glm::vec3(0.0f, 1.0f, -0.1f)});
    }
    return all;
}

// ---- layouts against each other -------------------------------------------------------

// Two layouts' traversals over trees collapsed from the same binary tree (the same
// leaves, the same blocks) return the same nearest hit: the same triangle at the same t
// with the same barycentrics, bit for bit, and the same any-hit answer. With `ties`
// (soups of overlapping coplanar slivers, whose computed distances differ by more than
// the box tests' rounding, so the order of the visits decides), a different triangle
// is allowed where the two planes' exact distances tie, as in expect_agreement.
// Returns the number of rays that hit.
inline std::size_t expect_same_hits(const std::vector<glm::vec3>& soup, const BvhOptions& options, const Rays& rays,
                                    bool ties = false, const Layout& a = kLayouts[0], const Layout& b = kFloat8) {
    const Bvh ba = build_bvh(soup, with_layout(options, a)), bb = build_bvh(soup, with_layout(options, b));
    EXPECT_EQ(ba.stats.leaves, bb.stats.leaves);
    EXPECT_EQ(ba.stats.leaf_blocks, bb.stats.leaf_blocks);
    const Result ra = run("trace_rays_bvh", ba, rays), rb = run("trace_rays_bvh", bb, rays);
    int failures = 0;
    std::size_t hits = 0;
    for (std::size_t i = 0; i < rays.o.size() && failures < 10; ++i) {
        hits += ra.prim(i) >= 0;
        if (std::memcmp(&ra.hit[i], &rb.hit[i], sizeof ra.hit[i]) == 0 && ra.any[i] == rb.any[i]) continue;
        if (ties && ra.any[i] == rb.any[i] && ra.prim(i) >= 0 && rb.prim(i) >= 0) {
            const glm::vec3 o(rays.o[i]), d(rays.d[i]);
            const double pa = plane_t(soup, ra.prim(i), o, d), pb = plane_t(soup, rb.prim(i), o, d);
            if (std::fabs(pa - pb) <= 1e-5 * std::fabs(pa)) continue;
        }
        ++failures;
        ADD_FAILURE() << "ray " << i << ": " << a.name << " prim " << ra.prim(i) << " t " << ra.hit[i].x << " any "
                      << ra.any[i] << ", " << b.name << " prim " << rb.prim(i) << " t " << rb.hit[i].x << " any "
                      << rb.any[i];
    }
    return hits;
}

}  // namespace facet::bvh_test
