// build_bvh: filters the triangle soup, runs the binned SAH builder
// (bvh/sah_builder.cpp), collapses its binary tree into 4-wide nodes, lays the
// triangles out in leaf order and appends the leaves' four-triangle blocks to the nodes.
#include "host/bvh/bvh.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "host/bvh/sah_builder.hpp"
#include "host/error.hpp"

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

// One child reference of a binary node.
struct ChildRef {
    const float* lo;
    const float* hi;
    std::int32_t index, count;
    bool empty() const { return !(lo[0] <= hi[0]); }
    bool inner() const { return count == 0 && !empty(); }
};

ChildRef child(const bvh_detail::BinaryNode& n, int side) {
    return side == 0 ? ChildRef{n.a_min, n.a_max, n.a_index, n.a_count}
                     : ChildRef{n.b_min, n.b_max, n.b_index, n.b_count};
}

void set_slot(FcBvhNode& node, int k, const float* lo, const float* hi, std::int32_t index, std::int32_t count) {
    node.lo_x[k] = lo[0], node.lo_y[k] = lo[1], node.lo_z[k] = lo[2];
    node.hi_x[k] = hi[0], node.hi_y[k] = hi[1], node.hi_z[k] = hi[2];
    node.index[k] = index;
    node.count[k] = count;
}

// Collapses the binary tree: each 4-wide node holds a binary node's children, with
// every inner child replaced by its own two children, so every root-to-leaf path
// halves. Empty slots get the inverted box. Returns the 4-wide depth (nodes on the
// longest root-to-leaf path).
int collapse(const std::vector<bvh_detail::BinaryNode>& bin, std::vector<FcBvhNode>& out) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    const float empty_lo[3] = {inf, inf, inf}, empty_hi[3] = {-inf, -inf, -inf};
    out.clear();
    out.reserve(bin.size() / 2 + 1);
    out.emplace_back();
    struct Item {
        std::int32_t binary, wide, depth;
    };
    std::vector<Item> stack{{0, 0, 1}};
    int max_depth = 0;
    while (!stack.empty()) {
        Item it = stack.back();
        stack.pop_back();
        ChildRef slots[4];
        int k = 0;
        for (int side = 0; side < 2; ++side) {
            ChildRef c = child(bin[static_cast<std::size_t>(it.binary)], side);
            if (c.inner()) {
                const bvh_detail::BinaryNode& g = bin[static_cast<std::size_t>(c.index)];
                slots[k++] = child(g, 0);
                slots[k++] = child(g, 1);
            } else {
                slots[k++] = c;
            }
        }
        for (int s = 0; s < 4; ++s) {
            if (s >= k || slots[s].empty()) {
                set_slot(out[static_cast<std::size_t>(it.wide)], s, empty_lo, empty_hi, 0, 0);
            } else if (slots[s].inner()) {
                const auto j = static_cast<std::int32_t>(out.size());
                out.emplace_back();
                set_slot(out[static_cast<std::size_t>(it.wide)], s, slots[s].lo, slots[s].hi, j, 0);
                stack.push_back({slots[s].index, j, it.depth + 1});
            } else {
                set_slot(out[static_cast<std::size_t>(it.wide)], s, slots[s].lo, slots[s].hi, slots[s].index,
                         slots[s].count);
            }
        }
        max_depth = std::max(max_depth, static_cast<int>(it.depth));
    }
    return max_depth;
}

constexpr std::int64_t kRowsPerNode = sizeof(FcBvhNode) / 16, kRowsPerBlock = sizeof(FcTriBlock) / 16;
static_assert(sizeof(FcBvhNode) % 16 == 0 && sizeof(FcTriBlock) % 16 == 0, "the node buffer is addressed in rows");

