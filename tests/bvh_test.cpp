// The BVH builder (host/bvh/) and its traversal (kernels/trace/): the tree's structure
// on the host, and on the device the BVH against a brute-force loop over every
// triangle with the same watertight triangle test.
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

namespace facet {
namespace {

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

bool encloses(const float* lo, const float* hi, const float* p) {
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

BvhOptions with_layout(BvhOptions o, const Layout& layout) {
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
NodeView view_of(const Node& n, int width) {
    NodeView v;
    v.width = width;
    for (int k = 0; k < width; ++k) {
        v.lo[0][k] = n.lo_x[k], v.lo[1][k] = n.lo_y[k], v.lo[2][k] = n.lo_z[k];
        v.hi[0][k] = n.hi_x[k], v.hi[1][k] = n.hi_y[k], v.hi[2][k] = n.hi_z[k];
        v.index[k] = n.index[k], v.count[k] = n.count[k];
    }
    return v;
}

NodeView node_view(const Bvh& bvh, std::size_t i) {
    return bvh.stats.width == 8 ? view_of(wide_node8(bvh, i), 8) : view_of(wide_node4(bvh, i), 4);
}

void walk_child(const Bvh& bvh, const float* lo, const float* hi, int index, int count, int depth, Walk& w);

// Pushes at most (width - 1) entries a node; the 4-wide tree's depth bounds its stack,
// the 8-wide tree's stack_need (checked against the walk below).
int stack_size(const Bvh& bvh) { return bvh.stats.width == 8 ? FC_BVH8_STACK_SIZE : FC_BVH_STACK_SIZE; }

void walk_node(const Bvh& bvh, int node, int depth, int pushes, Walk& w) {
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
bool encloses_children(const float* lo, const float* hi, const NodeView& c) {
    for (int k = 0; k < c.width; ++k) {
        if (!(c.lo[0][k] <= c.hi[0][k])) continue;
        const float clo[3] = {c.lo[0][k], c.lo[1][k], c.lo[2][k]}, chi[3] = {c.hi[0][k], c.hi[1][k], c.hi[2][k]};
        if (!encloses(lo, hi, clo) || !encloses(lo, hi, chi)) return false;
    }
    return true;
}

void walk_child(const Bvh& bvh, const float* lo, const float* hi, int index, int count, int depth, Walk& w) {
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
void check_structure(const Bvh& bvh, const std::vector<glm::vec3>& input, std::size_t skipped) {
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

TEST(Bvh, StructureValid) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        std::vector<glm::vec3> torus = test::make_torus(100, 100, 1.0f, 0.3f).soup();
        std::size_t skipped = 99;
        Bvh bvh = build_bvh(torus, with_layout({}, layout), &skipped);
        EXPECT_EQ(skipped, 0u);
        check_structure(bvh, torus, skipped);
        EXPECT_LE(bvh.stats.max_leaf_size, BvhOptions{}.max_leaf_size);
        EXPECT_GT(bvh.stats.sah_cost, 1.0);
        EXPECT_LT(bvh.stats.sah_cost, 200.0);

        // Every centroid in one spot: no SAH split exists, yet leaves stay small and the
        // tree within the stack bound.
        std::vector<glm::vec3> stack;
        for (int i = 0; i < 5000; ++i) {
            float s = 1.0f + static_cast<float>(i) * 1e-3f;
            stack.insert(stack.end(),
                         {glm::vec3(-s, -s, 0.0f), glm::vec3(s, -s, 0.0f), glm::vec3(0.0f, 2.0f * s, 0.0f)});
        }
        Bvh same = build_bvh(stack, with_layout({}, layout), &skipped);
        check_structure(same, stack, skipped);
        EXPECT_LE(same.stats.max_leaf_size, BvhOptions{}.max_leaf_size);

        // Geometric progression of sizes: the SAH alone would build a list.
        std::vector<glm::vec3> nested;
        for (int i = 0; i < 300; ++i) {
            float s = std::ldexp(1.0f, -i / 3);
            nested.insert(nested.end(), {glm::vec3(0.0f), glm::vec3(s, 0.0f, 0.0f), glm::vec3(0.0f, s, s)});
        }
        BvhOptions one;
        one.max_leaf_size = 1;
        Bvh deep = build_bvh(nested, with_layout(one, layout), &skipped);
        check_structure(deep, nested, skipped);
        EXPECT_LE(3 * deep.stats.max_depth, FC_BVH_STACK_SIZE);
    }
}

// The builder's paths on inputs that reach each of them below the root (the
// references move between two buffers level by level): binned splits, the exact
// sweep of small ranges, the median fallback for coincident centroids under a binned
// split, every option combination, zero-area triangles kept out.
TEST(Bvh, StructureValidAcrossBuilderPaths) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        std::vector<glm::vec3> soup = test::make_torus(60, 40, 1.0f, 0.3f).soup();
        const std::size_t torus_tris = soup.size() / 3;
        // Two far clusters of triangles sharing one centroid each (odd counts), after the
        // binned root split; zero-area triangles in between.
        for (int c = 0; c < 2; ++c) {
            const glm::vec3 at(c ? 40.0f : -40.0f, 3.0f, -2.0f);
            for (int i = 0; i < 301 + 4 * c; ++i) {
                float s = 0.01f + static_cast<float>(i) * 1e-3f;
                soup.insert(soup.end(), {at + glm::vec3(-s, -s, 0.0f), at + glm::vec3(s, -s, 0.0f),
                                         at + glm::vec3(0.0f, 2.0f * s, 0.0f)});
            }
        }
        const glm::vec3 z(5.0f), x(6.0f, 5.0f, 5.0f);
        for (int i = 0; i < 7; ++i) soup.insert(soup.end(), {z, z, x});
        const std::size_t kept = soup.size() / 3 - 7;

        BvhOptions plain;
        plain.exact_max = 0;
        double plain_sah = 0.0;
        for (int bins : {2, 12, 32, 256})
            for (int exact : {0, 4, 16})
                for (int leaf : {1, 4, 8}) {
                    BvhOptions o;
                    o.bins = bins;
                    o.exact_max = exact;
                    o.max_leaf_size = leaf;
                    std::size_t skipped = 99;
                    Bvh bvh = build_bvh(soup, with_layout(o, layout), &skipped);
                    SCOPED_TRACE(testing::Message() << "bins " << bins << " exact " << exact << " leaf " << leaf);
                    EXPECT_EQ(skipped, 7u);
                    EXPECT_EQ(bvh.triangles.size(), kept);
                    check_structure(bvh, soup, skipped);
                    EXPECT_LE(bvh.stats.max_leaf_size, leaf);
                    EXPECT_GT(bvh.stats.sah_cost, 1.0);
                    if (bins == 12 && exact == 0 && leaf == 8) plain_sah = bvh.stats.sah_cost;
                }
        // The default build (exact sweep of small ranges) is no worse than plain binning.
        EXPECT_GT(plain_sah, 0.0);
        EXPECT_LE(build_bvh(soup, with_layout({}, layout)).stats.sah_cost, plain_sah * (1.0 + 1e-6));

        // Small inputs: every count up to a few binned levels, and the torus alone.
        for (std::size_t n : {1u, 2u, 3u, 5u, 8u, 9u, 16u, 17u, 33u, 129u, 130u}) {
            std::vector<glm::vec3> part(soup.begin(), soup.begin() + static_cast<std::ptrdiff_t>(3 * n));
            std::size_t skipped = 99;
            Bvh bvh = build_bvh(part, with_layout({}, layout), &skipped);
            SCOPED_TRACE(testing::Message() << n << " triangles");
            EXPECT_EQ(skipped, 0u);
            check_structure(bvh, part, skipped);
        }
        EXPECT_GT(torus_tris, 1000u);
    }
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
cl::Buffer upload(const std::vector<T>& v) {
    auto& ctx = test::context();
    std::size_t bytes = std::max<std::size_t>(v.size() * sizeof(T), 64);  // never 0 bytes
    cl::Buffer b(ctx.context(), CL_MEM_READ_ONLY, bytes);
    if (!v.empty()) ctx.queue().enqueueWriteBuffer(b, CL_TRUE, 0, v.size() * sizeof(T), v.data());
    return b;
}

// The next rays' origins from surface points leaving along their normals, by the
// kernels' own offset (kernels/test/trace_kernels.cl, offset_origins).
std::vector<glm::vec4> offset_origins(const std::vector<glm::vec4>& points, const std::vector<glm::vec4>& normals) {
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
const char* trace_program(const Bvh& bvh) {
    if (bvh.stats.quantised) return "kernels/test/trace_kernels8q.cl";
    return bvh.stats.width == 8 ? "kernels/test/trace_kernels8.cl" : "kernels/test/trace_kernels.cl";
}

Result run(const char* kernel_name, const Bvh& bvh, const Rays& rays) {
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
double plane_t(const std::vector<glm::vec3>& soup, int prim, glm::vec3 o, glm::vec3 d) {
    glm::dvec3 a(soup[3 * static_cast<std::size_t>(prim)]), b(soup[3 * static_cast<std::size_t>(prim) + 1]),
        c(soup[3 * static_cast<std::size_t>(prim) + 2]);
    glm::dvec3 n = glm::cross(b - a, c - a);
    return glm::dot(n, a - glm::dvec3(o)) / glm::dot(n, glm::dvec3(d));
}

// BVH and brute force agree on hit/miss, any-hit, and the nearest distance; the
// triangle may differ only where the two triangles' exact distances tie (duplicates,
// coplanar overlaps). Returns the BVH's result.
Result expect_agreement(const Bvh& bvh, const std::vector<glm::vec3>& soup, const Rays& rays) {
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
Rays random_rays(const std::vector<glm::vec3>& soup, std::size_t count, float extent, unsigned seed) {
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

TEST(Bvh, MatchesBruteForceOnMesh) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        std::vector<glm::vec3> torus = test::make_torus(50, 20, 1.0f, 0.35f).soup();
        Bvh bvh = build_bvh(torus, with_layout({}, layout));
        Result r = expect_agreement(bvh, torus, random_rays(torus, 100000, 1.6f, 1));
        EXPECT_GT(std::count_if(r.any.begin(), r.any.end(), [](int a) { return a != 0; }), 30000);
    }
}

// The Stanford bunny from ../shared/assets, when present.
TEST(Bvh, MatchesBruteForceOnBunny) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        const std::string bunny = FACET_ASSETS_DIR "/meshes_common3d/stanford-bunny.obj";
        if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
        std::vector<glm::vec3> soup = test::load_obj_soup(bunny);
        ASSERT_GT(soup.size(), 3000u);
        Bvh bb = build_bvh(soup, with_layout({}, layout));
        check_structure(bb, soup, soup.size() / 3 - bb.triangles.size());
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const glm::vec3& p : soup) lo = glm::min(lo, p), hi = glm::max(hi, p);
        Rays rays = random_rays(soup, 2000, 1.0f, 2);
        for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
        expect_agreement(bb, soup, rays);
    }
}

TEST(Bvh, MatchesBruteForceDegenerateMesh) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        std::size_t unusable = 0, skipped = 0;
        std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
        Bvh bvh = build_bvh(soup, with_layout({}, layout), &skipped);
        EXPECT_EQ(skipped, unusable);
        check_structure(bvh, soup, skipped);
        expect_agreement(bvh, soup, random_rays(soup, 100000, 1.5f, 3));
    }
}

// Rays aimed exactly at shared edges and vertices of closed meshes, from outside and
// from inside, must hit (Woop et al. 2013): on the integer grid cube the edge
// functions come out exactly zero; on the torus the rays are oblique.
TEST(Bvh, EdgesAndVerticesAreWatertight) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        Rays rays;
        std::vector<float> expect_t;  // expected distance; ray directions are not normalised
        const int n = 6;
        IndexedMesh cube = test::make_grid_cube(n);
        const glm::vec3 centre(0.5f * n);
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side)
                for (int i = 0; i <= 2 * n; ++i)
                    for (int j = 0; j <= 2 * n; ++j) {  // vertices, edge midpoints, diagonals
                        glm::vec3 p, out(0.0f);
                        p[axis] = static_cast<float>(side * n);
                        p[(axis + 1) % 3] = 0.5f * static_cast<float>(i);
                        p[(axis + 2) % 3] = 0.5f * static_cast<float>(j);
                        out[axis] = side ? 1.0f : -1.0f;
                        rays.add(p + 2.0f * out, -out), expect_t.push_back(2.0f);  // straight in
                        rays.add(centre, p - centre), expect_t.push_back(1.0f);    // from inside
                        glm::vec3 d = -out;
                        d[(axis + 1) % 3] = 0.25f, d[(axis + 2) % 3] = -0.5f;  // oblique, exact
                        rays.add(p - 2.0f * d, d), expect_t.push_back(-2.0f);  // any t <= 2
                    }
        Bvh cube_bvh = build_bvh(cube.soup(), with_layout({}, layout));
        std::vector<glm::vec3> cube_soup = cube.soup();
        Result r = expect_agreement(cube_bvh, cube_soup, rays);
        for (std::size_t i = 0; i < rays.o.size(); ++i) {
            ASSERT_GE(r.prim(i), 0) << "cube ray " << i << " slipped through";
            float t = r.hit[i].x;
            if (expect_t[i] > 0.0f) EXPECT_NEAR(t, expect_t[i], 1e-6f * expect_t[i]) << "cube ray " << i;
            else EXPECT_LE(t, -expect_t[i] * (1.0f + 1e-6f)) << "cube ray " << i;
        }

        // Torus: every vertex and every edge midpoint, along the tube's normal from outside
        // and from the tube's centre circle inside.
        const float R = 1.0f, tube = 0.35f;
        IndexedMesh torus = test::make_torus(40, 16, R, tube);
        std::vector<glm::vec3> targets = torus.positions;
        for (const glm::ivec3& f : torus.faces)
            for (int k = 0; k < 3; ++k)
                targets.push_back(0.5f * (torus.positions[f[k]] + torus.positions[f[(k + 1) % 3]]));
        Rays trays;
        for (const glm::vec3& p : targets) {
            glm::vec3 ring = R * glm::normalize(glm::vec3(p.x, p.y, 0.0f));
            glm::vec3 o = p + 0.5f * (p - ring);
            trays.add(o, p - o);
            trays.add(ring, p - ring);
        }
        std::vector<glm::vec3> torus_soup = torus.soup();
        Result tr = expect_agreement(build_bvh(torus_soup, with_layout({}, layout)), torus_soup, trays);
        for (std::size_t i = 0; i < trays.o.size(); ++i) {
            ASSERT_GE(tr.prim(i), 0) << "torus ray " << i << " slipped through";
            EXPECT_NEAR(tr.hit[i].x, 1.0f, 1e-4f) << "torus ray " << i;
        }
    }
}

