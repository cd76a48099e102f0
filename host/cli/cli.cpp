// `facet devices | info | render`: argument parsing and dispatch.
#include "host/cli/cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/error.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/scene/render_names.hpp"
#include "host/scene/settings_limits.hpp"
#include "host/util/strings.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {
namespace {

// CLI11's range checks let NaN through (every comparison with it is false): a number
// option must first be a finite number ("nan" and "inf" parse as doubles).
const CLI::Validator kFinite(
    [](std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return std::string();  // left to the conversion's message
        return std::isfinite(v) ? std::string() : "Value " + text + " is not a finite number";
    },
    "FINITE");

// An integer option within its setting's range (host/scene/settings_limits.hpp), the
// range said in words when it is not.
CLI::Validator in_range(SettingRange range) {
    return CLI::Validator(
        [range](std::string& text) {
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(text.c_str(), &end, 10);
            if (end == text.c_str() || *end != '\0') return std::string();  // left to the conversion's message
            if (errno == ERANGE || !range.contains(v)) return fmt::format("Value {} is not {}", text, range.words());
            return std::string();
        },
        range.words());
}

// A number of seconds > 0 (after kFinite).
const CLI::Validator kSeconds(
    [](std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return std::string();  // left to the conversion's message
        return v > 0.0 ? std::string() : fmt::format("Value {} is not {}", text, limits::kTimeWords);
    },
    "SECONDS > 0");

// A number in (0, hi], said in words when it is not.
CLI::Validator positive_up_to(double hi, const char* unit) {
    const std::string words = fmt::format("a number in (0, {:g}] ({})", hi, unit);
    return CLI::Validator(
        [hi, words](std::string& text) {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return std::string();  // left to the conversion's message
            return v > 0.0 && v <= hi ? std::string() : fmt::format("Value {} is not {}", text, words);
        },
        words);
}

std::map<std::string, int> pixel_filter_map() {
    std::map<std::string, int> m;
    for (const PixelFilterInfo& f : kPixelFilters) m[f.name] = f.code;
    return m;
}

std::string pixel_filter_help() {
    std::string out;
    for (const PixelFilterInfo& f : kPixelFilters) out += (out.empty() ? "" : ", ") + std::string(f.words);
    return out;
}

// After an unknown option: "did you mean --spp?" for each unexpected --word that is
// within 2 edits of an option of the subcommand it was given to.
void suggest_options(const CLI::App& app) {
    const CLI::App* cmd = &app;
    for (const CLI::App* sub : app.get_subcommands()) cmd = sub;  // the one parsed
    for (const std::string& extra : app.remaining(/*recurse=*/true)) {
        if (extra.rfind("--", 0) != 0) continue;
        const std::string word = extra.substr(0, extra.find('='));
        std::string best;
        std::size_t best_distance = 3;
        for (const CLI::Option* o : cmd->get_options())
            for (const std::string& name : o->get_lnames()) {
                const std::size_t d = edit_distance(word, "--" + name);
                if (d < best_distance) best_distance = d, best = "--" + name;
            }
        if (!best.empty()) std::cerr << fmt::format("facet: {}: did you mean {}?\n", word, best);
    }
}

}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"facet: a physically based path tracer running as OpenCL kernels"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "facet 0.1.0");

    CLI::App* devices = app.add_subcommand("devices", "List OpenCL platforms and devices");

    InfoOptions info_opt;
    CLI::App* info = app.add_subcommand("info", "Print what a scene holds: triangles, materials, lights, BVH");
    info->add_option("scene", info_opt.scene,
                     "Scene file (.json), mesh (.obj, .ply, .ply.gz) or glTF 2.0 (.gltf, .glb)")
        ->required();

    RenderOptions opt;
    CLI::App* render = app.add_subcommand("render", "Render a scene progressively to EXR + PNG");
    render->add_option("scene", opt.scene, "Scene file (.json), mesh (.obj, .ply, .ply.gz) or glTF 2.0 (.gltf, .glb)")
        ->required();
    render->add_option("--spp", opt.spp, "Samples per pixel (default: the scene's)")->check(in_range(limits::kSpp));
    render
        ->add_option("--time", opt.time_limit,
                     "Stop after this many seconds of rendering (whichever of --spp and --time ends first)")
        ->check(kFinite & kSeconds);
    render
        ->add_option("--noise-threshold", opt.noise_threshold,
                     "Adaptive stopping: end once the reference-free error estimate (relMSE of the two half-images, "
                     "from 16 spp on) is at most RELMSE (whichever of --spp, --time and this ends first)")
        ->check(kFinite & positive_up_to(1e30, "relMSE"));
    render
        ->add_option("--adaptive", opt.adaptive,
                     "With --noise-threshold: global (default; the whole image stops at once) or tiles (after 16 "
                     "spp, bands of 8 rows whose own estimate is above the threshold get their samples doubled, "
                     "round after round)")
        ->transform(CLI::CheckedTransformer(std::map<std::string, RenderOptions::Adaptive>{
            {"global", RenderOptions::Adaptive::Global}, {"tiles", RenderOptions::Adaptive::Tiles}}))
        ->needs("--noise-threshold");
    render->add_option("--width", opt.width, "Image width in pixels (default: the scene's)")
        ->check(in_range(limits::kWidth));
    render->add_option("--height", opt.height, "Image height in pixels (default: the scene's)")
        ->check(in_range(limits::kHeight));
    render->add_option("--max-depth", opt.max_depth, "Maximum number of bounces (1 = direct light only)")
        ->check(in_range(limits::kMaxDepth));
    render->add_option("--seed", opt.seed, "Seed of the random stream (same seed and settings give the same image)")
        ->check(in_range(limits::kSeed));
    render
        ->add_option("--strategy", opt.strategy,
                     "Direct light from area lights and the environment: mis (default), light (light sampling only) "
                     "or bsdf (BSDF sampling only); for measuring the strategies")
        ->transform(CLI::CheckedTransformer(setting_map(kStrategyNames)));
    render
        ->add_option("--env-sampling", opt.env_plain,
                     "Environment map sampling under MIS: compensated (default; MIS compensation, Karlik et al. "
                     "2019) or plain (by luminance)")
        ->transform(CLI::CheckedTransformer(std::map<std::string, int>{{"compensated", 0}, {"plain", 1}}));
    render
        ->add_option("--sampler", opt.sampler,
                     "Sample generator: sobol (default; Owen-scrambled Sobol', Burley 2020) or independent (PCG32)")
        ->transform(CLI::CheckedTransformer(setting_map(kSamplerNames)));
    render
        ->add_option("--filter", opt.filter,
                     "Pixel filter, drawn by filter importance sampling: " + pixel_filter_help() +
                         "; default: the scene's, else box")
        ->transform(CLI::CheckedTransformer(pixel_filter_map()));
    render
        ->add_option("--filter-radius", opt.filter_radius,
                     "Radius of the pixel filter in pixels (default: the filter's)")
        ->check(kFinite & positive_up_to(kMaxFilterRadius, "pixels"));
    render
        ->add_option("--clamp", opt.clamp,
                     "Clamp each sample's contribution to this value (its largest channel): fewer fireflies, but "
                     "biased (darker); off by default, recorded in the EXR metadata and the report")
        ->check(kFinite & positive_up_to(FC_MAX_RADIANCE, "radiance"));
    render->add_option("--camera", opt.camera, "A glTF file's camera by name (default: the first one)");
    render->add_option("--eye", opt.eye, "Camera position X,Y,Z (replaces the scene's)")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite);
    render->add_option("--target", opt.target, "Point the camera looks at, X,Y,Z")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite);
    render->add_option("--up", opt.up, "Camera up direction X,Y,Z")->delimiter(',')->expected(3)->check(kFinite);
    render->add_option("--fov", opt.fov, "Vertical field of view in degrees (perspective)")
        ->check(kFinite & CLI::Validator(
                              [](std::string& text) {
                                  const double v = std::strtod(text.c_str(), nullptr);
                                  return v > 0.0 && v < 180.0
                                             ? std::string()
                                             : fmt::format("Value {} is not a number of degrees in (0, 180)", text);
                              },
                              "DEGREES in (0, 180)"));
    render->add_option("--aperture", opt.aperture, "Thin-lens radius in scene units (0: a pinhole; depth of field)")
        ->check(kFinite & CLI::Validator(
                              [](std::string& text) {
                                  return std::strtod(text.c_str(), nullptr) >= 0.0
                                             ? std::string()
                                             : fmt::format("Value {} is not a number >= 0", text);
                              },
                              "RADIUS >= 0"));
    render
        ->add_option("--focus-distance", opt.focus_distance,
                     "Distance of the plane in focus along the view direction (default: to --target)")
        ->check(kFinite & positive_up_to(1e30f, "scene units"));
    render->add_option("--device", opt.device,
                       "OpenCL device: index from `facet devices` or part of its name (default: first GPU, else CPU); "
                       "several render together: all, gpu, cpu, or a list such as 0,2 (docs/devices.md)");
    render
        ->add_option("--samples-from", opt.samples_from,
                     "First sample index: renders with disjoint ranges (--samples-from K --spp N renders K..K+N-1) "
                     "merge with `facet merge`")
        ->check(CLI::Range(std::uint64_t(0), std::uint64_t(0xffffffffu)));
    render->add_option("--out", opt.out,
                       "Output image, linear 32-bit float: .exr (or .hdr, .tif, .pfm); the tone-mapped PNG is written "
                       "beside it with .png (so --out cannot be a .png); default out/<scene>.exr");
    render->add_option("--snapshot", opt.snapshot, "Write the image so far (and the report) every SECONDS")
        ->check(kFinite & kSeconds);
    render->add_option("--reference", opt.reference,
                       "Reference image (EXR/HDR) to measure the error against, per pass");
    render->add_option("--report", opt.report,
                       "Error-against-time report (CSV; .json summary and .svg plot beside it); default beside --out");
    render->add_option(
        "--film", opt.film,
        "Also save the film (the accumulated samples, docs/film-format.md) here at the end; without it "
        "the film is saved beside --out (.film) only when interrupted or when the image cannot be written");
    render->add_option("--resume", opt.resume,
                       "Continue the render saved in this film (same scene and settings; --spp and --time count its "
                       "samples and time too)");
    render->add_option("--exposure", opt.exposure, "Exposure of the PNG in stops")
        ->check(kFinite & CLI::Range(-30.0f, 30.0f));
    render
        ->add_option("--tonemap", opt.tonemap,
                     "Tone mapping of the PNG: clip (default; linear clamped to 1, sRGB-encoded) or filmic (a "
                     "sigmoid in stops, AgX-like: highlights roll off over 7 stops instead of clipping)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, ToneMap>{{"clip", ToneMap::Clip}, {"filmic", ToneMap::Filmic}}));
    render
        ->add_option("--aov", opt.aov,
                     "Extra layers of the EXR for denoisers and compositors, at the first non-specular hit: any of "
                     "albedo, normal, depth, comma-separated (albedo.R/G/B, normal.X/Y/Z, depth.Z)")
        ->delimiter(',')
        ->check(CLI::IsMember({"albedo", "normal", "depth"}));
    render->add_flag(
        "--generic", opt.generic,
        "Build the generic program (every feature, chosen at run time) instead of one specialised to the scene");
    render->add_flag("--quiet,-q", opt.quiet, "Print only errors and the final summary");

    MergeOptions merge;
    CLI::App* merge_cmd = app.add_subcommand(
        "merge", "Add up films of one scene holding disjoint sample ranges (docs/film-format.md) into one image");
    merge_cmd->add_option("films", merge.films, "Films written with --film")->required();
    merge_cmd->add_option("--out", merge.out, "Merged image (.exr; the PNG is written beside it)")->required();
    merge_cmd->add_option("--film", merge.film, "Also write the merged film here");
    merge_cmd->add_option("--exposure", merge.exposure, "Exposure of the PNG in stops")
        ->check(kFinite & CLI::Range(-30.0f, 30.0f));

    CompareOptions cmp;
    CLI::App* compare =
        app.add_subcommand("compare", "Error metrics (MSE, RMSE, relMSE) of an image against a reference");
    compare->add_option("image", cmp.image, "Image (EXR, HDR, ...)")->required();
    compare->add_option("reference", cmp.reference, "Reference image of the same size")->required();

    PlotOptions plot;
    CLI::App* plot_cmd = app.add_subcommand("plot", "Plot a render report's error against time (log-log SVG)");
    plot_cmd->add_option("report", plot.report, "CSV report written by `facet render`")->required();
    plot_cmd->add_option("--out", plot.out, "Output SVG (default: the report with .svg)");

    SkyOptions sky;
    CLI::App* sky_cmd =
        app.add_subcommand("sky", "Write the generated sun-and-sky environment map as EXR (docs/environment.md)");
    sky_cmd->add_option("out", sky.out, "Output EXR")->required();
    sky_cmd->add_option("--width", sky.width, "Width in texels (height is half)")->check(CLI::Range(8, 16384));
    sky_cmd->add_option("--elevation", sky.elevation, "Sun elevation in degrees")
        ->check(kFinite & CLI::Range(-10.0f, 90.0f));
    sky_cmd->add_option("--azimuth", sky.azimuth, "Sun azimuth in degrees")
        ->check(kFinite & CLI::Range(-360.0f, 360.0f));
    sky_cmd->add_option("--turbidity", sky.turbidity, "Atmospheric turbidity (Preetham's model)")
        ->check(kFinite & CLI::Range(1.7f, 10.0f));

    // A bare `facet`: the help, not "a subcommand is required".
    if (argc <= 1) {
        std::cout << app.help();
        return kExitOk;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // Prints the help, or the option and the problem ("--spp: Value 0 not in range"),
        // and for an unknown option the closest known one.
        const int status = app.exit(e) == 0 ? kExitOk : kExitUsage;
        if (dynamic_cast<const CLI::ExtrasError*>(&e)) suggest_options(app);
        return status;
    }
    try {
        if (*devices) return run_devices();
        if (*info) return run_info(info_opt);
        if (*render) return run_render(opt);
        if (*merge_cmd) return run_merge(merge);
        if (*compare) return run_compare(cmp);
        if (*plot_cmd) return run_plot(plot);
        if (*sky_cmd) return run_sky(sky);
    } catch (const Error& e) {
        std::fflush(stdout);
        std::cerr << "facet: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::cerr << "facet: internal error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace facet
