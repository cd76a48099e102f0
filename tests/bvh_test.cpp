// The BVH builder (host/bvh/) and its traversal (kernels/trace/): the tree's structure
// on the host, and on the device the BVH against a brute-force loop over every
// triangle with the same watertight triangle test.
#include <gtest/gtest.h>

#include "tests/bvh_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace bvh_test;

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
        const std::string bunny = test::assets_dir() + "/meshes_common3d/stanford-bunny.obj";
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
            BvhOptions one_leaf;  // both planes in one leaf: a block test as cheap as a node visit
            one_leaf.intersection_cost = 1.0f;
            Bvh bvh = build_bvh(soup, with_layout(one_leaf, layout));
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

}  // namespace
}  // namespace facet