TEST(Bvh, EmptyAndSingleTriangle) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        auto expect_empty_slot = [](const NodeView& n, int k) {
            EXPECT_EQ(n.count[k], 0);
            EXPECT_EQ(n.index[k], 0);
            for (int a = 0; a < 3; ++a)
                EXPECT_TRUE(std::isinf(n.lo[a][k]) && n.lo[a][k] > 0.0f && std::isinf(n.hi[a][k]) && n.hi[a][k] < 0.0f);
        };
        Rays rays = random_rays({}, 200, 2.0f, 4);
        rays.add(glm::vec3(0.25f, 0.5f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f));        // hits at t = 1
        rays.add(glm::vec3(0.25f, 0.5f, -2.0f), glm::vec3(0.0f, 0.0f, 2.0f));        // from behind
        rays.add(glm::vec3(0.25f, 0.5f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f), 0.5f);  // tmax short
        rays.add(glm::vec3(0.25f, 0.5f, 1.0f), glm::vec3(0.0f, 0.0f, 1.0f));         // away

        // Empty, and only unusable triangles: a root with two empty children, all rays miss.
        const glm::vec3 z(0.0f), x(1.0f, 0.0f, 0.0f);
        for (const std::vector<glm::vec3>& input :
             {std::vector<glm::vec3>{}, std::vector<glm::vec3>{z, z, x, z, x, 2.0f * x}}) {
            std::size_t skipped = 99;
            Bvh bvh = build_bvh(input, with_layout({}, layout), &skipped);
            EXPECT_EQ(skipped, input.size() / 3);
            ASSERT_EQ(bvh.stats.nodes, 1u);
            ASSERT_EQ(bvh.nodes.size(), static_cast<std::size_t>(layout.quantised ? 1 : layout.width / 4));
            EXPECT_EQ(bvh.stats.leaf_blocks, 0u);
            EXPECT_TRUE(bvh.triangles.empty());
            for (int k = 0; k < layout.width; ++k) expect_empty_slot(node_view(bvh, 0), k);
            Result r = expect_agreement(bvh, input, rays);
            for (std::size_t i = 0; i < rays.o.size(); ++i) EXPECT_EQ(r.prim(i), -1);
        }

        // One triangle: root = {leaf, empty}.
        std::vector<glm::vec3> one = {z, x, glm::vec3(0.0f, 1.0f, 0.0f)};
        Bvh bvh = build_bvh(one, with_layout({}, layout));
        ASSERT_EQ(bvh.stats.nodes, 1u);
        EXPECT_EQ(bvh.stats.leaf_blocks, 1u);
        EXPECT_EQ(node_view(bvh, 0).count[0], 1);
        for (int k = 1; k < layout.width; ++k) expect_empty_slot(node_view(bvh, 0), k);
        check_structure(bvh, one, 0);
        Result r = expect_agreement(bvh, one, rays);
        const std::size_t k = rays.o.size() - 4;
        EXPECT_EQ(r.prim(k), 0);
        EXPECT_FLOAT_EQ(r.hit[k].x, 1.0f);
        EXPECT_FLOAT_EQ(r.hit[k].y, 0.25f);  // weight of v1 = x
        EXPECT_FLOAT_EQ(r.hit[k].z, 0.5f);   // weight of v2 = y
        EXPECT_EQ(r.prim(k + 1), 0);
        EXPECT_FLOAT_EQ(r.hit[k + 1].x, 1.0f);
        EXPECT_EQ(r.prim(k + 2), -1);
        EXPECT_EQ(r.prim(k + 3), -1);

        EXPECT_THROW(build_bvh(std::vector<glm::vec3>(4), with_layout({}, layout)), Error);
    }
}

