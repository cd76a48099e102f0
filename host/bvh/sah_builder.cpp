#include "host/bvh/sah_builder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>

#include "host/error.hpp"

namespace facet::bvh_detail {
namespace {

// Four-float SIMD values (GCC/Clang vector extensions); lane 3 is kept at zero.
typedef float f4 __attribute__((vector_size(16)));
typedef std::int32_t i4 __attribute__((vector_size(16)));

constexpr float kInf = std::numeric_limits<float>::infinity();

inline f4 vmin(f4 a, f4 b) { return a < b ? a : b; }
inline f4 vmax(f4 a, f4 b) { return a > b ? a : b; }
// Lanes 0..2 of p and zero in lane 3 (p[3] may be an integer): one 16-byte load and
// an AND, so lane 3 never holds a denormal that an add would have to assist.
inline f4 load3(const float* p) {
    i4 v;
    std::memcpy(&v, p, sizeof v);
    const i4 keep = {-1, -1, -1, 0};
    return reinterpret_cast<f4>(v & keep);
}
inline f4 lo_of(const PrimRef& r) { return load3(r.lo); }
inline f4 hi_of(const PrimRef& r) { return load3(r.hi); }
// Twice the centroid: every pass bins and partitions on lo + hi (bin positions scale
// the same way, so they equal those of the centroid bit for bit), and the partition
// agrees with the binning exactly.
inline f4 centroid2(f4 lo, f4 hi) { return lo + hi; }
inline f4 centroid(const PrimRef& r) { return centroid2(lo_of(r), hi_of(r)); }

struct Box {
    f4 lo = {kInf, kInf, kInf, 0.0f};
    f4 hi = {-kInf, -kInf, -kInf, 0.0f};
    void grow(f4 l, f4 h) {
        lo = vmin(lo, l);
        hi = vmax(hi, h);
    }
    void grow(const Box& b) { grow(b.lo, b.hi); }
    // Half the surface area; 0 for an empty box (its inverted extents clamp to 0),
    // without a branch.
    float half_area() const {
        const f4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
        f4 d = vmax(hi - lo, zero);
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }
};

// Half the surface areas of three boxes, in lanes 0..2 (the same operations, in the
// same order, as Box::half_area, so the values agree bit for bit).
inline f4 half_areas(const Box& b0, const Box& b1, const Box& b2) {
    const f4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
    const f4 d0 = vmax(b0.hi - b0.lo, zero), d1 = vmax(b1.hi - b1.lo, zero), d2 = vmax(b2.hi - b2.lo, zero);
    const f4 t0 = __builtin_shuffle(d0, d1, i4{0, 4, 1, 5});  // x0 x1 y0 y1
    const f4 t1 = __builtin_shuffle(d0, d1, i4{2, 6, 3, 7});  // z0 z1 . .
    const f4 dx = __builtin_shuffle(t0, d2, i4{0, 1, 4, 4});
    const f4 dy = __builtin_shuffle(t0, d2, i4{2, 3, 5, 5});
    const f4 dz = __builtin_shuffle(t1, d2, i4{0, 1, 6, 6});
    return dx * dy + dy * dz + dz * dx;
}

// The cheapest of the three per-axis sweeps (lanes 0..2 of best, their split in best_at),
// strictly: the first axis on ties, as one sweep over the axes in turn would. Returns the
// axis, -1 when every cost is infinite or NaN.
inline int cheapest_axis(f4 best, i4 best_at, float& cost, int& at) {
    int axis = -1;
    cost = kInf;
    for (int a = 0; a < 3; ++a)
        if (best[a] < cost) {
            cost = best[a];
            axis = a;
            at = best_at[a];
        }
    return axis;
}

// Ranges up to this size get the exact SAH sweep instead of binning.
constexpr int kExactMax = 16;
// Ranges from this size on bin into two bin sets.
constexpr std::uint32_t kTwoSetsMin = 128;

int ceil_log2(std::uint32_t n) { return n <= 1 ? 0 : 32 - std::countl_zero(n - 1); }

// log2 of BvhOptions::block_size.
int block_shift(int block_size) {
    if (block_size != 1 && block_size != 2 && block_size != 4 && block_size != 8)
        throw Error("build_bvh: block_size " + std::to_string(block_size) + " is not 1, 2, 4 or 8");
    return std::countr_zero(static_cast<unsigned>(block_size));
}

void set_child(BinaryNode& node, int side, const Box& box) {
    float* lo = side == 0 ? node.a_min : node.b_min;
    float* hi = side == 0 ? node.a_max : node.b_max;
    for (int a = 0; a < 3; ++a) {
        lo[a] = box.lo[a];
        hi[a] = box.hi[a];
    }
}

void set_ref(BinaryNode& node, int side, std::uint32_t index, std::uint32_t count) {
    (side == 0 ? node.a_index : node.b_index) = static_cast<std::int32_t>(index);
    (side == 0 ? node.a_count : node.b_count) = static_cast<std::int32_t>(count);
}

// A range of references still to be built, and the child slot that refers to it.
struct Task {
    std::uint32_t begin, end;
    int depth;   // nodes above this range
    int parent;  // node whose child slot `side` refers to this range; -1 for the root
    int side;
    Box box;   // bounds of the primitives
    Box cbox;  // bounds of their centroids (twice the centroids, see centroid2)
    int buf;   // where its references are: 0 the caller's array, 1 the scratch one
};

struct Split {
    std::uint32_t mid;
    bool moved;  // the children's references went to the other buffer
    Box lbox, rbox, lcbox, rcbox;
};

class Builder {
public:
    Builder(std::vector<PrimRef>& refs, const BvhOptions& opt)
        : refs_(refs), opt_(opt), nb_(std::clamp(opt.bins, 2, 256)),
          max_leaf_(static_cast<std::uint32_t>(std::max(opt.max_leaf_size, 1))),
          exact_max_(static_cast<std::uint32_t>(std::clamp(opt.exact_max, 0, kExactMax))),
          block_shift_(block_shift(opt.block_size)), bins_(6 * nb_), counts_(6 * nb_), right_area_(nb_),
          right_count_(nb_), scratch_(new PrimRef[refs.size()]) {}

