// From a film's sums to images: the two half-images (means of the even- and the
// odd-indexed samples, for the error estimate without a reference) and the image (the
// mean of all samples). The sums are laid out as the device holds them
// (film_layout.hpp): the even half's RGBA sums, then the odd half's, then each half's
// second moments.
#pragma once

#include <cstdint>
#include <vector>

#include "host/film/error_metrics.hpp"
#include "host/film/film_state.hpp"
#include "host/film/sample_ranges.hpp"

namespace facet {

struct FilmHalves {
    std::vector<float> rgb[2];  // 3 floats a pixel, each half averaged over its own count
    // 1 float a pixel: the mean over the half's samples of r^2 + g^2 + b^2, from which the
    // half's own variance follows (denoise/denoise_variance.hpp); empty when the sums do
    // not hold every sample's (a film written before format version 3, or continued from one)
    std::vector<float> square[2];
    std::uint64_t samples[2] = {0, 0};
    double rejected = 0.0;  // samples the kernel dropped (the A channels)
};

// The halves of `sums` (film_floats(pixels) floats) holding the samples `samples`; their
// second moments too when `second_moments` says the sums hold every sample's.
FilmHalves film_halves(const std::vector<float>& sums, std::size_t pixels, const SampleRanges& samples,
                       bool second_moments);
// The halves of a film.
FilmHalves film_halves(const FilmState& film);

// estimate_error of the halves of the sum of `films` (each film_floats(pixels) floats)
// holding the samples `samples`, without building the sum or the halves: the progressive
// render's estimate after every pass, which at 1024² would otherwise allocate and fill
// about 70 MB each pass. The films are added in list order in float and each half scaled
// as film_halves scales it, so the result is estimate_error(film_halves(sum, ...)) bit for bit.
ErrorMetrics estimate_film_error(const std::vector<const std::vector<float>*>& films, std::size_t pixels,
                                 const SampleRanges& samples);

// The mean of both halves, weighted by their counts; 3 floats a pixel.
std::vector<float> film_mean(const FilmHalves& halves);

}  // namespace facet
