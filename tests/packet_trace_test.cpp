// Rays in packets through the triangles' tree (kernels/trace/packet_trace.cl) against the
// single-ray traversal (bvh_traverse.cl): the same nearest hit, bit for bit (t, barycentrics,
// triangle), but where two triangles' planes tie, for packets of 8 and 16 over float and
// quantised 8-wide nodes, with every lane traced, some, or fewer than the packet needs (whose
// rays then trace alone from the root), and rays incoherent, coherent, or from inside a mesh;
// and as shadow rays, blocked where the single ray meets a triangle.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "tests/bvh_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using namespace bvh_test;

const char* packet_program(int width, bool quantised) {
    if (width == 8)
        return quantised ? "kernels/test/packet_trace_kernels_w8q.cl" : "kernels/test/packet_trace_kernels_w8.cl";
    return quantised ? "kernels/test/packet_trace_kernels_w16q.cl" : "kernels/test/packet_trace_kernels_w16.cl";
}

struct PacketResult {
    Result r;
    std::vector<int> met;
};

// The rays (a multiple of `width` of them), those with traced[i] != 0, in packets: for their
// nearest hits, or with `any` as shadow rays (then only `met`).
PacketResult run_packets(const Bvh& bvh, const Rays& rays, const std::vector<int>& traced, int width,
                         bool any = false) {
    auto& ctx = test::context();
    cl::Kernel k(test::program(packet_program(width, bvh.stats.quantised != 0)), "trace_rays_packet");
    const std::size_t n = rays.o.size();
    cl::Buffer nodes = upload(bvh.nodes), tris = upload(bvh.triangles);
    cl::Buffer o = upload(rays.o), d = upload(rays.d), t = upload(traced);
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(glm::vec4));
    cl::Buffer met(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
    int arg = 0;
    for (cl::Buffer* b : {&nodes, &tris, &o, &d, &t, &out, &met}) k.setArg(arg++, *b);
    k.setArg(arg, any ? 1 : 0);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n / static_cast<std::size_t>(width)));
    PacketResult p;
    p.r.hit.resize(n);
    p.met.resize(n);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(glm::vec4), p.r.hit.data());
    ctx.queue().enqueueReadBuffer(met, CL_TRUE, 0, n * sizeof(int), p.met.data());
    return p;
}

// Which lanes a packet traces: all; about half; one to three of each packet (fewer than
// FC_PACKET_TRACE_MIN: they trace alone from the root).
enum class Lanes { kAll, kHalf, kFew };

std::vector<int> lane_pattern(std::size_t n, Lanes lanes, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<int> traced(n, 1);
    if (lanes == Lanes::kAll) return traced;
    for (std::size_t i = 0; i < n; ++i)
        traced[i] = lanes == Lanes::kHalf ? static_cast<int>(rng() & 1u) : (rng() % 8u == 0u);
    return traced;
}