    BuildOutput run();

private:
    bool decide(const Task& t, Split& s);
    bool sah_split(const Task& t, Split& s, float& cost);
    bool exact_split(const Task& t, Split& s, float& cost);
    void median_split(const Task& t, Split& s);
    void bounds(const PrimRef* p, std::uint32_t begin, std::uint32_t end, Box& box, Box& cbox) const;

    std::vector<PrimRef>& refs_;
    const BvhOptions& opt_;
    int nb_;
    std::uint32_t max_leaf_;
    std::uint32_t exact_max_;
    int block_shift_;  // log2 of BvhOptions::block_size
    // Intersection tests of a leaf of n references: n in blocks, rounded up.
    std::uint32_t blocks(std::uint32_t n) const { return (n + (1u << block_shift_) - 1u) >> block_shift_; }
    std::vector<Box> bins_;  // [axis * nb_ + bin]
    std::vector<std::uint32_t> counts_;
    std::vector<f4> right_area_;  // per bin boundary, lane a = axis a
    std::vector<i4> right_count_;
    std::unique_ptr<PrimRef[]> scratch_;  // the partition's other buffer (not zeroed)
    PrimRef* buf(int b) const { return b ? scratch_.get() : refs_.data(); }
};

void Builder::bounds(const PrimRef* p, std::uint32_t begin, std::uint32_t end, Box& box, Box& cbox) const {
    box = cbox = Box{};
    for (std::uint32_t i = begin; i < end; ++i) {
        box.grow(lo_of(p[i]), hi_of(p[i]));
        f4 c = centroid(p[i]);
        cbox.grow(c, c);
    }
}

// Bins the centroids along all three axes, sweeps the bin boundaries for the lowest
// sum(area * count) and partitions the range at the best one into the other buffer
// (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies").
// One pass bins all three axes; even and odd references go to two separate bin sets
// (merged before the sweep) so that runs of references landing in the same bin do
// not chain their read-modify-writes. The children's boxes are the unions of their
// bins; the partition pass only gathers their centroid bounds.
bool Builder::sah_split(const Task& t, Split& s, float& best_cost) {
    const int nb = nb_;
    const float last = static_cast<float>(nb - 1);
    const f4 origin = t.cbox.lo;  // cbox holds twice the centroids, as centroid2
    f4 scale = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int a = 0; a < 3; ++a) {
        float extent = t.cbox.hi[a] - t.cbox.lo[a];
        if (extent > 0.0f && std::isfinite(extent)) scale[a] = static_cast<float>(nb) * (1.0f - 1e-6f) / extent;
    }
    const f4 zero = {0.0f, 0.0f, 0.0f, 0.0f}, top = {last, last, last, 0.0f};
    auto bin_of = [&](f4 c) {  // NaN (0 * inf) lands in bin 0
        f4 f = vmin(vmax((c - origin) * scale, zero), top);
        return __builtin_convertvector(f, i4);
    };

