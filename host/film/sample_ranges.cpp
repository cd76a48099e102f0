#include "host/film/sample_ranges.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace facet {
namespace {

// Even indices in [0, n).
std::uint64_t evens_below(std::uint64_t n) { return (n + 1) / 2; }

}  // namespace

std::uint64_t sample_count(const SampleRanges& ranges) {
    std::uint64_t n = 0;
    for (const SampleRange& r : ranges) n += r.count();
    return n;
}

std::uint64_t even_samples(const SampleRanges& ranges) {
    std::uint64_t n = 0;
    for (const SampleRange& r : ranges)
        if (r.end > r.begin) n += evens_below(r.end) - evens_below(r.begin);
    return n;
}

std::uint64_t odd_samples(const SampleRanges& ranges) { return sample_count(ranges) - even_samples(ranges); }

SampleRanges normalized(SampleRanges ranges) {
    std::erase_if(ranges, [](const SampleRange& r) { return r.count() == 0; });
    std::sort(ranges.begin(), ranges.end(), [](const SampleRange& a, const SampleRange& b) {
        return a.begin < b.begin || (a.begin == b.begin && a.end < b.end);
    });
    SampleRanges out;
    for (const SampleRange& r : ranges) {
        if (!out.empty() && out.back().end == r.begin) out.back().end = r.end;
        else out.push_back(r);
    }
    return out;
}

std::optional<std::uint64_t> first_overlap(const SampleRanges& ranges) {
    SampleRanges sorted = normalized(ranges);
    for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].begin < sorted[i - 1].end) return sorted[i].begin;
    return std::nullopt;
}

std::uint64_t next_sample(const SampleRanges& ranges) {
    std::uint64_t n = 0;
    for (const SampleRange& r : ranges)
        if (r.count()) n = std::max(n, r.end);
    return n;
}

std::string describe(const SampleRanges& ranges) {
    std::string s;
    for (const SampleRange& r : normalized(ranges))
        s += fmt::format("{}{}-{}", s.empty() ? "" : ", ", r.begin, r.end - 1);
    return s.empty() ? "none" : s;
}

}  // namespace facet
