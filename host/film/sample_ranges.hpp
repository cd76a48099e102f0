// Which sample indices a film holds: a list of half-open ranges [begin, end). Sample i of
// a pixel is a fixed function of (seed, pixel, i), so films holding disjoint ranges of
// one scene and settings add up to the film of their union, and a range rendered twice
// would count the same samples twice. Sample i goes to the even half (film_state.hpp)
// when i is even, to the odd half otherwise.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace facet {

struct SampleRange {
    std::uint64_t begin = 0, end = 0;  // indices begin ... end - 1
    std::uint64_t count() const { return end > begin ? end - begin : 0; }
    bool operator==(const SampleRange&) const = default;
};

using SampleRanges = std::vector<SampleRange>;

// Samples in all ranges.
std::uint64_t sample_count(const SampleRanges& ranges);

// Samples with even and with odd index: the two halves' counts.
std::uint64_t even_samples(const SampleRanges& ranges);
std::uint64_t odd_samples(const SampleRanges& ranges);

// Sorted by begin, empty ranges dropped, touching ones joined ([0,4) + [4,8) = [0,8)).
// Overlapping ranges are kept apart (first_overlap finds them).
SampleRanges normalized(SampleRanges ranges);

// The first index held twice by the ranges, if any.
std::optional<std::uint64_t> first_overlap(const SampleRanges& ranges);

// One past the largest index held (0 when none): where a continued render starts.
std::uint64_t next_sample(const SampleRanges& ranges);

// "0-63, 128-191" (inclusive ends), "none" when empty.
std::string describe(const SampleRanges& ranges);

}  // namespace facet
