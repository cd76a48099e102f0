#include "host/film/film_merge.hpp"

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {

void check_films_combine(const FilmState& a, const std::string& a_path, const FilmState& b, const std::string& b_path) {
    auto refuse = [&](const std::string& what, const std::string& a_value, const std::string& b_value) {
        throw Error(fmt::format("{} has {} {}, {} has {}: samples of different renders cannot be combined", b_path,
                                what, b_value, a_path, a_value));
    };
    auto refuse_scene = [&] {
        throw Error(
            fmt::format("{}: the film was rendered from another scene (identity {:016x}, {} has {:016x}; "
                        "scene files {} and {}): samples of different scenes cannot be combined",
                        b_path, b.scene_hash, a_path, a.scene_hash, b.scene_path, a.scene_path));
    };
    // Another scene file: said first; else the setting that differs, else the scene's contents.
    if (a.scene_hash != b.scene_hash && a.scene_path != b.scene_path) refuse_scene();
    if (a.width != b.width || a.height != b.height)
        refuse("a size of", fmt::format("{}x{}", a.width, a.height), fmt::format("{}x{}", b.width, b.height));
    const std::pair<const char*, std::pair<long long, long long>> settings[] = {
        {"seed", {a.seed, b.seed}},
        {"max depth", {a.max_depth, b.max_depth}},
        {"Russian roulette depth", {a.rr_depth, b.rr_depth}},
        {"strategy", {a.strategy, b.strategy}},
        {"sampler", {a.sampler, b.sampler}}};
    for (const auto& [name, values] : settings)
        if (values.first != values.second) refuse(name, std::to_string(values.first), std::to_string(values.second));
    if (a.scene_hash != b.scene_hash) refuse_scene();
}

FilmState merge_films(const std::vector<FilmState>& films, const std::vector<std::string>& paths) {
    if (films.empty()) throw Error("no films to merge");
    if (paths.size() != films.size()) throw Error("merge_films: one path per film");
    FilmState merged = films[0];
    for (std::size_t i = 1; i < films.size(); ++i) {
        const FilmState& f = films[i];
        check_films_combine(films[0], paths[0], f, paths[i]);
        for (std::size_t j = 0; j < i; ++j) {
            SampleRanges both = films[j].samples;
            both.insert(both.end(), f.samples.begin(), f.samples.end());
            if (const auto index = first_overlap(both))
                throw Error(
                    fmt::format("{} and {} both hold sample {} (samples {} and {}): the same samples "
                                "cannot be counted twice",
                                paths[j], paths[i], *index, describe(films[j].samples), describe(f.samples)));
        }
        for (std::size_t k = 0; k < merged.sums.size(); ++k) merged.sums[k] += f.sums[k];
        merged.samples.insert(merged.samples.end(), f.samples.begin(), f.samples.end());
        merged.render_seconds += f.render_seconds;
        merged.second_moments = merged.second_moments && f.second_moments;
    }
    merged.samples = normalized(merged.samples);
    merged.spp = sample_count(merged.samples);
    return merged;
}

}  // namespace facet