// Secondary rays leaving a surface from offset_ray_origin (Wächter & Binder 2019)
// never hit the triangle they start on, near the origin and far from it.
TEST(Bvh, OffsetOriginAvoidsSelfHits) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        for (float shift : {0.0f, 3000.0f}) {
            std::vector<glm::vec3> soup = test::make_torus(40, 16, 1.0f, 0.35f).soup();
            for (glm::vec3& p : soup) p += glm::vec3(shift, -shift, 0.5f * shift);
            Bvh bvh = build_bvh(soup, with_layout({}, layout));
            std::mt19937 rng(5);
            std::uniform_real_distribution<float> u01(0.0f, 1.0f), u(-1.0f, 1.0f);
            std::vector<glm::vec4> points, normals;
            std::vector<glm::vec3> dirs;
            std::vector<int> from;
            for (int i = 0; i < 20000; ++i) {
                int t = static_cast<int>(u01(rng) * static_cast<float>(soup.size() / 3 - 1));
                glm::vec3 a = soup[3 * t], b = soup[3 * t + 1], c = soup[3 * t + 2];
                float s = u01(rng), w = u01(rng) * (1.0f - s);
                glm::vec3 ng = glm::normalize(glm::cross(b - a, c - a));
                glm::vec3 d(u(rng), u(rng), u(rng));
                if (glm::dot(d, ng) < 0.0f) ng = -ng;  // the side the ray leaves from
                points.emplace_back(a + s * (b - a) + w * (c - a), 0.0f);
                normals.emplace_back(ng, 0.0f);
                dirs.push_back(d);
                from.push_back(t);
            }
            const std::vector<glm::vec4> origins = offset_origins(points, normals);
            Rays rays;
            for (std::size_t i = 0; i < origins.size(); ++i) rays.add(glm::vec3(origins[i]), dirs[i]);
            Result r = run("trace_rays_bvh", bvh, rays);
            int self = 0;
            for (std::size_t i = 0; i < origins.size(); ++i) self += r.prim(i) == from[i];
            EXPECT_EQ(self, 0) << "shift " << shift;
        }
    }
}

