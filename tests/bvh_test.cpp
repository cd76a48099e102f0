// The BVH builder (host/bvh/) and its traversal (kernels/trace/): the tree's structure
// on the host, and on the device the BVH against a brute-force loop over every
// triangle with the same watertight triangle test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "host/bvh/bvh.hpp"
#include "tests/bvh_meshes.hpp"
#include "tests/cl_test_env.hpp"
#include "host/error.hpp"

namespace facet {
namespace {

using test::IndexedMesh;

// ---- host-side structure ------------------------------------------------------------

struct Walk {
    std::vector<int> seen;  // leaf visits per triangle
    int max_depth = 0;
    std::size_t leaves = 0;
};

bool encloses(const float* lo, const float* hi, const float* p) {
    for (int a = 0; a < 3; ++a)
        if (!(lo[a] <= p[a] && p[a] <= hi[a])) return false;
    return true;
}

void walk_child(const Bvh& bvh, const float* lo, const float* hi, int index, int count, int depth, Walk& w);

void walk_node(const Bvh& bvh, int node, int depth, Walk& w) {
    ASSERT_GE(node, 0);
    ASSERT_LT(static_cast<std::size_t>(node), bvh.stats.nodes);
    ASSERT_LE(3 * (depth + 1), FC_BVH_STACK_SIZE) << "deeper than the traversal stack allows";
    const FcBvhNode& n = bvh.nodes[static_cast<std::size_t>(node)];
    for (int k = 0; k < 4; ++k) {
        const float lo[3] = {n.lo_x[k], n.lo_y[k], n.lo_z[k]}, hi[3] = {n.hi_x[k], n.hi_y[k], n.hi_z[k]};
        walk_child(bvh, lo, hi, n.index[k], n.count[k], depth + 1, w);
    }
}

// Whether box [lo, hi] encloses all four child boxes of node `c` that are not empty.
bool encloses_children(const float* lo, const float* hi, const FcBvhNode& c) {
    for (int k = 0; k < 4; ++k) {
        if (!(c.lo_x[k] <= c.hi_x[k])) continue;
        const float clo[3] = {c.lo_x[k], c.lo_y[k], c.lo_z[k]}, chi[3] = {c.hi_x[k], c.hi_y[k], c.hi_z[k]};
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
        EXPECT_TRUE(encloses_children(lo, hi, bvh.nodes[static_cast<std::size_t>(index)]));
        walk_node(bvh, index, depth, w);
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
        }
    }
}

// Every kept triangle in exactly one leaf, boxes enclosing their contents, stats true.
void check_structure(const Bvh& bvh, const std::vector<glm::vec3>& input, std::size_t skipped) {
    ASSERT_GE(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.triangles.size() + skipped, input.size() / 3);
    Walk w;
    w.seen.assign(bvh.triangles.size(), 0);
    walk_node(bvh, 0, 0, w);
    for (std::size_t i = 0; i < w.seen.size(); ++i) ASSERT_EQ(w.seen[i], 1) << "triangle " << i;
    std::vector<char> prim_seen(input.size() / 3, 0);
    for (const FcTriangle& t : bvh.triangles) {
        ASSERT_GE(t.prim, 0);
        ASSERT_EQ(prim_seen[static_cast<std::size_t>(t.prim)]++, 0);
        const glm::vec3& v0 = input[3 * static_cast<std::size_t>(t.prim)];
        EXPECT_TRUE(v0.x == t.v0[0] && v0.y == t.v0[1] && v0.z == t.v0[2]);
    }
    EXPECT_EQ(w.max_depth, bvh.stats.max_depth);
    EXPECT_LE(3 * bvh.stats.max_depth, FC_BVH_STACK_SIZE);
    EXPECT_EQ(w.leaves, bvh.stats.leaves);
    EXPECT_EQ(bvh.nodes.size(), bvh.stats.nodes + (bvh.stats.leaf_blocks * 160 + 127) / 128);
    EXPECT_EQ(bvh.stats.triangles, bvh.triangles.size());
    EXPECT_EQ(bvh.stats.device_bytes, bvh.nodes.size() * 128 + bvh.triangles.size() * 48);
}

TEST(Bvh, StructureValid) {
    std::vector<glm::vec3> torus = test::make_torus(100, 100, 1.0f, 0.3f).soup();
    std::size_t skipped = 99;
    Bvh bvh = build_bvh(torus, {}, &skipped);
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
        stack.insert(stack.end(), {glm::vec3(-s, -s, 0.0f), glm::vec3(s, -s, 0.0f), glm::vec3(0.0f, 2.0f * s, 0.0f)});
    }
    Bvh same = build_bvh(stack, {}, &skipped);
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
    Bvh deep = build_bvh(nested, one, &skipped);
    check_structure(deep, nested, skipped);
    EXPECT_LE(3 * deep.stats.max_depth, FC_BVH_STACK_SIZE);
}

