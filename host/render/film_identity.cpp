#include "host/render/film_identity.hpp"

#include <span>
#include <string>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

// FNV-1a, 64 bits (Fowler, Noll and Vo; the film format's payload checksum is the same).
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const unsigned char* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
    }
};

std::string strategy_name(int v) {
    return v == FC_STRATEGY_MIS     ? std::string("mis")
           : v == FC_STRATEGY_LIGHT ? std::string("light")
           : v == FC_STRATEGY_BSDF  ? std::string("bsdf")
                                    : std::to_string(v);
}

std::string sampler_name(int v) {
    return v == FC_SAMPLER_SOBOL         ? std::string("sobol")
           : v == FC_SAMPLER_INDEPENDENT ? std::string("independent")
                                         : std::to_string(v);
}

}  // namespace

std::uint64_t film_identity(const DeviceScene& scene) {
    Fnv f;
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
    // Another scene file: said first; else the setting that differs, else the scene's contents.
    if (film.scene_hash != identity && film.scene_path != scene.source_path) refuse_scene();
    if (film.width != s.width || film.height != s.height)
        refuse("a size of", fmt::format("{}x{}", film.width, film.height), fmt::format("{}x{}", s.width, s.height));
    if (film.seed != s.seed) refuse("--seed", std::to_string(film.seed), std::to_string(s.seed));
    if (film.max_depth != s.max_depth)
        refuse("--max-depth", std::to_string(film.max_depth), std::to_string(s.max_depth));
    if (film.rr_depth != s.rr_depth)
        refuse("Russian roulette depth", std::to_string(film.rr_depth), std::to_string(s.rr_depth));
    if (film.strategy != s.strategy) refuse("--strategy", strategy_name(film.strategy), strategy_name(s.strategy));
    if (film.sampler != s.sampler) refuse("--sampler", sampler_name(film.sampler), sampler_name(s.sampler));
    if (film.scene_hash != identity) refuse_scene();
}

}  // namespace facet