// A surface in the plane x = 0 of a large scene: the origin offset along x is the small
// fixed one (ray.cl: coordinates near 0), far below the rounding of the other
// coordinates, so only the triangle test's error bound on t keeps the ray off the
// surface it leaves. The wall and a second quad share one leaf block (LargeScene's lit
// wall, where half the shadow rays were blocked by the wall at 1e5 and up).
TEST(Bvh, NoSelfHitsOnAPlaneThroughZeroAtLargeScale) {
    for (const Layout& layout : kLayouts) {
        SCOPED_TRACE(layout.name);
        for (float scale : {1.0f, 1e5f, 1e10f}) {
            const glm::vec3 w0 = scale * glm::vec3(0.0f, -1.0f, -1.0f), wy = scale * glm::vec3(0.0f, 2.0f, 0.0f),
                            wz = scale * glm::vec3(0.0f, 0.0f, 2.0f);
            const glm::vec3 l0 = scale * glm::vec3(0.0f, 2.0f, -1.0f), lx = scale * glm::vec3(2.0f, 0.0f, 0.0f);
            std::vector<glm::vec3> soup = {w0, w0 + wy, w0 + wy + wz, w0, w0 + wy + wz, w0 + wz,
                                           l0, l0 + lx, l0 + lx + wz, l0, l0 + lx + wz, l0 + wz};
            Bvh bvh = build_bvh(soup, with_layout({}, layout));
            ASSERT_EQ(bvh.stats.leaves, 1u);
            std::mt19937 rng(6);
            std::uniform_real_distribution<float> u01(0.0f, 1.0f), u(-1.0f, 1.0f);
            std::vector<glm::vec4> points, normals;
            std::vector<glm::vec3> dirs;
            for (int i = 0; i < 4096; ++i) {
                points.emplace_back(w0 + u01(rng) * wy + u01(rng) * wz, 0.0f);
                normals.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
                dirs.emplace_back(0.05f + u01(rng), u(rng), u(rng));  // leaving on the +x side
            }
            const std::vector<glm::vec4> origins = offset_origins(points, normals);
            Rays rays;
            for (std::size_t i = 0; i < origins.size(); ++i) rays.add(glm::vec3(origins[i]), dirs[i]);
            Result r = expect_agreement(bvh, soup, rays);
            int self = 0;
            for (std::size_t i = 0; i < origins.size(); ++i) self += r.prim(i) == 0 || r.prim(i) == 1;
            EXPECT_EQ(self, 0) << "scale " << scale;
        }
    }
}

