// build_bvh: filters the triangle soup, runs the binned SAH builder
// (bvh/sah_builder.cpp), collapses its binary tree into 4- or 8-wide nodes, lays the
// triangles out in leaf order, appends the leaves' four-triangle blocks to the nodes and,
// for quantised 8-wide trees, encodes the nodes (bvh/quantise.cpp).
#include "host/bvh/bvh.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <type_traits>

#include "host/bvh/bvh_width.hpp"
#include "host/bvh/quantise.hpp"
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

template <typename Node>
void set_slot(Node& node, int k, const float* lo, const float* hi, std::int32_t index, std::int32_t count) {
    node.lo_x[k] = lo[0], node.lo_y[k] = lo[1], node.lo_z[k] = lo[2];
    node.hi_x[k] = hi[0], node.hi_y[k] = hi[1], node.hi_z[k] = hi[2];
    node.index[k] = index;
    node.count[k] = count;
}

template <typename Node>
constexpr int kWidth = static_cast<int>(sizeof(Node::index) / sizeof(Node::index[0]));

float half_area(const ChildRef& c) {
    const float dx = c.hi[0] - c.lo[0], dy = c.hi[1] - c.lo[1], dz = c.hi[2] - c.lo[2];
    return dx * dy + dy * dz + dz * dx;
}

// The children of one wide node, from binary node `binary`. 4-wide: its children,
// every inner one replaced by its own two children (every path halves). 8-wide: the
// same, then, while a slot is free, the inner child of largest surface area opened
// (Embree's BVH8 collapse); or, with `by_level`, every inner child of the 4-wide set
// opened once more (every path a third as long).
template <int W>
int gather_children(const std::vector<bvh_detail::BinaryNode>& bin, std::int32_t binary, bool by_level,
                    ChildRef (&slots)[W]) {
    const bvh_detail::BinaryNode& b = bin[static_cast<std::size_t>(binary)];
    ChildRef cur[8] = {child(b, 0), child(b, 1)};
    int k = 2;
    const int levels = W == 4 || by_level ? (W == 4 ? 1 : 2) : 0;
    for (int l = 0; l < levels; ++l) {  // open every inner child: k at most doubles
        ChildRef next[8];
        int m = 0;
        for (int s = 0; s < k; ++s)
            if (cur[s].inner()) {
                const bvh_detail::BinaryNode& g = bin[static_cast<std::size_t>(cur[s].index)];
                next[m++] = child(g, 0);
                next[m++] = child(g, 1);
            } else {
                next[m++] = cur[s];
            }
        std::copy(next, next + m, cur);
        k = m;
    }
    if (W == 8 && !by_level)
        while (k < 8) {  // open the largest inner child in place
            int best = -1;
            float best_area = -1.0f;
            for (int s = 0; s < k; ++s)
                if (cur[s].inner() && half_area(cur[s]) > best_area) best = s, best_area = half_area(cur[s]);
            if (best < 0) break;
            const bvh_detail::BinaryNode& g = bin[static_cast<std::size_t>(cur[best].index)];
            cur[best] = child(g, 0);
            cur[k++] = child(g, 1);
        }
    std::copy(cur, cur + k, slots);
    return k;
}

struct CollapseOut {
    int depth = 0;       // wide nodes on the longest root-to-leaf path
    int stack_need = 0;  // most stack entries a root-to-leaf path pushes (inner children less one a node)
};

