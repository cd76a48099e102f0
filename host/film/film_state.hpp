// The film: everything a render has accumulated, saved so that it can be continued
// later (`facet render SCENE --resume FILM`) or merged with others. Both half-buffers
// as the device holds them (sums, not means), the samples per pixel, the render time,
// and what the samples depend on (the scene's identity, size, seed, depth, strategy). The
// file format is in docs/film-format.md; films are made and matched against a scene by
// host/render/film_identity.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/film/sample_ranges.hpp"

namespace facet {

struct FilmState {
    std::string scene_path;        // for messages only
    std::uint64_t scene_hash = 0;  // the scene's identity (render/film_identity.hpp)
    int width = 0, height = 0;
    std::uint32_t seed = 0;
    int max_depth = 0, rr_depth = 0, strategy = 0, sampler = 0;
    std::uint64_t spp = 0;  // samples in every pixel: sample_count(samples)
    SampleRanges samples;   // their indices (sample_ranges.hpp), even ones in the first half
    double render_seconds = 0.0;
    // film_floats(width * height) floats (film_layout.hpp): 2 * width * height RGBA float
    // sums, the even-sample half then the odd-sample half (A counts the samples the kernel
    // rejected, render/renderer.hpp), then each half's second moments.
    std::vector<float> sums;
    // Whether the second moments hold every sample's: false for a film of format version 1
    // or 2 (read with zeros there) and for films continued or merged from one.
    bool second_moments = true;
};

// Writes the film through write_file_safely; throws facet::Error naming the path.
void write_film(const std::string& path, const FilmState& film);

// Reads a film, checking its magic, version, sizes, sample ranges and checksum; throws
// facet::Error naming the file and the problem. Version 1 films hold indices [0, spp).
FilmState read_film(const std::string& path);

}  // namespace facet
