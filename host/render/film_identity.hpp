// What a film's samples depend on, so that samples of different scenes or settings are
// never combined (`--resume`, `facet merge`, MPI ranks). The identity is a hash of what
// the kernels read: every array of the compiled device scene (kernels/shared/scene_arrays.h,
// so no array can be left out; the trees by what they are built from) and the parameter block without its per-launch
// fields, which holds every setting that changes a sample (size, camera, seed, depths, strategy, sampler, pixel filter,
// clamp, environment); and of the code that computes the samples, the render program's sources
// (render_kernel_digest), so that a film is never continued by another facet whose kernels
// would draw or weigh its samples differently. The film format itself is host/film/.
#pragma once

#include <cstdint>
#include <string>

#include "host/bvh/bvh.hpp"
#include "host/film/film_state.hpp"
#include "host/film/sample_ranges.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// A 64-bit FNV-1a hash of the parameter block with sample_begin, sample_count, row_begin
// and row_count zeroed, of every array's name and, for FC_ARRAY_CONTENT arrays, its length
// and bytes (list order), and of the tree arrays' inputs (DeviceScene::tree_inputs).
std::uint64_t film_identity(const DeviceScene& scene);
// The same with the render kernels' digest given (the first form passes render_kernel_digest()).
std::uint64_t film_identity(const DeviceScene& scene, std::uint64_t kernel_digest);

// A 64-bit FNV-1a over an assembled program's text without its #line directives (which
// name where the files were read from: embedded or FACET_KERNEL_DIR).
std::uint64_t kernel_code_digest(const std::string& assembled_text);
// kernel_code_digest of the render program (kernels/integrator/path.cl with every file it
// includes, whatever the scene's features), assembled once per process.
std::uint64_t render_kernel_digest();
// The identity of `scene` compiled with `bvh` (for tools and tests; a render compiles once
// and takes the first form).
std::uint64_t film_identity(const Scene& scene, const Bvh& bvh);

// A film of `scene` (settings from scene.settings) with identity `identity` holding `sums`
// of the samples with indices in `samples`; the second form for indices [0, spp).
FilmState make_film(const Scene& scene, std::uint64_t identity, const SampleRanges& samples, double render_seconds,
                    std::vector<float> sums);
FilmState make_film(const Scene& scene, std::uint64_t identity, std::uint64_t spp, double render_seconds,
                    std::vector<float> sums);

// Throws facet::Error when the film's samples cannot be continued by a render of `scene`
// with identity `identity`: "the film was rendered from another scene (identity X, this
// scene Y)" when the identities and the scene files differ, else the first setting that
// differs (width, height, seed, max depth, Russian roulette depth, strategy, sampler), else
// the same message when only the identities differ.
void check_film_matches(const FilmState& film, const std::string& film_path, const Scene& scene,
                        std::uint64_t identity);

}  // namespace facet