// The builder's paths on inputs that reach each of them below the root (the
// references move between two buffers level by level): binned splits, the exact
// sweep of small ranges, the median fallback for coincident centroids under a binned
// split, every option combination, zero-area triangles kept out.
TEST(Bvh, StructureValidAcrossBuilderPaths) {
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
                Bvh bvh = build_bvh(soup, o, &skipped);
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
    EXPECT_LE(build_bvh(soup).stats.sah_cost, plain_sah * (1.0 + 1e-6));

    // Small inputs: every count up to a few binned levels, and the torus alone.
    for (std::size_t n : {1u, 2u, 3u, 5u, 8u, 9u, 16u, 17u, 33u, 129u, 130u}) {
        std::vector<glm::vec3> part(soup.begin(), soup.begin() + static_cast<std::ptrdiff_t>(3 * n));
        std::size_t skipped = 99;
        Bvh bvh = build_bvh(part, {}, &skipped);
        SCOPED_TRACE(testing::Message() << n << " triangles");
        EXPECT_EQ(skipped, 0u);
        check_structure(bvh, part, skipped);
    }
    EXPECT_GT(torus_tris, 1000u);
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

Result run(const char* kernel_name, const Bvh& bvh, const Rays& rays) {
    auto& ctx = test::context();
    cl::Kernel k(test::program("kernels/test/trace_kernels.cl"), kernel_name);
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
    std::vector<glm::vec3> torus = test::make_torus(50, 20, 1.0f, 0.35f).soup();
    Bvh bvh = build_bvh(torus);
    Result r = expect_agreement(bvh, torus, random_rays(torus, 100000, 1.6f, 1));
    EXPECT_GT(std::count_if(r.any.begin(), r.any.end(), [](int a) { return a != 0; }), 30000);
}

// The Stanford bunny from ../shared/assets, when present.
TEST(Bvh, MatchesBruteForceOnBunny) {
    const std::string bunny = FACET_ASSETS_DIR "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    std::vector<glm::vec3> soup = test::load_obj_soup(bunny);
    ASSERT_GT(soup.size(), 3000u);
    Bvh bb = build_bvh(soup);
    check_structure(bb, soup, soup.size() / 3 - bb.triangles.size());
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : soup) lo = glm::min(lo, p), hi = glm::max(hi, p);
    Rays rays = random_rays(soup, 2000, 1.0f, 2);
    for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
    expect_agreement(bb, soup, rays);
}

TEST(Bvh, MatchesBruteForceDegenerateMesh) {
    std::size_t unusable = 0, skipped = 0;
    std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
    Bvh bvh = build_bvh(soup, {}, &skipped);
    EXPECT_EQ(skipped, unusable);
    check_structure(bvh, soup, skipped);
    expect_agreement(bvh, soup, random_rays(soup, 100000, 1.5f, 3));
}

// Rays aimed exactly at shared edges and vertices of closed meshes, from outside and
// from inside, must hit (Woop et al. 2013): on the integer grid cube the edge
// functions come out exactly zero; on the torus the rays are oblique.
TEST(Bvh, EdgesAndVerticesAreWatertight) {
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
    Bvh cube_bvh = build_bvh(cube.soup());
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
        for (int k = 0; k < 3; ++k) targets.push_back(0.5f * (torus.positions[f[k]] + torus.positions[f[(k + 1) % 3]]));
    Rays trays;
    for (const glm::vec3& p : targets) {
        glm::vec3 ring = R * glm::normalize(glm::vec3(p.x, p.y, 0.0f));
        glm::vec3 o = p + 0.5f * (p - ring);
        trays.add(o, p - o);
        trays.add(ring, p - ring);
    }
    std::vector<glm::vec3> torus_soup = torus.soup();
    Result tr = expect_agreement(build_bvh(torus_soup), torus_soup, trays);
    for (std::size_t i = 0; i < trays.o.size(); ++i) {
        ASSERT_GE(tr.prim(i), 0) << "torus ray " << i << " slipped through";
        EXPECT_NEAR(tr.hit[i].x, 1.0f, 1e-4f) << "torus ray " << i;
    }
}