// Collapses the binary tree into W-wide nodes (gather_children). Empty slots get the
// inverted box.
template <typename Node>
CollapseOut collapse(const std::vector<bvh_detail::BinaryNode>& bin, bool by_level, std::vector<Node>& out) {
    constexpr int W = kWidth<Node>;
    constexpr float inf = std::numeric_limits<float>::infinity();
    const float empty_lo[3] = {inf, inf, inf}, empty_hi[3] = {-inf, -inf, -inf};
    out.clear();
    out.reserve(bin.size() / (W - 1) + 1);
    out.emplace_back();
    struct Item {
        std::int32_t binary, wide, depth, pushes;
    };
    std::vector<Item> stack{{0, 0, 1, 0}};
    CollapseOut res;
    while (!stack.empty()) {
        Item it = stack.back();
        stack.pop_back();
        ChildRef slots[W];
        const int k = gather_children<W>(bin, it.binary, by_level, slots);
        int inner = 0;
        for (int s = 0; s < k; ++s) inner += slots[s].inner() ? 1 : 0;
        const int pushes = it.pushes + std::max(0, inner - 1);
        for (int s = 0; s < W; ++s) {
            if (s >= k || slots[s].empty()) {
                set_slot(out[static_cast<std::size_t>(it.wide)], s, empty_lo, empty_hi, 0, 0);
            } else if (slots[s].inner()) {
                const auto j = static_cast<std::int32_t>(out.size());
                out.emplace_back();
                set_slot(out[static_cast<std::size_t>(it.wide)], s, slots[s].lo, slots[s].hi, j, 0);
                stack.push_back({slots[s].index, j, it.depth + 1, pushes});
            } else {
                set_slot(out[static_cast<std::size_t>(it.wide)], s, slots[s].lo, slots[s].hi, slots[s].index,
                         slots[s].count);
            }
        }
        res.depth = std::max(res.depth, static_cast<int>(it.depth));
        res.stack_need = std::max(res.stack_need, pushes);
    }
    return res;
}

// collapse() within the traversal's stack (FC_BVH_STACK_SIZE or FC_BVH8_STACK_SIZE entries):
// an 8-wide tree whose paths would push more is collapsed by levels instead; a tree still too
// deep is an Error naming `who`.
template <typename Node>
CollapseOut collapse_within_stack(const std::vector<bvh_detail::BinaryNode>& bin, std::vector<Node>& out,
                                  const char* who) {
    constexpr int W = kWidth<Node>;
    constexpr int stack = W == 8 ? FC_BVH8_STACK_SIZE : FC_BVH_STACK_SIZE;
    CollapseOut wide = collapse(bin, false, out);
    if (W == 8 && wide.stack_need > stack) wide = collapse(bin, true, out);
    if (wide.stack_need > stack)
        throw Error(std::string(who) + ": the " + std::to_string(W) + "-wide tree needs " +
                    std::to_string(wide.stack_need) + " stack entries, more than " +
                    (W == 8 ? "FC_BVH8_STACK_SIZE" : "FC_BVH_STACK_SIZE"));
    return wide;
}

constexpr std::int64_t kRowsPerBlock = sizeof(FcTriBlock) / 16;
static_assert(sizeof(FcBvhNode) % 16 == 0 && sizeof(FcBvhNode8) % sizeof(FcBvhNode) == 0 &&
                  sizeof(FcBvhNodeQ) % 16 == 0 && sizeof(FcTriBlock) % 16 == 0,
              "the node buffer is addressed in rows");

// Bytes of one node of a tree as stored.
std::size_t node_bytes(int width, bool quantised) {
    return width == 4 ? sizeof(FcBvhNode) : quantised ? sizeof(FcBvhNodeQ) : sizeof(FcBvhNode8);
}

// Appends the leaves' triangles as FcTriBlock, in node order, after `stored_bytes` of nodes
// (the nodes as they will be stored), and points every leaf slot at its first block (a
// row index). Returns the blocks.
template <typename Node>
std::vector<FcTriBlock> pack_leaf_blocks(std::vector<Node>& nodes, const std::vector<FcTriangle>& tris,
                                         std::size_t stored_bytes) {
    constexpr int W = kWidth<Node>;
    std::vector<FcTriBlock> blocks;
    blocks.reserve(tris.size() / 2 + 1);
    const auto base = static_cast<std::int64_t>(stored_bytes / 16);
    for (Node& node : nodes)
        for (int k = 0; k < W; ++k) {
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
    return blocks;
}

// The node buffer (128-byte units): `bytes` of nodes, then the blocks.
void fill_buffer(const void* nodes, std::size_t bytes, const std::vector<FcTriBlock>& blocks,
                 std::vector<FcBvhNode>& buffer) {
    const std::size_t block_bytes = blocks.size() * sizeof(FcTriBlock);
    buffer.resize((bytes + block_bytes + sizeof(FcBvhNode) - 1) / sizeof(FcBvhNode));
    auto* out = reinterpret_cast<unsigned char*>(buffer.data());
    std::memcpy(out, nodes, bytes);
    if (block_bytes) std::memcpy(out + bytes, blocks.data(), block_bytes);
    const std::size_t tail = buffer.size() * sizeof(FcBvhNode) - bytes - block_bytes;
    if (tail) std::memset(out + bytes + block_bytes, 0, tail);
}

// Packs a tree of float nodes, or of their quantised encodings, with its leaf blocks.
template <typename Node>
std::size_t pack_node_buffer(std::vector<Node>& nodes, bool quantised, const std::vector<FcTriangle>& tris,
                             std::vector<FcBvhNode>& buffer) {
    const std::size_t bytes = nodes.size() * (quantised ? sizeof(FcBvhNodeQ) : sizeof(Node));
    const std::vector<FcTriBlock> blocks = pack_leaf_blocks(nodes, tris, bytes);
    if constexpr (std::is_same_v<Node, FcBvhNode8>) {
        if (quantised) {
            std::vector<FcBvhNodeQ> q;
            q.reserve(nodes.size());
            for (const FcBvhNode8& n : nodes) q.push_back(bvh_detail::quantise_node(n));
            fill_buffer(q.data(), bytes, blocks, buffer);
            return blocks.size();
        }
    }
    fill_buffer(nodes.data(), bytes, blocks, buffer);
    return blocks.size();
}

}  // namespace