// Packet and single rays agree on every ray: traced rays bit for bit or on a tie of planes
// (as expect_same_hits), untraced ones untouched. Returns the traced rays that hit.
std::size_t expect_packets_match(const std::vector<glm::vec3>& soup, const BvhOptions& options, Rays rays) {
    while (rays.o.size() % 16 != 0) rays.add(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    std::size_t hits = 0;
    for (const Layout& layout : {kFloat8, kQuantised8}) {
        const Bvh bvh = build_bvh(soup, with_layout(options, layout));
        const Result single = run("trace_rays_bvh", bvh, rays);
        for (int width : {8, 16})
            for (Lanes lanes : {Lanes::kAll, Lanes::kHalf, Lanes::kFew}) {
                SCOPED_TRACE(testing::Message()
                             << layout.name << ", packets of " << width << ", lanes " << static_cast<int>(lanes));
                const std::vector<int> traced = lane_pattern(rays.o.size(), lanes, 7u + static_cast<unsigned>(width));
                const PacketResult p = run_packets(bvh, rays, traced, width);
                int failures = 0;
                for (std::size_t i = 0; i < rays.o.size() && failures < 10; ++i) {
                    if (!traced[i]) {
                        if (p.r.prim(i) == -1 && p.met[i] == 0 && p.r.hit[i].x == rays.d[i].w) continue;
                    } else {
                        const bool same_met = p.met[i] == (p.r.prim(i) >= 0 ? 1 : 0);
                        hits += single.prim(i) >= 0;
                        if (same_met && std::memcmp(&p.r.hit[i], &single.hit[i], sizeof p.r.hit[i]) == 0) continue;
                        if (same_met && p.r.prim(i) >= 0 && single.prim(i) >= 0) {
                            const glm::vec3 o(rays.o[i]), d(rays.d[i]);
                            const double a = plane_t(soup, p.r.prim(i), o, d), b = plane_t(soup, single.prim(i), o, d);
                            if (std::fabs(a - b) <= 1e-5 * std::fabs(a)) continue;
                        }
                    }
                    ++failures;
                    ADD_FAILURE() << "ray " << i << (traced[i] ? "" : " (not traced)") << ": packet prim "
                                  << p.r.prim(i) << " t " << p.r.hit[i].x << " met " << p.met[i] << ", single prim "
                                  << single.prim(i) << " t " << single.hit[i].x;
                }
                // as shadow rays: blocked exactly where the single ray meets a triangle
                const PacketResult a = run_packets(bvh, rays, traced, width, true);
                failures = 0;
                for (std::size_t i = 0; i < rays.o.size() && failures < 10; ++i) {
                    const int blocked = traced[i] && single.prim(i) >= 0 ? 1 : 0;
                    if (a.met[i] == blocked) continue;
                    ++failures;
                    ADD_FAILURE() << "shadow ray " << i << (traced[i] ? "" : " (not traced)") << ": packet met "
                                  << a.met[i] << ", single prim " << single.prim(i);
                }
            }
    }
    return hits;
}

// Rays from one point through a grid of directions toward the mesh's box, as a camera's.
Rays camera_rays(const std::vector<glm::vec3>& soup, int side) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : soup) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 c = 0.5f * (lo + hi), size = hi - lo;
    const glm::vec3 eye = c + glm::vec3(0.3f, 0.4f, 2.5f) * glm::max(size.x, glm::max(size.y, size.z));
    Rays rays;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const glm::vec3 target = lo + size * glm::vec3((x + 0.5f) / side, (y + 0.5f) / side, 0.5f);
            rays.add(eye, target - eye);
        }
    return rays;
}

TEST(PacketTrace, SameHitsAsSingleRaysOnMeshes) {
    const std::vector<glm::vec3> torus = test::make_torus(120, 60, 1.0f, 0.35f).soup();
    EXPECT_GT(expect_packets_match(torus, {}, random_rays(torus, 8000, 1.6f, 31)), 1000u);
    EXPECT_GT(expect_packets_match(torus, {}, camera_rays(torus, 64)), 1000u);
    BvhOptions small;
    small.max_leaf_size = 1;  // many inner nodes: deep packets, subtrees handed to single rays
    expect_packets_match(torus, small, random_rays(torus, 4000, 1.6f, 32));
    const std::vector<glm::vec3> cube = test::make_grid_cube(12).soup();
    expect_packets_match(cube, {}, random_rays(cube, 4000, 1.2f, 33));
}

// Overlapping coplanar slivers and degenerate triangles: ties between planes, which the
// visiting order decides.
TEST(PacketTrace, SameHitsOnDegenerateSoups) {
    std::size_t unusable = 0;
    const std::vector<glm::vec3> soup = test::make_degenerate_soup(1400, unusable);
    expect_packets_match(soup, {}, random_rays(soup, 4000, 1.5f, 34));
}

// 1, 7, 8 and 9 triangles: a root of leaves alone, and one with an inner child.
TEST(PacketTrace, SameHitsOnSmallScenes) {
    const std::vector<glm::vec3> all = nine_triangles();
    for (std::size_t n : {1u, 7u, 8u, 9u})
        for (int leaf : {1, 8}) {
            SCOPED_TRACE(testing::Message() << n << " triangles, leaves of up to " << leaf);
            const std::vector<glm::vec3> soup(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(3 * n));
            BvhOptions o;
            o.max_leaf_size = leaf;
            expect_packets_match(soup, o, random_rays(soup, 2000, 3.0f, static_cast<unsigned>(40 + n)));
        }
}

TEST(PacketTrace, SameHitsInsideTheBunny) {
    const std::string bunny = test::assets_dir() + "/meshes_common3d/stanford-bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " not found";
    const std::vector<glm::vec3> mesh = test::load_obj_soup(bunny);
    Rays rays = random_rays(mesh, 6000, 1.0f, 35);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (auto& o : rays.o) o = glm::vec4(0.5f * (lo + hi) + 0.75f * glm::vec3(o) * (hi - lo), 0.0f);
    EXPECT_GT(expect_packets_match(mesh, {}, rays), 1000u);
    EXPECT_GT(expect_packets_match(mesh, {}, camera_rays(mesh, 64)), 1000u);
}

}  // namespace
}  // namespace facet