// Appends the leaves' triangles to the node buffer as FcTriBlock, in node order, and
// points every leaf slot at its first block (a row index).
std::size_t pack_leaf_blocks(std::vector<FcBvhNode>& nodes, const std::vector<FcTriangle>& tris) {
    const std::size_t tree_nodes = nodes.size();
    std::vector<FcTriBlock> blocks;
    blocks.reserve(tris.size() / 2 + 1);
    const std::int64_t base = static_cast<std::int64_t>(tree_nodes) * kRowsPerNode;
    for (std::size_t n = 0; n < tree_nodes; ++n)
        for (int k = 0; k < 4; ++k) {
            FcBvhNode& node = nodes[n];
            if (node.count[k] <= 0) continue;
            const std::int64_t row = base + static_cast<std::int64_t>(blocks.size()) * kRowsPerBlock;
            if (row + ((node.count[k] + 3) / 4) * kRowsPerBlock > INT32_MAX)
                throw Error("build_bvh: the node buffer outgrows 32-bit row indices (" + std::to_string(tris.size()) +
                            " triangles)");
            const std::int32_t first = node.index[k];
            for (std::int32_t b = 0; b < node.count[k]; b += 4) {
                FcTriBlock& blk = blocks.emplace_back();
                std::memset(&blk, 0, sizeof blk);
                for (int lane = 0; lane < 4; ++lane) {
                    blk.tri[lane] = -1;
                    if (b + lane >= node.count[k]) continue;
                    const FcTriangle& t = tris[static_cast<std::size_t>(first + b + lane)];
                    blk.x0[lane] = t.v0[0], blk.y0[lane] = t.v0[1], blk.z0[lane] = t.v0[2];
                    blk.x1[lane] = t.v1[0], blk.y1[lane] = t.v1[1], blk.z1[lane] = t.v1[2];
                    blk.x2[lane] = t.v2[0], blk.y2[lane] = t.v2[1], blk.z2[lane] = t.v2[2];
                    blk.tri[lane] = first + b + lane;
                }
            }
            node.index[k] = static_cast<std::int32_t>(row);
        }
    const std::size_t bytes = blocks.size() * sizeof(FcTriBlock);
    nodes.resize(tree_nodes + (bytes + sizeof(FcBvhNode) - 1) / sizeof(FcBvhNode));
    if (bytes) std::memcpy(reinterpret_cast<unsigned char*>(nodes.data() + tree_nodes), blocks.data(), bytes);
    return blocks.size();
}

}  // namespace

FcTriBlock leaf_block(const Bvh& bvh, std::int64_t row) {
    const auto rows = static_cast<std::int64_t>(bvh.nodes.size()) * kRowsPerNode;
    if (row < static_cast<std::int64_t>(bvh.stats.nodes) * kRowsPerNode || row + kRowsPerBlock > rows)
        throw Error("leaf_block: row " + std::to_string(row) + " is outside the leaf blocks of the node buffer");
    FcTriBlock b;
    std::memcpy(&b, reinterpret_cast<const unsigned char*>(bvh.nodes.data()) + row * 16, sizeof b);
    return b;
}

Bvh build_bvh(const std::vector<glm::vec3>& vertices, const BvhOptions& options, std::size_t* skipped) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    if (vertices.size() % 3 != 0)
        throw Error("build_bvh: the vertex count " + std::to_string(vertices.size()) + " is not a multiple of 3");
    const std::size_t count = vertices.size() / 3;
    if (count > static_cast<std::size_t>(INT32_MAX))
        throw Error("build_bvh: too many triangles (" + std::to_string(count) + ")");

    Bvh bvh;
    BvhStats& st = bvh.stats;
    {  // the builder's buffers are freed inside the timed span
        // Per-triangle bounds for the builder.
        std::vector<bvh_detail::PrimRef> refs;
        refs.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            const glm::vec3& a = vertices[3 * i];
            const glm::vec3& b = vertices[3 * i + 1];
            const glm::vec3& c = vertices[3 * i + 2];
            if (!usable(a, b, c)) continue;
            bvh_detail::PrimRef& r = refs.emplace_back();
            for (int k = 0; k < 3; ++k) {
                r.lo[k] = std::min(a[k], std::min(b[k], c[k]));  // finite: no NaN cases
                r.hi[k] = std::max(a[k], std::max(b[k], c[k]));
            }
            r.id = static_cast<std::uint32_t>(i);
            r.pad = 0.0f;
        }
        if (skipped) *skipped = count - refs.size();

        bvh_detail::BuildOutput built = bvh_detail::build_sah(refs, options);

        const int depth = collapse(built.nodes, bvh.nodes);
        static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vertices are packed float triples");
        bvh.triangles.reserve(refs.size());  // filled in order, without zeroing first
        for (std::size_t k = 0; k < refs.size(); ++k) {
            const std::uint32_t i = refs[k].id;
            FcTriangle& t = bvh.triangles.emplace_back();
            std::memcpy(t.v0, &vertices[3 * i], sizeof t.v0);
            std::memcpy(t.v1, &vertices[3 * i + 1], sizeof t.v1);
            std::memcpy(t.v2, &vertices[3 * i + 2], sizeof t.v2);
            t.prim = static_cast<fc_int>(i);
            t.pad0 = t.pad1 = 0;
        }

        st.nodes = bvh.nodes.size();
        st.leaf_blocks = pack_leaf_blocks(bvh.nodes, bvh.triangles);
        st.triangles = bvh.triangles.size();
        st.leaves = built.leaves;
        st.max_depth = depth;
        st.binary_nodes = built.nodes.size();
        st.max_leaf_size = built.max_leaf_size;
        st.sah_cost = built.sah_cost;
        st.device_bytes = bvh.nodes.size() * sizeof(FcBvhNode) + bvh.triangles.size() * sizeof(FcTriangle);
    }
    st.build_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return bvh;
}

}  // namespace facet