std::vector<FcBvhNode> bvh_detail::collapse_float_tree(const std::vector<BinaryNode>& bin, int width) {
    std::vector<FcBvhNode> units;
    if (width == 8) {
        std::vector<FcBvhNode8> nodes8;
        collapse_within_stack(bin, nodes8, "collapse_float_tree");
        units.resize(nodes8.size() * (sizeof(FcBvhNode8) / sizeof(FcBvhNode)));
        std::memcpy(units.data(), nodes8.data(), nodes8.size() * sizeof(FcBvhNode8));
    } else if (width == 4) {
        collapse_within_stack(bin, units, "collapse_float_tree");
    } else {
        throw Error("collapse_float_tree: width " + std::to_string(width) + " is not 4 or 8");
    }
    return units;
}

int resolve_width(int width) {
    if (width == 0) {
        const char* env = std::getenv("FACET_BVH_WIDTH");
        if (!env || !*env) return 4;
        const std::string v(env);
        if (v == "4" || v == "8") return v == "8" ? 8 : 4;
        throw Error("FACET_BVH_WIDTH is \"" + v + "\": it must be 4 or 8");
    }
    if (width != 4 && width != 8)
        throw Error("build_bvh: BvhOptions::width is " + std::to_string(width) + ": it must be 0 (auto), 4 or 8");
    return width;
}

bool resolve_quantised(const BvhOptions& options, std::size_t triangles) {
    // The meta byte holds up to 7 blocks a leaf and a leaf's first block up to 31 after the
    // node's first: eight leaves of up to 16 triangles (4 blocks) always fit.
    const bool fits = options.max_leaf_size <= 16;
    int q = options.quantised;
    const char* env = std::getenv("FACET_BVH_QUANTISED");
    if (q < 0 && env && *env) {
        const std::string v(env);
        if (v != "0" && v != "1") throw Error("FACET_BVH_QUANTISED is \"" + v + "\": it must be 0 or 1");
        q = v == "1" ? 1 : 0;
    }
    if (q > 1) throw Error("build_bvh: BvhOptions::quantised is " + std::to_string(q) + ": it must be -1, 0 or 1");
    if (q == 1 && !fits)
        throw Error("build_bvh: quantised nodes hold leaves of up to 16 triangles, max_leaf_size is " +
                    std::to_string(options.max_leaf_size) + " (FACET_BVH_QUANTISED=0 keeps float boxes)");
    const std::size_t counted = options.layout_triangles ? options.layout_triangles : triangles;
    return q < 0 ? fits && counted > kQuantiseAboveTriangles : q == 1;
}

int bvh_width_for(bool gpu, unsigned native_float_vector_width) {
    const char* env = std::getenv("FACET_BVH_WIDTH");
    if (env && *env) return resolve_width(0);
    return !gpu && native_float_vector_width >= 8 ? 8 : 4;
}