    Box* __restrict b0 = bins_.data();
    Box* __restrict b1 = b0 + 3 * nb;
    std::uint32_t* __restrict n0 = counts_.data();
    std::uint32_t* __restrict n1 = n0 + 3 * nb;
    // Small ranges use one bin set (clearing and merging the second costs more there).
    const bool two_sets = t.end - t.begin >= kTwoSetsMin;
    std::fill(bins_.begin(), bins_.begin() + (two_sets ? 6 : 3) * nb, Box{});
    std::fill(counts_.begin(), counts_.begin() + (two_sets ? 6 : 3) * nb, 0u);
    const PrimRef* __restrict refs = buf(t.buf);
    std::uint32_t i = t.begin;
    if (two_sets)
        for (; i + 1 < t.end; i += 2) {
            f4 lo0 = lo_of(refs[i]), hi0 = hi_of(refs[i]);
            f4 lo1 = lo_of(refs[i + 1]), hi1 = hi_of(refs[i + 1]);
            i4 x0 = bin_of(centroid2(lo0, hi0)) + i4{0, nb, 2 * nb, 0};
            i4 x1 = bin_of(centroid2(lo1, hi1)) + i4{0, nb, 2 * nb, 0};
            for (int a = 0; a < 3; ++a) {
                Box& p = b0[x0[a]];
                p.lo = vmin(p.lo, lo0);
                p.hi = vmax(p.hi, hi0);
                ++n0[x0[a]];
                Box& q = b1[x1[a]];
                q.lo = vmin(q.lo, lo1);
                q.hi = vmax(q.hi, hi1);
                ++n1[x1[a]];
            }
        }
    for (; i < t.end; ++i) {
        f4 lo0 = lo_of(refs[i]), hi0 = hi_of(refs[i]);
        i4 x0 = bin_of(centroid2(lo0, hi0)) + i4{0, nb, 2 * nb, 0};
        for (int a = 0; a < 3; ++a) {
            b0[x0[a]].grow(lo0, hi0);
            ++n0[x0[a]];
        }
    }
    if (two_sets)
        for (int k = 0; k < 3 * nb; ++k) {
            b0[k].grow(b1[k]);
            n0[k] += n1[k];
        }

    // The sweeps of the three axes run side by side (lane a is axis a), without
    // branches: the best split per axis is tracked lane by lane.
    const Box* x = b0;
    const Box* y = b0 + nb;
    const Box* z = b0 + 2 * nb;
    auto counts_at = [&](int k) {
        return i4{static_cast<std::int32_t>(n0[k]), static_cast<std::int32_t>(n0[nb + k]),
                  static_cast<std::int32_t>(n0[2 * nb + k]), 0};
    };
    {
        Box r0, r1, r2;
        i4 count = {0, 0, 0, 0};
        for (int k = nb - 1; k > 0; --k) {
            r0.grow(x[k]);
            r1.grow(y[k]);
            r2.grow(z[k]);
            count += counts_at(k);
            right_area_[k] = half_areas(r0, r1, r2);
            right_count_[k] = count;
        }
    }
    const f4 zero4 = {0.0f, 0.0f, 0.0f, 0.0f};
    const i4 axis_ok = (scale != zero4) & i4{-1, -1, -1, 0};  // an axis with extent
    f4 best = {kInf, kInf, kInf, kInf};
    i4 best_at = {0, 0, 0, 0};
    {
        Box l0, l1, l2;
        i4 count = {0, 0, 0, 0};
        const i4 none = {0, 0, 0, 0};
        for (int k = 1; k < nb; ++k) {
            l0.grow(x[k - 1]);
            l1.grow(y[k - 1]);
            l2.grow(z[k - 1]);
            count += counts_at(k - 1);
            const i4 rcount = right_count_[k];
            const i4 round = {(1 << block_shift_) - 1, (1 << block_shift_) - 1, (1 << block_shift_) - 1, 0};
            const i4 lblocks = (count + round) >> block_shift_, rblocks = (rcount + round) >> block_shift_;
            const f4 cost = half_areas(l0, l1, l2) * __builtin_convertvector(lblocks, f4) +
                            right_area_[k] * __builtin_convertvector(rblocks, f4);
            const i4 better = axis_ok & (count != none) & (rcount != none) & (cost < best);
            best = better ? cost : best;
            best_at = better ? i4{k, k, k, k} : best_at;
        }
    }
    int best_bin = 0;
    const int best_axis = cheapest_axis(best, best_at, best_cost, best_bin);
    if (best_axis < 0) return false;
    s.lbox = s.rbox = Box{};
    std::uint32_t nl_bins = 0;
    for (int k = 0; k < nb; ++k) {
        const Box& bx = b0[best_axis * nb + k];
        (k < best_bin ? s.lbox : s.rbox).grow(bx);
        if (k < best_bin) nl_bins += n0[best_axis * nb + k];
    }

