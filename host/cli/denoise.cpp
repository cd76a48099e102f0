// `facet denoise IMAGE.exr [--film FILM]`: an image rendered with --aov albedo,normal
// (and depth) denoised after the render, by OIDN or facet's denoiser; with the render's
// film, from its two half-images, with the denoised error estimated
// (denoise/denoise_error.hpp). Load, denoise, write.
#include <filesystem>

#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/cli/output_locks.hpp"
#include "host/cli/outputs.hpp"
#include "host/denoise/denoise_choice.hpp"
#include "host/denoise/denoise_error.hpp"
#include "host/denoise/oidn.hpp"
#include "host/error.hpp"
#include "host/film/film_halves.hpp"
#include "host/film/film_state.hpp"
#include "host/image/image_channels.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The AOV layers of `path` (depth optional: 0, which turns its guide off).
AovImages read_features(const std::string& path, std::size_t pixels) {
    AovImages f;
    for (const char* layer : {"albedo", "normal"}) {
        const std::vector<std::string> names = std::string(layer) == "albedo"
                                                   ? std::vector<std::string>{"albedo.R", "albedo.G", "albedo.B"}
                                                   : std::vector<std::string>{"normal.X", "normal.Y", "normal.Z"};
        if (!has_channels(path, names))
            throw Error(fmt::format("{}: has no {} layer ({}, {}, {}): render it with --aov albedo,normal,depth", path,
                                    layer, names[0], names[1], names[2]));
        (std::string(layer) == "albedo" ? f.albedo : f.normal) = read_channels(path, names);
    }
    f.depth = has_channels(path, {"depth.Z"}) ? read_channels(path, {"depth.Z"}) : std::vector<float>(pixels, 0.0f);
    return f;
}

}  // namespace

int run_denoise(const DenoiseOptions& opt) {
    const fs::path in(opt.image);
    const std::string out =
        opt.out.empty() ? (in.parent_path() / in.stem()).string() + ".denoised" + in.extension().string() : opt.out;
    const std::string png = replace_extension(out, ".png");
    check_output_path(out, "--out");
    std::string why;
    if (!can_write_float_image(out, &why)) throw Error(fmt::format("--out {}: {}", out, why));
    for (const std::string& output : {out, png})
        for (const std::string& input : {opt.image, opt.film})
            if (!input.empty() && same_file(output, input))
                throw Error(fmt::format("--out {}: would overwrite the input {}", output, input));
    OutputLocks locks;
    locks.lock(out, "--out");

    const ImageRGB image = read_image(opt.image);
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    const AovImages features = read_features(opt.image, pixels);
    FilmHalves halves;
    const bool with_film = !opt.film.empty();
    if (with_film) {
        const FilmState film = read_film(opt.film);
        if (film.width != image.width || film.height != image.height)
            throw Error(fmt::format("--film {}: is {}x{}, the image {} is {}x{}", opt.film, film.width, film.height,
                                    opt.image, image.width, image.height));
        halves = film_halves(film);
    } else {
        if (opt.denoiser == "facet")
            throw Error(fmt::format(
                "{}: facet's denoiser reads the two half-images of the render's film: give --film FILM", opt.image));
        if (find_oidn(opt.oidn).empty())
            throw Error(fmt::format(
                "{}: without --film (the render's film: its half-images) only Intel Open Image Denoise can denoise "
                "it, and it was not found: give --film FILM, or --oidn LIBRARY (or `pip install pyoidn`)",
                opt.image));
        halves.rgb[0] = halves.rgb[1] = image.rgb;  // OIDN alone: the image, no half-images
        halves.samples[0] = halves.samples[1] = 1;
    }
    const std::string asked = with_film ? opt.denoiser : "oidn";
    const DenoiseRun d = run_denoiser(
        asked, opt.oidn, std::uint32_t(image.width), std::uint32_t(image.height), halves, features,
        [&] {
            ClContext ctx = ClContext::create(opt.device);
            return denoise(ctx, std::uint32_t(image.width), std::uint32_t(image.height), halves, features);
        },
        [](const std::string& w) { fmt::print(stderr, "facet: warning: {}\n", w); });
    if (with_film && d.denoiser == "facet" && !d.image.own_variance)
        fmt::print(stderr,
                   "facet: warning: {}: the film holds no second moments (written before film format 3, or "
                   "continued from such a film), so facet's denoiser read each half's variance from both halves: "
                   "the error estimate may read low below 16 spp (docs/denoising.md)\n",
                   opt.film);
    ImageMetadata meta;
    meta.strings.push_back({"facet:denoiser", d.denoiser});
    meta.strings.push_back({"facet:denoised_from", opt.image});
    if (image.spp > 0) meta.ints.push_back({"facet:spp", image.spp});
    write_exr(out, image.width, image.height, d.image.rgb, meta);
    write_png(png, image.width, image.height, d.image.rgb, opt.exposure);
    fmt::print("denoised {} with {} in {:.2f} s\n", opt.image, d.words, d.image.seconds);
    if (with_film) {
        const ErrorMetrics noisy = estimate_error(halves.rgb[0], halves.rgb[1], halves.samples[0], halves.samples[1]);
        fmt::print("estimate rmse {:.6e} denoised, {:.6e} noisy (from the two halves)\n",
                   estimate_denoised_error(halves, d.image).rmse, noisy.rmse);
    } else {
        fmt::print("estimate none: without --film there are no half-images to estimate the error from\n");
    }
    fmt::print("wrote    {} and {}\n", out, png);
    return kExitOk;
}

}  // namespace facet
