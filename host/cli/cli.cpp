// `facet devices | info | render`: argument parsing and dispatch.
#include "cli/cli.hpp"

#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "error.hpp"

namespace facet {

int run_cli(int argc, char** argv) {
    CLI::App app{"facet: a physically based path tracer running as OpenCL kernels"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "facet 0.1.0");

    CLI::App* devices = app.add_subcommand("devices", "List OpenCL platforms and devices");

    InfoOptions info_opt;
    CLI::App* info = app.add_subcommand("info", "Print what a scene holds: triangles, materials, lights, BVH");
    info->add_option("scene", info_opt.scene, "Scene file (.json) or mesh (.obj)")->required();

    RenderOptions opt;
    CLI::App* render = app.add_subcommand("render", "Render a scene progressively to EXR + PNG");
    render->add_option("scene", opt.scene, "Scene file (.json) or mesh (.obj)")->required();
    render->add_option("--spp", opt.spp, "Samples per pixel (default: the scene's)")->check(CLI::Range(1, 1 << 24));
    render->add_option("--time", opt.time_limit, "Stop after this many seconds of rendering (whichever of --spp and --time ends first)")
        ->check(CLI::PositiveNumber);
    render->add_option("--width", opt.width, "Image width in pixels (default: the scene's)")->check(CLI::Range(1, 16384));
    render->add_option("--height", opt.height, "Image height in pixels (default: the scene's)")->check(CLI::Range(1, 16384));
    render->add_option("--max-depth", opt.max_depth, "Maximum number of bounces (1 = direct light only)")
        ->check(CLI::Range(1, 1024));
    render->add_option("--seed", opt.seed, "Seed of the random stream (same seed and settings give the same image)");
    render->add_option("--device", opt.device, "OpenCL device: index from `facet devices` or part of its name (default: first GPU, else CPU)");
    render->add_option("--out", opt.out, "Output EXR (a tone-mapped PNG is written beside it); default out/<scene>.exr");
    render->add_option("--exposure", opt.exposure, "Exposure of the PNG in stops")->check(CLI::Range(-30.0f, 30.0f));
    render->add_flag("--quiet,-q", opt.quiet, "Print only errors and the final summary");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // Prints the help, or the option and the problem ("--spp: Value 0 not in range").
        return app.exit(e) == 0 ? kExitOk : kExitUsage;
    }
    try {
        if (*devices) return run_devices();
        if (*info) return run_info(info_opt);
        if (*render) return run_render(opt);
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
