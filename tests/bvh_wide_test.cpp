// The 8-wide (FcBvhNode8) and quantised (FcBvhNodeQ) layouts against the 4-wide one and
// each other: the same hits bit for bit, small scenes, quantised boxes that contain the
// float ones, and how the layout is chosen.
#include <gtest/gtest.h>

#include "tests/bvh_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace bvh_test;

// random_rays with their origins moved inside the mesh's bounding box (its middle 3/4), so
// that a closed mesh such as the bunny is hit from inside as well.
Rays rays_from_inside(const std::vector<glm::vec3>& mesh, std::size_t count, unsigned seed) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh) lo = glm::min(lo, p), hi = glm::max(hi, p);
    Rays rays = random_rays(mesh, count, 1.0f, seed);
    for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
    return rays;
}

TEST(BvhWide, EightWideHitsEqualFourWideOnMeshes) {
    std::vector<glm::vec3> torus = test::make_torus(120, 60, 1.0f, 0.35f).soup();
    EXPECT_GT(expect_same_hits(torus, {}, random_rays(torus, 100000, 1.6f, 11)), 30000u);
    BvhOptions small;
    small.max_leaf_size = 1;  // many more inner nodes: every 8-wide node full
    expect_same_hits(torus, small, random_rays(torus, 20000, 1.6f, 12));
    std::size_t unusable = 0;
    std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
    expect_same_hits(soup, {}, random_rays(soup, 20000, 1.5f, 13), true);

    const std::string bunny = test::assets_dir() + "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    std::vector<glm::vec3> mesh = test::load_obj_soup(bunny);
    Rays rays = rays_from_inside(mesh, 50000, 14);
    EXPECT_GT(expect_same_hits(mesh, {}, rays), 10000u);
}

// Scenes of 1, 7, 8 and 9 triangles, one triangle a leaf or all in one leaf: the 8-wide
// root holds up to eight leaves, the ninth needs a second node; both widths against
// brute force and against each other.
TEST(BvhWide, EightWideSmallScenes) {
    const std::vector<glm::vec3> all = nine_triangles();
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
TEST(BvhWide, QuantisedBoxesContainFloatBoxes) {
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
    const std::string bunny = test::assets_dir() + "/meshes_common3d/stanford-bunny.obj";
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
TEST(BvhWide, QuantisedHitsEqualFloatOnMeshes) {
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

    const std::string bunny = test::assets_dir() + "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    std::vector<glm::vec3> mesh = test::load_obj_soup(bunny);
    Rays rays = rays_from_inside(mesh, 100000, 35);
    EXPECT_GT(expect_same_hits(mesh, {}, rays, false, kFloat8, kQuantised8), 20000u);
}

// The width comes from BvhOptions::width, else FACET_BVH_WIDTH, else 4; anything else is
// refused with a message that names it. bvh_width_for picks one by device.
TEST(BvhWide, WidthChoice) {
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
// from the size: above kQuantiseAboveTriangles (the tree's own, or
// BvhOptions::layout_triangles when set), where every leaf fits the node's bytes
// (max_leaf_size <= 16); 4-wide trees are never quantised; bad values are refused with a
// message that names them.
TEST(BvhWide, QuantisedChoice) {
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
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 0);  // one triangle: float boxes
    EXPECT_FALSE(resolve_quantised(o, kQuantiseAboveTriangles));
    EXPECT_TRUE(resolve_quantised(o, kQuantiseAboveTriangles + 1));
    o.layout_triangles = kQuantiseAboveTriangles + 1;  // a scene's instanced meshes counted
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 1);
    EXPECT_FALSE(resolve_quantised(BvhOptions{.layout_triangles = 10}, kQuantiseAboveTriangles + 1));
    o.max_leaf_size = 17;
    EXPECT_EQ(build_bvh(tri, o).stats.quantised, 0);
    o.layout_triangles = 0;
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
