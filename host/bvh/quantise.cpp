// quantise_node / dequantise_node: the 80-byte FcBvhNodeQ of kernels/shared/bvh_layout.h.
#include "host/bvh/quantise.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "host/error.hpp"

namespace facet::bvh_detail {
namespace {

constexpr unsigned kMaxExp = 254;  // biased exponents of normal powers of two: 1..254
constexpr unsigned kMaxBlocks = 7, kMaxFirst = 31;
constexpr std::int32_t kRowsPerBlock = sizeof(FcTriBlock) / 16;

float scale_of(unsigned biased_exp) { return std::bit_cast<float>(static_cast<std::uint32_t>(biased_exp) << 23); }

bool slot_empty(const FcBvhNode8& n, int k) { return !(n.lo_x[k] <= n.hi_x[k]); }

// Byte k of the 8 bytes at `offset` of a node (planes and meta), in memory order: the
// kernels read them as uchar8.
constexpr std::size_t kMetaOffset = offsetof(FcBvhNodeQ, meta), kPlaneOffset = offsetof(FcBvhNodeQ, q_lo_x);
static_assert(offsetof(FcBvhNodeQ, q_hi_z) == kPlaneOffset + 40, "six consecutive planes of 8 bytes");

void set_byte(FcBvhNodeQ& n, std::size_t offset, int k, unsigned value) {
    reinterpret_cast<unsigned char*>(&n)[offset + static_cast<std::size_t>(k)] = static_cast<unsigned char>(value);
}

unsigned get_byte(const FcBvhNodeQ& n, std::size_t offset, int k) {
    return reinterpret_cast<const unsigned char*>(&n)[offset + static_cast<std::size_t>(k)];
}

// Plane p (0-2: lo x y z, 3-5: hi x y z).
std::size_t plane(int p) { return kPlaneOffset + 8 * static_cast<std::size_t>(p); }

// The smallest exponent whose grid of 255 steps from `lo` reaches `hi`.
unsigned exponent_for(float lo, float hi) {
    const double step = (static_cast<double>(hi) - static_cast<double>(lo)) / 255.0;
    int e = 1;
    if (step > 0.0) e = std::clamp(static_cast<int>(std::ceil(std::log2(step))) + 127, 1, static_cast<int>(kMaxExp));
    unsigned u = static_cast<unsigned>(e);
    while (quantised_plane(lo, u, 255) < hi && u < kMaxExp) ++u;
    if (!(quantised_plane(lo, u, 255) >= hi))
        throw Error("quantise_node: a node box from " + std::to_string(lo) + " to " + std::to_string(hi) +
                    " cannot be quantised");
    return u;
}

// The largest q whose plane is at or below `lo` (q = 0 is the origin, at or below every child).
unsigned quantise_down(float origin, unsigned e, float lo) {
    const double s = static_cast<double>(scale_of(e));
    unsigned q = static_cast<unsigned>(
        std::clamp(std::floor((static_cast<double>(lo) - static_cast<double>(origin)) / s), 0.0, 255.0));
    while (q > 0 && quantised_plane(origin, e, q) > lo) --q;
    while (q < 255 && quantised_plane(origin, e, q + 1) <= lo) ++q;
    return q;
}

// The smallest q whose plane is at or above `hi` (q = 255 reaches the node's top, exponent_for).
unsigned quantise_up(float origin, unsigned e, float hi) {
    const double s = static_cast<double>(scale_of(e));
    unsigned q = static_cast<unsigned>(
        std::clamp(std::ceil((static_cast<double>(hi) - static_cast<double>(origin)) / s), 0.0, 255.0));
    while (q < 255 && quantised_plane(origin, e, q) < hi) ++q;
    while (q > 0 && quantised_plane(origin, e, q - 1) >= hi) --q;
    return q;
}

}  // namespace

float quantised_plane(float origin, unsigned biased_exp, unsigned q) {
    // Two steps, not contracted by hand: q * scale is exact, so any contraction agrees.
    const float offset = static_cast<float>(q) * scale_of(biased_exp);
    return origin + offset;
}

FcBvhNodeQ quantise_node(const FcBvhNode8& n) {
    FcBvhNodeQ q;
    std::memset(&q, 0, sizeof q);
    // The node's box: the union of its slots.
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-lo[0], -lo[0], -lo[0]};
    const float* slo[3] = {n.lo_x, n.lo_y, n.lo_z};
    const float* shi[3] = {n.hi_x, n.hi_y, n.hi_z};
    bool any = false;
    for (int k = 0; k < 8; ++k) {
        if (slot_empty(n, k)) continue;
        any = true;
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], slo[a][k]), hi[a] = std::max(hi[a], shi[a][k]);
    }
    unsigned exps[3] = {127, 127, 127};
    for (int a = 0; a < 3; ++a) {
        q.origin[a] = any ? lo[a] : 0.0f;
        if (any) exps[a] = exponent_for(lo[a], hi[a]);
    }

    // Child references by rank: the first inner child's node and the first leaf's row.
    unsigned inner_bits = 0;
    std::int32_t child_base = -1, leaf_base = -1, rank = 0;
    for (int k = 0; k < 8; ++k) {
        if (slot_empty(n, k)) {
            for (int a = 0; a < 3; ++a) set_byte(q, plane(a), k, 255), set_byte(q, plane(3 + a), k, 0);
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            set_byte(q, plane(a), k, quantise_down(q.origin[a], exps[a], slo[a][k]));
            set_byte(q, plane(3 + a), k, quantise_up(q.origin[a], exps[a], shi[a][k]));
        }
        const std::string slot = "quantise_node: slot " + std::to_string(k);
        if (n.count[k] == 0) {
            if (child_base < 0) child_base = n.index[k];
            if (n.index[k] != child_base + rank)
                throw Error(slot + ": inner child " + std::to_string(n.index[k]) + " is not the node's next child (" +
                            std::to_string(child_base + rank) + ")");
            ++rank;
            inner_bits |= 1u << k;
            continue;
        }
        if (leaf_base < 0) leaf_base = n.index[k];
        const std::int32_t offset = n.index[k] - leaf_base;
        const auto blocks = static_cast<unsigned>((n.count[k] + 3) / 4);
        if (offset < 0 || offset % kRowsPerBlock != 0 || offset / kRowsPerBlock > static_cast<std::int32_t>(kMaxFirst))
            throw Error(slot + ": its leaf starts " + std::to_string(offset) +
                        " rows after the node's first leaf (at most " + std::to_string(kMaxFirst) +
                        " blocks, in order)");
        if (blocks > kMaxBlocks)
            throw Error(slot + ": a leaf of " + std::to_string(n.count[k]) + " triangles has more than " +
                        std::to_string(kMaxBlocks) + " blocks");
        set_byte(q, kMetaOffset, k, blocks | static_cast<unsigned>(offset / kRowsPerBlock) << 3);
    }
    q.exps = exps[0] | exps[1] << 8 | exps[2] << 16 | inner_bits << 24;
    q.child_base = std::max(child_base, 0);
    q.leaf_base = std::max(leaf_base, 0);
    return q;
}

