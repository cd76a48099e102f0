// The film: everything a render has accumulated, saved so that it can be continued
// later (`facet render SCENE --resume FILM`) or merged with others. Both half-buffers
// as the device holds them (sums, not means), the samples per pixel, the render time,
// and what the samples depend on (scene hash, size, seed, depth, strategy). The file
// format is in docs/film-format.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/film/sample_ranges.hpp"

namespace facet {

struct Scene;

struct FilmState {
    std::string scene_path;        // for messages only
    std::uint64_t scene_hash = 0;  // film_scene_hash(): geometry, materials, lights, camera, environment
    int width = 0, height = 0;
    std::uint32_t seed = 0;
    int max_depth = 0, rr_depth = 0, strategy = 0, sampler = 0;
    std::uint64_t spp = 0;  // samples in every pixel: sample_count(samples)
    SampleRanges samples;   // their indices (sample_ranges.hpp), even ones in the first half
    double render_seconds = 0.0;
    // 2 * width * height RGBA float sums: the even-sample half, then the odd-sample half;
    // A counts the samples the kernel rejected (render/renderer.hpp).
    std::vector<float> sums;
};

// A 64-bit FNV-1a hash of what the samples depend on besides the settings: vertices,
// shading, materials, lights, camera and environment map.
std::uint64_t film_scene_hash(const Scene& scene);

// A film of `scene` (settings from scene.settings) holding `sums` of the samples with
// indices in `samples`; the second form for indices [0, spp).
FilmState make_film(const Scene& scene, std::uint64_t scene_hash, const SampleRanges& samples, double render_seconds,
                    std::vector<float> sums);
FilmState make_film(const Scene& scene, std::uint64_t scene_hash, std::uint64_t spp, double render_seconds,
                    std::vector<float> sums);

// Writes the film through write_file_safely; throws facet::Error naming the path.
void write_film(const std::string& path, const FilmState& film);

// Reads a film, checking its magic, version, sizes, sample ranges and checksum; throws
// facet::Error naming the file and the problem. Version 1 films hold indices [0, spp).
FilmState read_film(const std::string& path);

// Throws facet::Error naming the film and the first setting in which it differs from a
// render of `scene` (scene hash, width, height, seed, max depth, Russian roulette depth,
// strategy): samples of another scene or settings must not be mixed.
void check_film_matches(const FilmState& film, const std::string& film_path, const Scene& scene,
                        std::uint64_t scene_hash);

}  // namespace facet