// ---- layouts against each other -------------------------------------------------------

// Two layouts' traversals over trees collapsed from the same binary tree (the same
// leaves, the same blocks) return the same nearest hit: the same triangle at the same t
// with the same barycentrics, bit for bit, and the same any-hit answer. With `ties`
// (soups of overlapping coplanar slivers, whose computed distances differ by more than
// the box tests' rounding, so the order of the visits decides), a different triangle
// is allowed where the two planes' exact distances tie, as in expect_agreement.
// Returns the number of rays that hit.
std::size_t expect_same_hits(const std::vector<glm::vec3>& soup, const BvhOptions& options, const Rays& rays,
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

TEST(Bvh, EightWideHitsEqualFourWideOnMeshes) {
    std::vector<glm::vec3> torus = test::make_torus(120, 60, 1.0f, 0.35f).soup();
    EXPECT_GT(expect_same_hits(torus, {}, random_rays(torus, 100000, 1.6f, 11)), 30000u);
    BvhOptions small;
    small.max_leaf_size = 1;  // many more inner nodes: every 8-wide node full
    expect_same_hits(torus, small, random_rays(torus, 20000, 1.6f, 12));
    std::size_t unusable = 0;
    std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
    expect_same_hits(soup, {}, random_rays(soup, 20000, 1.5f, 13), true);

    const std::string bunny = FACET_ASSETS_DIR "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    std::vector<glm::vec3> mesh = test::load_obj_soup(bunny);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh) lo = glm::min(lo, p), hi = glm::max(hi, p);
    Rays rays = random_rays(mesh, 50000, 1.0f, 14);
    for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
    EXPECT_GT(expect_same_hits(mesh, {}, rays), 10000u);
}

// Scenes of 1, 7, 8 and 9 triangles, one triangle a leaf or all in one leaf: the 8-wide
// root holds up to eight leaves, the ninth needs a second node; both widths against
// brute force and against each other.
TEST(Bvh, EightWideSmallScenes) {
    std::vector<glm::vec3> all;
    for (int i = 0; i < 9; ++i) {
        const glm::vec3 at(static_cast<float>(i % 3) * 1.5f, static_cast<float>(i / 3) * 1.5f,
                           0.2f * static_cast<float>(i));
        all.insert(all.end(), {at, at + glm::vec3(1.0f, 0.0f, 0.1f), at + glm::vec3(0.0f, 1.0f, -0.1f)});
    }
    for (std::size_t n : {1u, 7u, 8u, 9u})
        for (int leaf : {1, 8}) {
            SCOPED_TRACE(testing::Message() << n << " triangles, leaves of up to " << leaf);
            std::vector<glm::vec3> soup(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(3 * n));
            BvhOptions o;
            o.max_leaf_size = leaf;
            Rays rays = random_rays(soup, 4000, 3.0f, static_cast<unsigned>(20 + n));
            for (const Layout& layout : kLayouts) {
                SCOPED_TRACE(layout.name);
                Bvh bvh = build_bvh(soup, with_layout(o, layout));
                check_structure(bvh, soup, 0);
                expect_agreement(bvh, soup, rays);
                if (layout.width == 8 && leaf == 1) {
                    EXPECT_EQ(bvh.stats.nodes, n <= 8 ? 1u : 2u);
                }
            }
            expect_same_hits(soup, o, rays);
            expect_same_hits(soup, o, rays, false, kFloat8, kQuantised8);
        }
}

// Quantised boxes (FcBvhNodeQ) against the float boxes of the same tree: every decoded
// box contains the exact one and is at most one grid step (plus the decode's rounding)
// larger on each side; the same slots, children and leaves. Meshes near the origin, far
// from it, flat, tiny and huge.
TEST(Bvh, QuantisedBoxesContainFloatBoxes) {
    std::vector<std::vector<glm::vec3>> soups;
    soups.push_back(test::make_torus(80, 40, 1.0f, 0.35f).soup());
    for (float shift : {3000.0f, -1e5f}) {  // coordinates far above the node sizes
        soups.push_back(soups[0]);
        for (glm::vec3& p : soups.back()) p = 0.1f * p + glm::vec3(shift, 0.5f * shift, -shift);
    }
    soups.push_back(soups[0]);  // flat: every box of zero height along z
    for (glm::vec3& p : soups.back()) p.z = 2.5f;
    for (float scale : {1e-20f, 1e15f}) {
        soups.push_back(soups[0]);
        for (glm::vec3& p : soups.back()) p *= scale;
    }
    std::size_t unusable = 0;
    soups.push_back(test::make_degenerate_soup(1400, unusable));
    const std::string bunny = FACET_ASSETS_DIR "/meshes_common3d/stanford-bunny.obj";
    if (std::filesystem::exists(bunny)) soups.push_back(test::load_obj_soup(bunny));
    for (std::size_t s = 0; s < soups.size(); ++s) {
        SCOPED_TRACE(testing::Message() << "soup " << s);
        const Bvh f = build_bvh(soups[s], with_layout({}, kFloat8)),
                  q = build_bvh(soups[s], with_layout({}, kQuantised8));
        ASSERT_EQ(q.stats.quantised, 1);
        ASSERT_EQ(f.stats.nodes, q.stats.nodes);
        ASSERT_EQ(f.stats.leaf_blocks, q.stats.leaf_blocks);
        EXPECT_EQ(q.nodes.size(), (80 * q.stats.nodes + 160 * q.stats.leaf_blocks + 127) / 128);
        check_structure(q, soups[s], soups[s].size() / 3 - q.triangles.size());
        const std::int64_t shift =
            5 * static_cast<std::int64_t>(q.stats.nodes) - 16 * static_cast<std::int64_t>(f.stats.nodes);
        int failures = 0;
        for (std::size_t i = 0; i < f.stats.nodes && failures < 10; ++i) {
            const NodeView a = node_view(f, i), b = node_view(q, i);
            const FcBvhNodeQ raw = wide_node_q(q, i);
            for (int k = 0; k < 8; ++k) {
                ASSERT_EQ(a.count[k], b.count[k]) << "node " << i << " slot " << k;
                if (a.lo[0][k] > a.hi[0][k]) continue;  // empty in both (count and index 0, checked by the walk)
                ASSERT_EQ(a.count[k] == 0 ? a.index[k] : a.index[k] + shift, b.index[k])
                    << "node " << i << " slot " << k;
                for (int ax = 0; ax < 3; ++ax) {
                    const float step = std::bit_cast<float>(((raw.exps >> (8 * ax)) & 0xffu) << 23);
                    const float slack = step +
                                        2.0f * std::fabs(std::nextafter(raw.origin[ax], INFINITY) - raw.origin[ax]) +
                                        2.0f * std::fabs(std::nextafter(a.hi[ax][k], INFINITY) - a.hi[ax][k]);
                    const bool ok = b.lo[ax][k] <= a.lo[ax][k] && a.hi[ax][k] <= b.hi[ax][k] &&
                                    a.lo[ax][k] - b.lo[ax][k] <= slack && b.hi[ax][k] - a.hi[ax][k] <= slack;
                    if (!ok && ++failures <= 10)
                        ADD_FAILURE() << "node " << i << " slot " << k << " axis " << ax << ": float [" << a.lo[ax][k]
                                      << ", " << a.hi[ax][k] << "], quantised [" << b.lo[ax][k] << ", " << b.hi[ax][k]
                                      << "], step " << step;
                }
            }
        }
    }
}

// Quantised traversal against the float boxes' over the same tree: the same hits bit for
// bit (t, barycentrics, triangle) and the same any-hit answers; the conservative boxes
// only add visits.
TEST(Bvh, QuantisedHitsEqualFloatOnMeshes) {
    std::vector<glm::vec3> torus = test::make_torus(120, 60, 1.0f, 0.35f).soup();
    EXPECT_GT(expect_same_hits(torus, {}, random_rays(torus, 100000, 1.6f, 31), false, kFloat8, kQuantised8), 30000u);
    BvhOptions small;
    small.max_leaf_size = 1;
    expect_same_hits(torus, small, random_rays(torus, 20000, 1.6f, 32), false, kFloat8, kQuantised8);
    std::vector<glm::vec3> far = torus;
    for (glm::vec3& p : far) p = 0.01f * p + glm::vec3(3000.0f, 1500.0f, -3000.0f);
    Rays far_rays = random_rays(far, 20000, 0.02f, 33);
    for (auto& o : far_rays.o) o += glm::vec4(3000.0f, 1500.0f, -3000.0f, 0.0f);
    expect_same_hits(far, {}, far_rays, false, kFloat8, kQuantised8);
    std::size_t unusable = 0;
    std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
    expect_same_hits(soup, {}, random_rays(soup, 20000, 1.5f, 34), true, kFloat8, kQuantised8);

    const std::string bunny = FACET_ASSETS_DIR "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    std::vector<glm::vec3> mesh = test::load_obj_soup(bunny);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh) lo = glm::min(lo, p), hi = glm::max(hi, p);
    Rays rays = random_rays(mesh, 100000, 1.0f, 35);
    for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
    EXPECT_GT(expect_same_hits(mesh, {}, rays, false, kFloat8, kQuantised8), 20000u);
}

// The width comes from BvhOptions::width, else FACET_BVH_WIDTH, else 4; anything else is
// refused with a message that names it. bvh_width_for picks one by device.
TEST(Bvh, WidthChoice) {
    const std::vector<glm::vec3> tri = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    const char* saved = std::getenv("FACET_BVH_WIDTH");
    const std::string keep = saved ? saved : "";
    unsetenv("FACET_BVH_WIDTH");
    EXPECT_EQ(build_bvh(tri).stats.width, 4);
    EXPECT_EQ(build_bvh(tri, with_layout({}, kFloat8)).stats.width, 8);
    EXPECT_EQ(bvh_prelude(build_bvh(tri, with_layout({}, kFloat8))), "#define FC_BVH_WIDTH 8");
    setenv("FACET_BVH_WIDTH", "8", 1);
    EXPECT_EQ(build_bvh(tri).stats.width, 8);
    EXPECT_EQ(build_bvh(tri, with_layout({}, kLayouts[0])).stats.width, 4);
    setenv("FACET_BVH_WIDTH", "16", 1);
    try {
        build_bvh(tri);
        ADD_FAILURE() << "FACET_BVH_WIDTH=16 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("FACET_BVH_WIDTH is \"16\""), std::string::npos) << e.what();
    }
    EXPECT_THROW(build_bvh(tri, with_layout({}, {2, 0, "2-wide"})), Error);
    // By device, FACET_BVH_WIDTH unset: 8 on CPUs with 8-wide float vectors, 4 elsewhere.
    unsetenv("FACET_BVH_WIDTH");
    EXPECT_EQ(bvh_width_for(false, 8), 8);
    EXPECT_EQ(bvh_width_for(false, 16), 8);
    EXPECT_EQ(bvh_width_for(false, 4), 4);
    EXPECT_EQ(bvh_width_for(true, 8), 4);
    setenv("FACET_BVH_WIDTH", "4", 1);
    EXPECT_EQ(bvh_width_for(false, 8), 4);
    if (saved) setenv("FACET_BVH_WIDTH", keep.c_str(), 1);
    else unsetenv("FACET_BVH_WIDTH");
}