FcBvhNode8 wide_node8(const Bvh& bvh, std::size_t i) {
    if (bvh.stats.width != 8 || i >= bvh.stats.nodes)
        throw Error("wide_node8: node " + std::to_string(i) + " is not a node of an 8-wide tree of " +
                    std::to_string(bvh.stats.nodes) + " (width " + std::to_string(bvh.stats.width) + ")");
    FcBvhNode8 n;
    if (!bvh.stats.quantised) {
        std::memcpy(&n, reinterpret_cast<const unsigned char*>(bvh.nodes.data()) + i * sizeof n, sizeof n);
        return n;
    }
    n = bvh_detail::dequantise_node(wide_node_q(bvh, i));
    for (int k = 0; k < 8; ++k) {  // four triangles a block, less the last block's unused lanes
        if (n.count[k] <= 0) continue;
        const FcTriBlock last = leaf_block(bvh, n.index[k] + (n.count[k] / 4 - 1) * kRowsPerBlock);
        for (int lane = 0; lane < 4; ++lane) n.count[k] -= last.tri[lane] < 0 ? 1 : 0;
    }
    return n;
}

FcBvhNodeQ wide_node_q(const Bvh& bvh, std::size_t i) {
    if (!bvh.stats.quantised || i >= bvh.stats.nodes)
        throw Error("wide_node_q: node " + std::to_string(i) + " is not a node of a quantised tree of " +
                    std::to_string(bvh.stats.nodes) + (bvh.stats.quantised ? "" : " (the tree has float boxes)"));
    FcBvhNodeQ n;
    std::memcpy(&n, reinterpret_cast<const unsigned char*>(bvh.nodes.data()) + i * sizeof n, sizeof n);
    return n;
}

const FcBvhNode& wide_node4(const Bvh& bvh, std::size_t i) {
    if (bvh.stats.width != 4 || i >= bvh.stats.nodes)
        throw Error("wide_node4: node " + std::to_string(i) + " is not a node of a 4-wide tree of " +
                    std::to_string(bvh.stats.nodes) + " (width " + std::to_string(bvh.stats.width) + ")");
    return bvh.nodes[i];
}

std::string bvh_prelude(const Bvh& bvh) {
    return "#define FC_BVH_WIDTH " + std::to_string(bvh.stats.width) +
           (bvh.stats.quantised ? "\n#define FC_BVH_QUANTISED 1" : "");
}

FcTriBlock leaf_block(const Bvh& bvh, std::int64_t row) {
    const auto rows = static_cast<std::int64_t>(bvh.nodes.size() * sizeof(FcBvhNode) / 16);
    const auto first =
        static_cast<std::int64_t>(bvh.stats.nodes * node_bytes(bvh.stats.width, bvh.stats.quantised) / 16);
    if (row < first || row + kRowsPerBlock > rows)
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

        const int width = resolve_width(options.width);
        if (width == 4 && options.quantised == 1)
            throw Error("build_bvh: BvhOptions::quantised is 1 for a 4-wide tree: quantised nodes are 8-wide");
        const bool quantised = width == 8 && resolve_quantised(options, refs.size());
        std::vector<FcBvhNode> nodes4;
        std::vector<FcBvhNode8> nodes8;
        const CollapseOut wide = width == 8 ? collapse_within_stack(built.nodes, nodes8, "build_bvh")
                                            : collapse_within_stack(built.nodes, nodes4, "build_bvh");
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

        st.width = width;
        st.quantised = quantised ? 1 : 0;
        st.nodes = width == 8 ? nodes8.size() : nodes4.size();
        st.leaf_blocks = width == 8 ? pack_node_buffer(nodes8, quantised, bvh.triangles, bvh.nodes)
                                    : pack_node_buffer(nodes4, false, bvh.triangles, bvh.nodes);
        st.triangles = bvh.triangles.size();
        st.leaves = built.leaves;
        st.max_depth = wide.depth;
        st.stack_need = wide.stack_need;
        st.binary_nodes = built.nodes.size();
        st.max_leaf_size = built.max_leaf_size;
        st.sah_cost = built.sah_cost;
        st.device_bytes = bvh.nodes.size() * sizeof(FcBvhNode) + bvh.triangles.size() * sizeof(FcTriangle);
    }
    st.build_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return bvh;
}

}  // namespace facet