TEST(Bvh, EmptyAndSingleTriangle) {
    auto expect_empty_slot = [](const FcBvhNode& n, int k) {
        EXPECT_EQ(n.count[k], 0);
        EXPECT_EQ(n.index[k], 0);
        const float lo[3] = {n.lo_x[k], n.lo_y[k], n.lo_z[k]}, hi[3] = {n.hi_x[k], n.hi_y[k], n.hi_z[k]};
        for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isinf(lo[a]) && lo[a] > 0.0f && std::isinf(hi[a]) && hi[a] < 0.0f);
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
        Bvh bvh = build_bvh(input, {}, &skipped);
        EXPECT_EQ(skipped, input.size() / 3);
        ASSERT_EQ(bvh.nodes.size(), 1u);
        EXPECT_EQ(bvh.stats.leaf_blocks, 0u);
        EXPECT_TRUE(bvh.triangles.empty());
        for (int k = 0; k < 4; ++k) expect_empty_slot(bvh.nodes[0], k);
        Result r = expect_agreement(bvh, input, rays);
        for (std::size_t i = 0; i < rays.o.size(); ++i) EXPECT_EQ(r.prim(i), -1);
    }

    // One triangle: root = {leaf, empty}.
    std::vector<glm::vec3> one = {z, x, glm::vec3(0.0f, 1.0f, 0.0f)};
    Bvh bvh = build_bvh(one);
    ASSERT_EQ(bvh.stats.nodes, 1u);
    EXPECT_EQ(bvh.stats.leaf_blocks, 1u);
    EXPECT_EQ(bvh.nodes[0].count[0], 1);
    for (int k = 1; k < 4; ++k) expect_empty_slot(bvh.nodes[0], k);
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

    EXPECT_THROW(build_bvh(std::vector<glm::vec3>(4)), Error);
}

// Secondary rays leaving a surface from offset_ray_origin (Wächter & Binder 2019)
// never hit the triangle they start on, near the origin and far from it.
TEST(Bvh, OffsetOriginAvoidsSelfHits) {
    for (float shift : {0.0f, 3000.0f}) {
        std::vector<glm::vec3> soup = test::make_torus(40, 16, 1.0f, 0.35f).soup();
        for (glm::vec3& p : soup) p += glm::vec3(shift, -shift, 0.5f * shift);
        Bvh bvh = build_bvh(soup);
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
        auto& ctx = test::context();
        cl::Kernel k(test::program("kernels/test/trace_kernels.cl"), "offset_origins");
        cl::Buffer pb = upload(points), nb = upload(normals);
        cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, points.size() * sizeof(glm::vec4));
        k.setArg(0, pb), k.setArg(1, nb), k.setArg(2, ob);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(points.size()));
        std::vector<glm::vec4> origins(points.size());
        ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, origins.size() * sizeof(glm::vec4), origins.data());
        Rays rays;
        for (std::size_t i = 0; i < origins.size(); ++i) rays.add(glm::vec3(origins[i]), dirs[i]);
        Result r = run("trace_rays_bvh", bvh, rays);
        int self = 0;
        for (std::size_t i = 0; i < origins.size(); ++i) self += r.prim(i) == from[i];
        EXPECT_EQ(self, 0) << "shift " << shift;
    }
}

// A surface in the plane x = 0 of a large scene: the origin offset along x is the small
// fixed one (ray.cl: coordinates near 0), far below the rounding of the other
// coordinates, so only the triangle test's error bound on t keeps the ray off the
// surface it leaves. The wall and a second quad share one leaf block (LargeScene's lit
// wall, where half the shadow rays were blocked by the wall at 1e5 and up).
TEST(Bvh, NoSelfHitsOnAPlaneThroughZeroAtLargeScale) {
    for (float scale : {1.0f, 1e5f, 1e10f}) {
        const glm::vec3 w0 = scale * glm::vec3(0.0f, -1.0f, -1.0f), wy = scale * glm::vec3(0.0f, 2.0f, 0.0f),
                        wz = scale * glm::vec3(0.0f, 0.0f, 2.0f);
        const glm::vec3 l0 = scale * glm::vec3(0.0f, 2.0f, -1.0f), lx = scale * glm::vec3(2.0f, 0.0f, 0.0f);
        std::vector<glm::vec3> soup = {w0, w0 + wy, w0 + wy + wz, w0, w0 + wy + wz, w0 + wz,
                                       l0, l0 + lx, l0 + lx + wz, l0, l0 + lx + wz, l0 + wz};
        Bvh bvh = build_bvh(soup);
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
        auto& ctx = test::context();
        cl::Kernel k(test::program("kernels/test/trace_kernels.cl"), "offset_origins");
        cl::Buffer pb = upload(points), nb = upload(normals);
        cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, points.size() * sizeof(glm::vec4));
        k.setArg(0, pb), k.setArg(1, nb), k.setArg(2, ob);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(points.size()));
        std::vector<glm::vec4> origins(points.size());
        ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, origins.size() * sizeof(glm::vec4), origins.data());
        Rays rays;
        for (std::size_t i = 0; i < origins.size(); ++i) rays.add(glm::vec3(origins[i]), dirs[i]);
        Result r = expect_agreement(bvh, soup, rays);
        int self = 0;
        for (std::size_t i = 0; i < origins.size(); ++i) self += r.prim(i) == 0 || r.prim(i) == 1;
        EXPECT_EQ(self, 0) << "scale " << scale;
    }
}

}  // namespace
}  // namespace facet