    // Partition with the same mapping (bin < best_bin <=> position < best_bin; NaN
    // positions were binned to 0, so they go left too) into the other buffer, where
    // the left count is known from the bins, gathering the children's centroid
    // bounds. Branch-free: the destination index is computed and the bounds grow
    // through selects, so the unpredictable side costs no mispredictions, and the
    // buffers alternate level by level, so nothing is copied back.
    const float o = origin[best_axis], sc = scale[best_axis];
    const float split_at = static_cast<float>(best_bin);
    const f4 inf4 = {kInf, kInf, kInf, 0.0f}, ninf4 = {-kInf, -kInf, -kInf, 0.0f};
    Box lcbox, rcbox;
    const std::uint32_t n = t.end - t.begin;
    const PrimRef* __restrict src = buf(t.buf) + t.begin;
    PrimRef* __restrict dst = buf(1 - t.buf) + t.begin;
    std::uint32_t nl = 0, nr = nl_bins;
    auto partition = [&](auto axis) {  // the axis as a constant: a fixed lane
        for (std::uint32_t k = 0; k < n; ++k) {
            const PrimRef& p = src[k];
            f4 c = centroid(p);
            const bool right = (c[decltype(axis)::value] - o) * sc >= split_at;
            dst[right ? nr : nl] = p;
            nl += right ? 0u : 1u;
            nr += right ? 1u : 0u;
            const i4 m = right ? i4{-1, -1, -1, -1} : i4{0, 0, 0, 0};  // all ones: right
            lcbox.grow(m ? inf4 : c, m ? ninf4 : c);
            rcbox.grow(m ? c : inf4, m ? c : ninf4);
        }
    };
    if (best_axis == 0) partition(std::integral_constant<int, 0>{});
    else if (best_axis == 1) partition(std::integral_constant<int, 1>{});
    else partition(std::integral_constant<int, 2>{});
    s.lcbox = lcbox;
    s.rcbox = rcbox;
    s.mid = t.begin + nl;
    s.moved = true;
    if (s.mid > t.begin && s.mid < t.end) return true;
    // Not reached (both sides of the chosen split hold references); keeps the range
    // where the task says it is.
    std::memcpy(static_cast<void*>(buf(t.buf) + t.begin), dst, n * sizeof(PrimRef));
    s.moved = false;
    return false;
}

// For small ranges: sorts the centroids on each axis and evaluates every split
// between consecutive references (the full SAH sweep), cheaper here than binning.
bool Builder::exact_split(const Task& t, Split& s, float& best_cost) {
    const int n = static_cast<int>(t.end - t.begin);
    PrimRef* p = buf(t.buf) + t.begin;
    s.moved = false;
    if (n == 2) {  // one way to split two
        s.lbox = s.lcbox = s.rbox = s.rcbox = Box{};
        f4 c0 = centroid(p[0]), c1 = centroid(p[1]);
        s.lbox.grow(lo_of(p[0]), hi_of(p[0]));
        s.rbox.grow(lo_of(p[1]), hi_of(p[1]));
        s.lcbox.grow(c0, c0);
        s.rcbox.grow(c1, c1);
        s.mid = t.begin + 1;
        best_cost = s.lbox.half_area() + s.rbox.half_area();
        return true;
    }
    f4 lo[kExactMax], hi[kExactMax], c[kExactMax];
    for (int i = 0; i < n; ++i) {
        lo[i] = lo_of(p[i]);
        hi[i] = hi_of(p[i]);
        c[i] = centroid2(lo[i], hi[i]);
    }
    // Stable sort on each axis by rank, all three axes at once and without branches:
    // a reference's position is the number of references before it in (centroid,
    // index) order.
    int order[3][kExactMax];
    for (int i = 0; i < n; ++i) {
        i4 rank = {0, 0, 0, 0};
        for (int j = 0; j < i; ++j) rank -= c[j] <= c[i];
        for (int j = i + 1; j < n; ++j) rank -= c[j] < c[i];
        order[0][rank[0]] = i;
        order[1][rank[1]] = i;
        order[2][rank[2]] = i;
    }
    // The sweeps of the three axes run side by side: lane a of an f4 is axis a.
    f4 right_area[kExactMax];
    {
        Box r0, r1, r2;
        for (int i = n - 1; i > 0; --i) {
            r0.grow(lo[order[0][i]], hi[order[0][i]]);
            r1.grow(lo[order[1][i]], hi[order[1][i]]);
            r2.grow(lo[order[2][i]], hi[order[2][i]]);
            right_area[i] = half_areas(r0, r1, r2);
        }
    }
    const f4 inf4 = {kInf, kInf, kInf, kInf};
    f4 best = inf4;
    i4 best_at = {0, 0, 0, 0};
    {
        Box l0, l1, l2;
        for (int i = 1; i < n; ++i) {
            l0.grow(lo[order[0][i - 1]], hi[order[0][i - 1]]);
            l1.grow(lo[order[1][i - 1]], hi[order[1][i - 1]]);
            l2.grow(lo[order[2][i - 1]], hi[order[2][i - 1]]);
            const auto fi = static_cast<float>(blocks(static_cast<std::uint32_t>(i)));
            const auto fr = static_cast<float>(blocks(static_cast<std::uint32_t>(n - i)));
            const f4 cost = half_areas(l0, l1, l2) * f4{fi, fi, fi, fi} + right_area[i] * f4{fr, fr, fr, fr};
            const i4 better = cost < best;  // strict: the first best split per axis
            best = better ? cost : best;
            best_at = better ? i4{i, i, i, i} : best_at;
        }
    }
    int best_i = 0;
    const int best_axis = std::max(cheapest_axis(best, best_at, best_cost, best_i), 0);
    if (best_i == 0) return false;  // only NaN costs
    PrimRef tmp[kExactMax];
    s.lbox = s.rbox = s.lcbox = s.rcbox = Box{};
    for (int i = 0; i < n; ++i) {
        int k = order[best_axis][i];
        tmp[i] = p[k];
        Box& box = i < best_i ? s.lbox : s.rbox;
        Box& cbox = i < best_i ? s.lcbox : s.rcbox;
        box.grow(lo[k], hi[k]);
        cbox.grow(c[k], c[k]);
    }
    std::copy(tmp, tmp + n, p);
    s.mid = t.begin + static_cast<std::uint32_t>(best_i);
    return true;
}

// Object median along the centroids' largest axis; halves in input order when every
// centroid coincides.
void Builder::median_split(const Task& t, Split& s) {
    f4 ext = t.cbox.hi - t.cbox.lo;
    int axis = 0;
    if (ext[1] > ext[axis]) axis = 1;
    if (ext[2] > ext[axis]) axis = 2;
    s.mid = t.begin + (t.end - t.begin) / 2;
    s.moved = false;
    PrimRef* p = buf(t.buf);
    if (ext[axis] > 0.0f)
        std::nth_element(p + t.begin, p + s.mid, p + t.end,
                         [axis](const PrimRef& x, const PrimRef& y) { return centroid(x)[axis] < centroid(y)[axis]; });
    bounds(p, t.begin, s.mid, s.lbox, s.lcbox);
    bounds(p, s.mid, t.end, s.rbox, s.rcbox);
}

// True when the range becomes a leaf; otherwise fills `s` with the split.
bool Builder::decide(const Task& t, Split& s) {
    const std::uint32_t n = t.end - t.begin;
    if (n <= 1) return true;
    const bool fits = n <= max_leaf_;
    if (t.depth + ceil_log2(n) >= kMaxLeafDepth) {  // too deep for the SAH: halve
        if (fits) return true;
        median_split(t, s);
        return false;
    }
    // Leaf or split by the SAH (MacDonald & Booth 1990): C_i*n against
    // C_t + C_i*(A_l*n_l + A_r*n_r)/A.
    float cost = 0.0f;
    if (n <= exact_max_ ? exact_split(t, s, cost) : sah_split(t, s, cost)) {
        float area = t.box.half_area();
        float split_cost = opt_.traversal_cost + opt_.intersection_cost * (area > 0.0f ? cost / area : 0.0f);
        return fits && opt_.intersection_cost * static_cast<float>(blocks(n)) <= split_cost;
    }
    if (fits) return true;  // all centroids coincide: nothing to gain from splitting
    median_split(t, s);
    return false;
}

BuildOutput Builder::run() {
    BuildOutput out;
    const std::uint32_t n = static_cast<std::uint32_t>(refs_.size());
    out.nodes.reserve(n / 2 + 1);
    out.nodes.emplace_back();
    if (n == 0) {
        set_empty_child(out.nodes[0], 0);
        set_empty_child(out.nodes[0], 1);
        return out;
    }
    Task root{0, n, 0, -1, 0, {}, {}, 0};
    bounds(refs_.data(), 0, n, root.box, root.cbox);
    double inner_sum = 0.0, leaf_sum = 0.0;  // sums of half areas

    std::vector<Task> stack;
    stack.reserve(2 * kMaxLeafDepth + 2);
    stack.push_back(root);
    Split s;
    while (!stack.empty()) {
        Task t = stack.back();
        stack.pop_back();
        const double area = static_cast<double>(t.box.half_area());
        if (decide(t, s)) {
            const std::uint32_t count = t.end - t.begin;
            if (t.buf)  // leaves end in the caller's array
                std::memcpy(static_cast<void*>(refs_.data() + t.begin), scratch_.get() + t.begin,
                            count * sizeof(PrimRef));
            int depth = t.depth;
            if (t.parent < 0) {  // the whole input is one leaf: root = {leaf, empty}
                set_child(out.nodes[0], 0, t.box);
                set_ref(out.nodes[0], 0, t.begin, count);
                set_empty_child(out.nodes[0], 1);
                inner_sum += area;
                depth = 1;
            } else {
                set_ref(out.nodes[t.parent], t.side, t.begin, count);
            }
            ++out.leaves;
            out.max_depth = std::max(out.max_depth, depth);
            out.max_leaf_size = std::max(out.max_leaf_size, static_cast<int>(count));
            leaf_sum += area * blocks(count);
            continue;
        }
        int index = 0;
        if (t.parent >= 0) {
            index = static_cast<int>(out.nodes.size());
            out.nodes.emplace_back();
            set_ref(out.nodes[t.parent], t.side, static_cast<std::uint32_t>(index), 0);
        }
        set_child(out.nodes[index], 0, s.lbox);
        set_child(out.nodes[index], 1, s.rbox);
        inner_sum += area;
        // Right first, so the left child is built next and lands right after its parent.
        const int cb = s.moved ? 1 - t.buf : t.buf;
        stack.push_back(Task{s.mid, t.end, t.depth + 1, index, 1, s.rbox, s.rcbox, cb});
        stack.push_back(Task{t.begin, s.mid, t.depth + 1, index, 0, s.lbox, s.lcbox, cb});
    }
    const double root_area = static_cast<double>(root.box.half_area());
    if (root_area > 0.0)
        out.sah_cost = (static_cast<double>(opt_.traversal_cost) * inner_sum +
                        static_cast<double>(opt_.intersection_cost) * leaf_sum) /
                       root_area;
    return out;
}

}  // namespace

void set_empty_child(BinaryNode& node, int side) {
    float* lo = side == 0 ? node.a_min : node.b_min;
    float* hi = side == 0 ? node.a_max : node.b_max;
    for (int a = 0; a < 3; ++a) {
        lo[a] = kInf;
        hi[a] = -kInf;
    }
    set_ref(node, side, 0, 0);
}

BuildOutput build_sah(std::vector<PrimRef>& refs, const BvhOptions& options) { return Builder(refs, options).run(); }

}  // namespace facet::bvh_detail
