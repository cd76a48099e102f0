// `facet devices | info | render`: argument parsing and dispatch.
#include "host/cli/cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <span>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "host/cli/cli_words.hpp"
#include "host/cli/commands.hpp"
#include "host/scene/smooth_normals.hpp"
#include "host/error.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/scene/scene.hpp"
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

// The choices of a closed list of render settings (scene/render_names.hpp), in list order.
std::vector<std::pair<std::string, long long>> setting_choices(std::span<const SettingName> table) {
    std::vector<std::pair<std::string, long long>> out;
    for (const SettingName& n : table) out.emplace_back(std::string(n.name), n.value);
    return out;
}

std::vector<std::pair<std::string, long long>> pixel_filter_choices() {
    std::vector<std::pair<std::string, long long>> c;
    for (const PixelFilterInfo& f : kPixelFilters) c.emplace_back(f.name, f.code);
    return c;
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

// When no command was recognised: the first word given names none. Says so, with the
// commands in words and the closest one; false when there is no such word.
bool refuse_unknown_command(const CLI::App& app) {
    if (!app.get_subcommands().empty()) return false;
    for (const std::string& word : app.remaining()) {
        if (word.empty() || word[0] == '-') continue;
        std::vector<std::string> names;
        for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
        const std::string near = closest_name(word, names);
        std::cerr << fmt::format("facet: {} is not a command: one of {}{}\nRun facet --help for more information.\n",
                                 word, or_list(names), near.empty() ? "" : fmt::format(" (did you mean {}?)", near));
        return true;
    }
    return false;
}

}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"facet: a physically based path tracer running as OpenCL kernels", "facet"};
    app.formatter(plain_formatter());  // before the subcommands, which take it
    app.require_subcommand(1);
    app.add_flag_callback(
        "--version",
        [] {
            std::cout << version_report();
            throw CLI::Success();
        },
        "Print the version, the git commit and build type it was built from, and the OpenCL platforms and "
        "devices found, and exit");
    const RenderSettings defaults;  // what a scene that does not say gets

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
    render
        ->add_option("--spp", opt.spp,
                     fmt::format("Samples per pixel, 1 to {} (default: the scene's, else {}; none with --time alone)",
                                 limits::kSpp.hi, defaults.spp))
        ->check(in_range(limits::kSpp));
    render
        ->add_option("--time", opt.time_limit,
                     "Seconds of rendering: alone, the render stops at this time (the scene's spp does not stop "
                     "it); with --spp, whichever ends first (default: no time limit)")
        ->option_text("SECONDS")
        ->check(kFinite & kSeconds);
    render
        ->add_option("--noise-threshold", opt.noise_threshold,
                     "Adaptive stopping: end once the reference-free error estimate (relMSE of the two half-images, "
                     "from 16 spp on) is at most RELMSE (whichever of --spp, --time and this ends first; default: off)")
        ->option_text("RELMSE")
        ->check(kFinite & positive_up_to(1e30, "relMSE"));
    render
        ->add_option("--adaptive", opt.adaptive,
                     "With --noise-threshold: global (default; the whole image stops at once) or tiles (after 16 "
                     "spp, bands of 8 rows whose own estimate is above the threshold get their samples doubled, "
                     "round after round)")
        ->option_text("global|tiles")
        ->transform(choice("an adaptive mode", {{"global", int(RenderOptions::Adaptive::Global)},
                                                {"tiles", int(RenderOptions::Adaptive::Tiles)}}))
        ->needs("--noise-threshold");
    render
        ->add_option("--width", opt.width,
                     fmt::format("Image width in pixels, 1 to {} (default: the scene's, else {}; with --resume, the "
                                 "film's)",
                                 limits::kWidth.hi, defaults.width))
        ->check(in_range(limits::kWidth));
    render
        ->add_option("--height", opt.height,
                     fmt::format("Image height in pixels, 1 to {} (default: the scene's, else {}; with --resume, "
                                 "the film's)",
                                 limits::kHeight.hi, defaults.height))
        ->check(in_range(limits::kHeight));
    render
        ->add_option("--max-depth", opt.max_depth,
                     fmt::format("Maximum number of bounces, 1 to {} (1: direct light only; default: the scene's, "
                                 "else {})",
                                 limits::kMaxDepth.hi, defaults.max_depth))
        ->check(in_range(limits::kMaxDepth));
    render
        ->add_option("--seed", opt.seed,
                     fmt::format("Seed of the random stream, 0 to {} (same seed and settings give the same image; "
                                 "default: the scene's, else {})",
                                 limits::kSeed.hi, defaults.seed))
        ->check(in_range(limits::kSeed));
    render
        ->add_option("--strategy", opt.strategy,
                     "Direct light from area lights and the environment: mis (default), light (light sampling only) "
                     "or bsdf (BSDF sampling only); for measuring the strategies")
        ->option_text("mis|light|bsdf")
        ->transform(choice("a strategy", setting_choices(kStrategyNames)));
    render
        ->add_option("--env-sampling", opt.env_plain,
                     "Environment map sampling under MIS: compensated (default; MIS compensation, Karlik et al. "
                     "2019) or plain (by luminance)")
        ->option_text("compensated|plain")
        ->transform(choice("an environment sampling", {{"compensated", 0}, {"plain", 1}}));
    render
        ->add_option(
            "--env", opt.env,
            "Environment light, replacing the scene's: an equirectangular .exr or .hdr map, sky (the generated "
            "sun and sky), white (uniform) or none (default: the scene's; a bare model with no lights gets a "
            "key light and a white environment of radiance 0.5)")
        ->option_text("FILE|sky|white|none");
    render
        ->add_option("--env-rotation", opt.env_rotation,
                     "With --env: turn the environment this many degrees about the vertical (+y) axis (default 0)")
        ->option_text("DEGREES")
        ->check(kFinite)
        ->needs("--env");
    render
        ->add_option("--env-strength", opt.env_strength,
                     "With --env: multiply its radiance by X, 0 to 1e6 (default 1; for sky 1/32, which brings a "
                     "sunlit white surface near 1)")
        ->option_text("X")
        ->check(kFinite & CLI::Range(0.0, 1e6))
        ->needs("--env");
    std::string smooth_normals_text;  // CLI11 needs a target; the value is read in each()
    render
        ->add_flag(fmt::format("--smooth-normals{{{:g}}}", kDefaultSmoothAngle), smooth_normals_text,
                   fmt::format("Recompute every triangle's shading normals, smooth across edges where faces meet at "
                               "less than ANGLE degrees, 0 to 180, and sharp where they meet at more (replaces the "
                               "file's normals; a bare --smooth-normals uses {:g}, Blender's auto-smooth angle; give "
                               "another as --smooth-normals=ANGLE)",
                               kDefaultSmoothAngle))
        ->option_text("[=ANGLE]")
        ->check(kFinite & CLI::Range(0.0, 180.0))
        ->each([&opt](const std::string& v) { opt.smooth_normals = std::stof(v); });
    render
        ->add_option("--sampler", opt.sampler,
                     "Sample generator: sobol (default; Owen-scrambled Sobol', Burley 2020) or independent (PCG32)")
        ->option_text("sobol|independent")
        ->transform(choice("a sampler", setting_choices(kSamplerNames)));
    render
        ->add_option("--filter", opt.filter,
                     "Pixel filter, drawn by filter importance sampling: " + pixel_filter_help() +
                         "; default: the scene's, else box")
        ->option_text("NAME")
        ->transform(choice("a pixel filter", pixel_filter_choices()));
    render
        ->add_option(
            "--filter-radius", opt.filter_radius,
            fmt::format("Radius of the pixel filter in pixels, at most {:g} (default: the filter's)", kMaxFilterRadius))
        ->option_text("PIXELS")
        ->check(kFinite & positive_up_to(kMaxFilterRadius, "pixels"));
    render
        ->add_option("--clamp", opt.clamp,
                     "Clamp each sample's contribution to this value (its largest channel): fewer fireflies, but "
                     "biased (darker); off by default, recorded in the EXR metadata and the report")
        ->option_text("X")
        ->check(kFinite & positive_up_to(FC_MAX_RADIANCE, "radiance"));
    render
        ->add_option("--caustic-guide", opt.caustic_guide,
                     fmt::format("Share of a Lambertian surface's sampled directions drawn toward the glass in the "
                                 "scene (its bounds; through smooth glass balls, toward the environment's light), for "
                                 "caustics seen by diffuse surfaces; a fifth of it at rough metals and plastics, half "
                                 "of that toward the balls' glints; unbiased at any value, 0 to {:g} (default: the "
                                 "scene's, else 0.25; 0: the BSDF alone; docs/sampling.md)",
                                 limits::kMaxCausticGuide))
        ->option_text("F")
        ->check(kFinite & CLI::Range(0.0, limits::kMaxCausticGuide));
    render
        ->add_option("--roulette-gain", opt.roulette_gain,
                     "Russian roulette's survival per unit of throughput: after the scene's rr_depth bounces a path "
                     "goes on with probability min(X * its throughput's largest channel, 0.95); higher keeps more "
                     "paths (longer samples, less noise each); unbiased at any value (default: the scene's, else 2; "
                     "1: pbrt-v4's and Mitsuba 3's rule; docs/sampling.md)")
        ->option_text("X")
        ->check(kFinite & positive_up_to(limits::kMaxRouletteGain, "gain"));
    render->add_option("--camera", opt.camera, "A glTF file's camera by name (default: the first one)")
        ->option_text("NAME");
    render->add_option("--eye", opt.eye, "Camera position X,Y,Z (default: the scene's; a bare mesh is framed to fit)")
        ->option_text("X,Y,Z")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite);
    render->add_option("--target", opt.target, "Point the camera looks at, X,Y,Z (default: the scene's)")
        ->option_text("X,Y,Z")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite);
    render->add_option("--up", opt.up, "Camera up direction X,Y,Z (default: the scene's, else +y)")
        ->option_text("X,Y,Z")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite);
    render
        ->add_option("--fov", opt.fov,
                     fmt::format("Vertical field of view in degrees, between 0 and 180 (perspective; default: the "
                                 "scene's, else {:g})",
                                 CameraDesc{}.fov_y_degrees))
        ->option_text("DEGREES")
        ->check(kFinite & CLI::Validator(
                              [](std::string& text) {
                                  const double v = std::strtod(text.c_str(), nullptr);
                                  return v > 0.0 && v < 180.0
                                             ? std::string()
                                             : fmt::format("Value {} is not a number of degrees in (0, 180)", text);
                              },
                              "DEGREES in (0, 180)"));
    render
        ->add_option("--aperture", opt.aperture,
                     "Thin-lens radius in scene units, 0 or more, for depth of field (default: the scene's, else 0: "
                     "a pinhole)")
        ->option_text("RADIUS")
        ->check(kFinite & CLI::Validator(
                              [](std::string& text) {
                                  return std::strtod(text.c_str(), nullptr) >= 0.0
                                             ? std::string()
                                             : fmt::format("Value {} is not a number >= 0", text);
                              },
                              "RADIUS >= 0"));
    render
        ->add_option("--focus-distance", opt.focus_distance,
                     "Distance of the plane in focus along the view direction (default: the scene's, else the distance "
                     "to --target; when the target is nearer than anything in view, the distance to the surface at "
                     "the image centre)")
        ->option_text("DISTANCE")
        ->check(kFinite & positive_up_to(1e30f, "scene units"));
    render
        ->add_option("--device", opt.device,
                     "OpenCL device: index from `facet devices` or part of its name (default: first GPU, else CPU); "
                     "several render together: all, gpu, cpu, or a list such as 0,2 (docs/devices.md)")
        ->option_text("DEVICE");
    render
        ->add_option("--samples-from", opt.samples_from,
                     "First sample index: renders with disjoint ranges (--samples-from K --spp N renders K..K+N-1) "
                     "merge with `facet merge` (0 to 4294967295; default: 0)")
        ->option_text("K")
        ->check(between(0.0, 4294967295.0));
    render
        ->add_option("--out", opt.out,
                     "Output image, linear 32-bit float: .exr (or .hdr, .tif, .pfm); the tone-mapped PNG is written "
                     "beside it with .png (so --out cannot be a .png); default out/<scene>.exr")
        ->option_text("FILE");
    render
        ->add_option("--snapshot", opt.snapshot,
                     "Write the image so far (and the report) every SECONDS (default: only at the end)")
        ->option_text("SECONDS")
        ->check(kFinite & kSeconds);
    render
        ->add_option("--reference", opt.reference,
                     "Reference image (EXR/HDR) to measure the error against, per pass (default: none)")
        ->option_text("FILE");
    render
        ->add_option("--report", opt.report,
                     "Error-against-time report (CSV; .json summary and .svg plot beside it); default beside --out")
        ->option_text("FILE");
    render
        ->add_option("--film", opt.film,
                     "Also save the film (the accumulated samples, docs/film-format.md) here at the end; without it "
                     "the film is saved beside --out (.film) only when interrupted or when the image cannot be written")
        ->option_text("FILE");
    render
        ->add_option("--resume", opt.resume,
                     "Continue the render saved in this film (same scene and settings, its size when --width and "
                     "--height are not given; --spp and --time count its samples and time too)")
        ->option_text("FILE");
    render->add_option("--exposure", opt.exposure, "Exposure of the PNG in stops, -30 to 30 (default: 0)")
        ->option_text("STOPS")
        ->check(kFinite & between(-30.0, 30.0));
    render
        ->add_option("--tonemap", opt.tonemap,
                     "Tone mapping of the PNG: clip (default; linear clamped to 1, sRGB-encoded) or filmic (a "
                     "sigmoid in stops, AgX-like: highlights roll off over 7 stops instead of clipping)")
        ->option_text("clip|filmic")
        ->transform(choice("a tone mapping", {{"clip", int(ToneMap::Clip)}, {"filmic", int(ToneMap::Filmic)}}));
    render
        ->add_option("--aov", opt.aov,
                     "Extra layers of the EXR for denoisers and compositors, at the first non-specular hit: any of "
                     "albedo, normal, depth, comma-separated (albedo.R/G/B, normal.X/Y/Z, depth.Z); default: none")
        ->option_text("LAYERS")
        ->delimiter(',')
        ->check(one_of("a layer", {"albedo", "normal", "depth"}));
    render
        ->add_option("--denoise", opt.denoise,
                     "Also write the image denoised, as NAME.denoised.exr and its PNG beside --out (the noisy image "
                     "is kept): facet (its own feature-guided denoiser, on the render's device), oidn (Intel Open "
                     "Image Denoise, when installed), auto (OIDN when found, else facet; the value when --denoise is "
                     "given alone) or none (default)")
        ->option_text("auto|facet|oidn|none")
        ->expected(0, 1)
        ->check(one_of("a denoiser", {"auto", "facet", "oidn", "none"}));
    render
        ->add_option("--oidn", opt.oidn,
                     "The Intel Open Image Denoise library for --denoise oidn or auto (default: $FACET_OIDN, else "
                     "the one of an installed pyoidn (pip install pyoidn), else libOpenImageDenoise.so.2 on the "
                     "loader's path)")
        ->option_text("LIBRARY");
    render->add_flag(
        "--generic", opt.generic,
        "Build the generic program (every feature, chosen at run time) instead of one specialised to the scene");
    render->add_flag("--quiet,-q", opt.quiet, "Print only errors and the final summary");
    render->add_flag("--strict", opt.strict,
                     "Refuse a scene whose assets are missing or unreadable (a texture, an OBJ's material library) "
                     "instead of warning and rendering without them (a missing colour texture shows as a magenta "
                     "and black checker)");

    DenoiseOptions denoise;
    CLI::App* denoise_cmd =
        app.add_subcommand("denoise", "Denoise an EXR rendered with --aov albedo,normal[,depth] (docs/denoising.md)");
    denoise_cmd->add_option("image", denoise.image, "The EXR, with its albedo and normal layers")->required();
    denoise_cmd->add_option("--film", denoise.film,
                            "The render's film (--film): its two half-images, which facet's denoiser and the error "
                            "estimate need");
    denoise_cmd->add_option("--out", denoise.out,
                            "The denoised image (default: IMAGE's name with .denoised; the PNG is written beside it)");
    denoise_cmd
        ->add_option("--denoiser", denoise.denoiser,
                     "facet, oidn or auto (default: OIDN when found, else facet's denoiser)")
        ->option_text("auto|facet|oidn")
        ->check(one_of("a denoiser", {"auto", "facet", "oidn"}));
    denoise_cmd->add_option("--oidn", denoise.oidn, "The Intel Open Image Denoise library (as facet render --oidn)")
        ->option_text("LIBRARY");
    denoise_cmd->add_option("--device", denoise.device, "The OpenCL device of facet's denoiser (as facet render)");
    denoise_cmd->add_option("--exposure", denoise.exposure, "Exposure of the PNG in stops, -30 to 30 (default: 0)")
        ->option_text("STOPS")
        ->check(kFinite & between(-30.0, 30.0));

    MergeOptions merge;
    CLI::App* merge_cmd = app.add_subcommand(
        "merge", "Add up films of one scene holding disjoint sample ranges (docs/film-format.md) into one image");
    merge_cmd->add_option("films", merge.films, "Films written with --film")->required();
    merge_cmd->add_option("--out", merge.out, "Merged image (.exr; the PNG is written beside it)")->required();
    merge_cmd->add_option("--film", merge.film, "Also write the merged film here");
    merge_cmd->add_option("--exposure", merge.exposure, "Exposure of the PNG in stops, -30 to 30 (default: 0)")
        ->option_text("STOPS")
        ->check(kFinite & between(-30.0, 30.0));

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
    sky_cmd
        ->add_option("--width", sky.width,
                     fmt::format("Width in texels, 8 to 16384 (height is half; default: {})", sky.width))
        ->check(between(8, 16384));
    sky_cmd
        ->add_option("--elevation", sky.elevation,
                     fmt::format("Sun elevation in degrees, -10 to 90 (default: {:g})", sky.elevation))
        ->check(kFinite & between(-10.0, 90.0));
    sky_cmd
        ->add_option("--azimuth", sky.azimuth,
                     fmt::format("Sun azimuth in degrees, -360 to 360 (default: {:g})", sky.azimuth))
        ->check(kFinite & between(-360.0, 360.0));
    sky_cmd
        ->add_option("--turbidity", sky.turbidity,
                     fmt::format("Atmospheric turbidity (Preetham's model), 1.7 to 10 (default: {:g})", sky.turbidity))
        ->check(kFinite & between(1.7, 10.0));

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
        if (!dynamic_cast<const CLI::Success*>(&e) && refuse_unknown_command(app)) return kExitUsage;
        if (const auto* c = dynamic_cast<const CLI::ConversionError*>(&e)) {
            const std::string words = conversion_words(app, *c);
            if (!words.empty()) {
                std::cerr << words << "\nRun with --help for more information.\n";
                return kExitUsage;
            }
        }
        const int status = app.exit(e) == 0 ? kExitOk : kExitUsage;
        if (dynamic_cast<const CLI::ExtrasError*>(&e)) suggest_options(app);
        return status;
    }
    try {
        if (*devices) return run_devices();
        if (*info) return run_info(info_opt);
        if (*render) {
            if (opt.denoise.empty()) opt.denoise = "auto";  // --denoise alone
            return run_render(opt);
        }
        if (*merge_cmd) return run_merge(merge);
        if (*denoise_cmd) return run_denoise(denoise);
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