// Quantised 8-wide nodes come from BvhOptions::quantised, else FACET_BVH_QUANTISED, else
// kQuantisedDefault where every leaf fits the node's bytes (max_leaf_size <= 16); 4-wide
// trees are never quantised; bad values are refused with a message that names them.
TEST(Bvh, QuantisedChoice) {
    const std::vector<glm::vec3> tri = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    const char* saved = std::getenv("FACET_BVH_QUANTISED");
    const std::string keep = saved ? saved : "";
    auto expect_error = [&](const BvhOptions& o, const std::string& part) {
        try {
            build_bvh(tri, o);
            ADD_FAILURE() << "accepted, expected an error naming " << part;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    unsetenv("FACET_BVH_QUANTISED");
    BvhOptions o;
    o.width = 8;
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, kQuantisedDefault ? 1 : 0);
    o.max_leaf_size = 17;
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 0);
    o.quantised = 1;
    expect_error(o, "quantised nodes hold leaves of up to 16 triangles, max_leaf_size is 17");
    o.max_leaf_size = 16;
    const Bvh q = build_bvh(tri, o);
    EXPECT_EQ(q.stats.quantised, 1);
    EXPECT_EQ(bvh_prelude(q), "#define FC_BVH_WIDTH 8\n#define FC_BVH_QUANTISED 1");
    EXPECT_THROW(wide_node_q(build_bvh(tri, with_layout({}, kFloat8)), 0), Error);
    o.quantised = -1;
    setenv("FACET_BVH_QUANTISED", "0", 1);
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 0);
    setenv("FACET_BVH_QUANTISED", "1", 1);
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 1);
    EXPECT_EQ(build_bvh(tri, with_layout(o, kFloat8)).stats.quantised, 0);  // the option wins
    o.width = 4;
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 0);
    o.quantised = 1;
    expect_error(o, "quantised nodes are 8-wide");
    o.width = 8;
    o.quantised = -1;
    setenv("FACET_BVH_QUANTISED", "yes", 1);
    expect_error(o, "FACET_BVH_QUANTISED is \"yes\"");
    if (saved) setenv("FACET_BVH_QUANTISED", keep.c_str(), 1);
    else unsetenv("FACET_BVH_QUANTISED");
}

}  // namespace
}  // namespace facet
