#include "host/render/film_identity.hpp"

#include <span>
#include <string>

#include <fmt/format.h>

#include "host/cl/kernel_source.hpp"
#include "host/error.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/render_names.hpp"
#include "host/util/fnv.hpp"

namespace facet {

std::uint64_t kernel_code_digest(const std::string& assembled_text) {
    Fnv1a f;
    std::size_t at = 0;
    while (at < assembled_text.size()) {
        std::size_t end = assembled_text.find('\n', at);
        end = end == std::string::npos ? assembled_text.size() : end + 1;
        if (assembled_text.compare(at, 6, "#line ") != 0) f.bytes(assembled_text.data() + at, end - at);
        at = end;
    }
    return f.h;
}

std::uint64_t render_kernel_digest() {
    static const std::uint64_t digest = kernel_code_digest(assemble_program(kRenderProgram).text);
    return digest;
}

std::uint64_t film_identity(const DeviceScene& scene) { return film_identity(scene, render_kernel_digest()); }

std::uint64_t film_identity(const DeviceScene& scene, std::uint64_t kernel_digest) {
    Fnv1a f;
    f.bytes(&kernel_digest, sizeof kernel_digest);
    FcRenderParams p = scene.params;
    p.sample_begin = p.sample_count = p.row_begin = p.row_count = 0;
    f.bytes(&p, sizeof p);
    auto block = [&](std::span<const std::byte> bytes) {
        const std::uint64_t n = bytes.size();
        f.bytes(&n, sizeof n);
        f.bytes(bytes.data(), bytes.size());
    };
    for (const DeviceScene::Array& a : scene.arrays()) {
        f.bytes(a.name, std::char_traits<char>::length(a.name));
        if (a.kind == FC_ARRAY_CONTENT) block(a.bytes);
    }
    for (std::span<const std::byte> input : scene.tree_inputs) block(input);
    return f.h;
}

std::uint64_t film_identity(const Scene& scene, const Bvh& bvh) { return film_identity(compile(scene, bvh)); }

FilmState make_film(const Scene& scene, std::uint64_t identity, std::uint64_t spp, double render_seconds,
                    std::vector<float> sums) {
    return make_film(scene, identity, SampleRanges{{0, spp}}, render_seconds, std::move(sums));
}

FilmState make_film(const Scene& scene, std::uint64_t identity, const SampleRanges& samples, double render_seconds,
                    std::vector<float> sums) {
    FilmState film;
    film.scene_path = scene.source_path;
    film.scene_hash = identity;
    film.width = scene.settings.width;
    film.height = scene.settings.height;
    film.seed = scene.settings.seed;
    film.max_depth = scene.settings.max_depth;
    film.rr_depth = scene.settings.rr_depth;
    film.strategy = scene.settings.strategy;
    film.sampler = scene.settings.sampler;
    film.samples = normalized(samples);
    film.spp = sample_count(film.samples);
    film.render_seconds = render_seconds;
    film.sums = std::move(sums);
    return film;
}

void check_film_matches(const FilmState& film, const std::string& film_path, const Scene& scene,
                        std::uint64_t identity) {
    const RenderSettings& s = scene.settings;
    auto refuse = [&](const std::string& what, const std::string& film_value, const std::string& now) {
        throw Error(
            fmt::format("--resume {}: the film was rendered with {} {}, this render has {}: samples of "
                        "different renders cannot be combined",
                        film_path, what, film_value, now));
    };
    auto refuse_scene = [&] {
        throw Error(
            fmt::format("--resume {}: the film was rendered from another scene (identity {:016x}, this scene {:016x}; "
                        "the film's scene file: {}, this one: {}): samples of different scenes cannot be combined",
                        film_path, film.scene_hash, identity, film.scene_path, scene.source_path));
    };
    // The same file and the settings above: its contents changed, a setting the film does not
    // list differs, or the film comes from a facet with other render kernels.
    auto refuse_contents = [&] {
        throw Error(fmt::format(
            "--resume {}: the film was rendered from another scene, or by a facet whose render kernels differ from "
            "this one's, or with other settings than its size, seed, depths, strategy and sampler (the pixel "
            "filter, the environment, --clamp, --caustic-guide, --roulette-gain) (identity {:016x}, this render "
            "{:016x}; scene file {}): samples of different scenes, settings or kernels cannot be combined; render "
            "it again, or resume it with the facet and the options that rendered it",
            film_path, film.scene_hash, identity, scene.source_path));
    };
    // Another scene file: said first; else the setting that differs, else the scene's contents.
    if (film.scene_hash != identity && film.scene_path != scene.source_path) refuse_scene();
    if (film.width != s.width || film.height != s.height)
        refuse("a size of", fmt::format("{}x{}", film.width, film.height), fmt::format("{}x{}", s.width, s.height));
    if (film.seed != s.seed) refuse("--seed", std::to_string(film.seed), std::to_string(s.seed));
    if (film.max_depth != s.max_depth)
        refuse("--max-depth", std::to_string(film.max_depth), std::to_string(s.max_depth));
    if (film.rr_depth != s.rr_depth)
        refuse("Russian roulette depth", std::to_string(film.rr_depth), std::to_string(s.rr_depth));
    if (film.strategy != s.strategy)
        refuse("--strategy", setting_name(kStrategyNames, film.strategy), setting_name(kStrategyNames, s.strategy));
    if (film.sampler != s.sampler)
        refuse("--sampler", setting_name(kSamplerNames, film.sampler), setting_name(kSamplerNames, s.sampler));
    if (film.scene_hash != identity) refuse_contents();
}

}  // namespace facet
