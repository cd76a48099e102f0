// `facet merge A.film B.film ... --out image.exr`: the films of one scene and settings,
// holding disjoint sample ranges (renders with --samples-from, or with different
// machines' shares), added into one film; its image, PNG and (with --film) the film
// written, and the merged film's error estimate printed.
#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/cli/output_locks.hpp"
#include "host/cli/outputs.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/film/film_halves.hpp"
#include "host/film/film_merge.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"

namespace facet {
namespace {

// The outputs (--out, the PNG beside it, --film) are files of their own: none an input
// film (by any spelling: ./a.film, a link, a hard link), none another output.
void check_merge_outputs(const MergeOptions& opt) {
    check_output_path(opt.out, "--out");
    std::string why;
    if (!can_write_float_image(opt.out, &why)) throw Error(fmt::format("--out {}: {}", opt.out, why));
    std::vector<std::pair<std::string, std::string>> outputs = {
        {"--out", opt.out}, {"the PNG beside --out", replace_extension(opt.out, ".png")}};
    if (!opt.film.empty()) {
        check_output_path(opt.film, "--film");
        outputs.push_back({"--film", opt.film});
    }
    for (const auto& [label, path] : outputs)
        for (const std::string& film : opt.films)
            if (same_file(path, film))
                throw Error(fmt::format("{} {}: would overwrite the input film {}", label, path, film));
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (same_file(outputs[i].second, outputs[j].second))
                throw Error(fmt::format("{} {}: is the same file as {} ({}): each output needs its own name",
                                        outputs[i].first, outputs[i].second, outputs[j].first, outputs[j].second));
}

}  // namespace

int run_merge(const MergeOptions& opt) {
    check_merge_outputs(opt);
    OutputLocks locks;  // no other facet writes them meanwhile (output_locks.hpp)
    locks.lock(opt.out, "--out");
    if (!opt.film.empty()) locks.lock(opt.film, "--film");
    std::vector<FilmState> films;
    for (const std::string& path : opt.films) films.push_back(read_film(path));
    const FilmState merged = merge_films(films, opt.films);
    if (merged.spp == 0) throw Error("the films hold no samples: nothing to merge");
    const FilmHalves h = film_halves(merged);
    const std::vector<float> rgb = film_mean(h);
    ImageMetadata meta;
    meta.ints.push_back({"facet:spp", int(merged.spp)});
    meta.ints.push_back({"facet:seed", int(merged.seed)});
    meta.ints.push_back({"facet:max_depth", merged.max_depth});
    meta.strings.push_back({"facet:samples", describe(merged.samples)});
    meta.floats.push_back({"facet:render_seconds", float(merged.render_seconds)});
    meta.strings.push_back({"facet:scene", merged.scene_path});
    write_exr(opt.out, merged.width, merged.height, rgb, meta);
    write_png(replace_extension(opt.out, ".png"), merged.width, merged.height, rgb, opt.exposure);
    if (!opt.film.empty()) write_film(opt.film, merged);
    const ErrorMetrics e = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
    fmt::print("merged   {} films: {} spp (samples {}), {:.2f} s of rendering\n", films.size(), merged.spp,
               describe(merged.samples), merged.render_seconds);
    fmt::print("estimate rmse {:.6e}, relmse {:.6e} (from the two halves)\n", e.rmse, e.relmse);
    fmt::print("wrote    {} and {}{}\n", opt.out, replace_extension(opt.out, ".png"),
               opt.film.empty() ? "" : " and " + opt.film);
    if (h.rejected > 0)
        fmt::print(stderr, "facet: warning: {} samples were NaN, infinite or negative and were dropped\n", h.rejected);
    return kExitOk;
}

}  // namespace facet
