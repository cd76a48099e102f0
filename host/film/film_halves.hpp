// From a film's sums to images: the two half-images (means of the even- and the
// odd-indexed samples, for the error estimate without a reference) and the image (the
// mean of all samples). The sums are laid out as the device holds them
// (film_state.hpp): the even half's RGBA sums, then the odd half's.
#pragma once

#include <cstdint>
#include <vector>

#include "host/film/sample_ranges.hpp"

namespace facet {

struct FilmHalves {
    std::vector<float> rgb[2];  // 3 floats a pixel, each half averaged over its own count
    std::uint64_t samples[2] = {0, 0};
    double rejected = 0.0;  // samples the kernel dropped (the A channels)
};

// The halves of `sums` (2 * pixels RGBA floats) holding the samples `samples`.
FilmHalves film_halves(const std::vector<float>& sums, std::size_t pixels, const SampleRanges& samples);

// The mean of both halves, weighted by their counts; 3 floats a pixel.
std::vector<float> film_mean(const FilmHalves& halves);

}  // namespace facet