FcBvhNode8 dequantise_node(const FcBvhNodeQ& q) {
    FcBvhNode8 n;
    float* lo[3] = {n.lo_x, n.lo_y, n.lo_z};
    float* hi[3] = {n.hi_x, n.hi_y, n.hi_z};
    const unsigned inner_bits = q.exps >> 24;
    constexpr float inf = std::numeric_limits<float>::infinity();
    std::int32_t rank = 0;
    for (int k = 0; k < 8; ++k) {
        const bool inner = (inner_bits >> k) & 1u;
        const unsigned meta = get_byte(q, kMetaOffset, k);
        for (int a = 0; a < 3; ++a) {
            const unsigned e = (q.exps >> (8 * a)) & 0xffu;
            lo[a][k] = inner || meta ? quantised_plane(q.origin[a], e, get_byte(q, plane(a), k)) : inf;
            hi[a][k] = inner || meta ? quantised_plane(q.origin[a], e, get_byte(q, plane(3 + a), k)) : -inf;
        }
        if (inner) {
            n.index[k] = q.child_base + rank++;
            n.count[k] = 0;
        } else if (meta) {
            n.index[k] = q.leaf_base + kRowsPerBlock * static_cast<std::int32_t>(meta >> 3);
            n.count[k] = 4 * static_cast<std::int32_t>(meta & 7u);
        } else {
            n.index[k] = n.count[k] = 0;
        }
    }
    return n;
}

}  // namespace facet::bvh_detail
