// Kernel specialisation, both sides of the trade: build time cold and warm, binary
// size, and samples per second, for the program specialised to each scene against the
// generic one, in one run.
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"

namespace facet {

nlohmann::json bench_specialisation(ClContext& ctx, const std::string& assets, bool quick) {
    namespace fs = std::filesystem;
    std::vector<std::pair<std::string, std::string>> scenes;
    for (const char* s : {"cornell_box.json", "material_grid.json", "spheres_sky.json"})
        scenes.push_back({s, (fs::path(FACET_SOURCE_DIR) / "scenes" / s).string()});
    fs::path dragon = fs::path(assets) / "dragon_stanford" / "dragon_vrip_res2.obj";
    if (fs::exists(dragon)) scenes.push_back({"dragon_res2.obj", dragon.string()});
    bench_print(
        "\n### Program build: kernel specialisation\n\nTime to first image = program build + the first launch (PoCL generates\n"
        "machine code at the first launch); cold: a nonce kernel defeats the driver's caches; warm: the\n"
        "same program again. The first row is the driver's own floor: a one-line program, cold.\n\n");
    bench_print("| scene | program | features | cold build + first launch s | warm s | binary KiB | Msamples/s |\n");
    bench_print("|---|---|---|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    const auto nonce = std::chrono::steady_clock::now().time_since_epoch().count();

    // The driver's floor: a one-line program, cold, built and launched once. It also pays
    // the driver's one-time set-up (PoCL loads its built-in library at the first build),
    // which would otherwise land on the first row.
    const double floor_s = [&] {
        auto start = std::chrono::steady_clock::now();
        cl::Program p(ctx.context(),
                      fmt::format("__kernel void fc_floor(__global int* o) {{ o[0] = {}; }}", nonce % 1000000007));
        p.build({ctx.device()}, default_build_options().c_str());
        cl::Kernel k(p, "fc_floor");
        cl::Buffer b(ctx.context(), CL_MEM_WRITE_ONLY, sizeof(cl_int));
        k.setArg(0, b);
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
        ctx.queue().finish();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }();
    bench_print("| (driver floor) | one-line kernel | — | {:.2f} | — | — | — |\n", floor_s);
    rows.push_back({{"scene", "(driver floor)"}, {"program", "one-line kernel"}, {"cold_first_image_s", floor_s}});
    for (const auto& [name, path] : scenes) {
        Scene scene = load_scene(path);
        scene.settings.width = scene.settings.height = quick ? 64 : 128;
        Bvh bvh = build_bvh(scene.vertices);
        for (bool generic : {true, false}) {
            FeatureMask mask = generic ? all_features() : scene_features(scene);
            std::vector<std::string> prelude = {fmt::format(
                "__kernel void fc_bench_nonce_{}(__global int* o) {{ o[0] = {}; }}", rows.size(), nonce % 1000000007)};
            auto first_image = [&] {
                auto start = std::chrono::steady_clock::now();
                Scene tiny = scene;
                tiny.settings.width = tiny.settings.height = 8;
                Renderer r(ctx, tiny, bvh, generic, prelude);
                render_fixed(r, 1);
                return std::pair{std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                                 r.build().program};
            };
            auto [cold_s, program] = first_image();
            const std::size_t binary_bytes = program_binary_bytes(program);  // outside the timed span
            double warm_s = first_image().first;
            Renderer r(ctx, scene, bvh, generic);
            render_fixed(r, 1);
            r.reset();
            std::uint32_t spp = quick ? 4 : 16;
            render_fixed(r, spp);
            double rate = double(spp) * double(r.pixel_count()) / r.stats().render_seconds * 1e-6;
            bench_print("| {} | {} | {} | {:.2f} | {:.3f} | {:.0f} | {:.3f} |\n", name,
                        generic ? "generic" : "specialised", describe_features(mask), cold_s, warm_s,
                        double(binary_bytes) / 1024.0, rate);
            std::fflush(stdout);
            rows.push_back({{"scene", name},
                            {"program", generic ? "generic" : "specialised"},
                            {"features", describe_features(mask)},
                            {"cold_first_image_s", cold_s},
                            {"warm_first_image_s", warm_s},
                            {"binary_bytes", binary_bytes},
                            {"msamples_per_s", rate}});
        }
    }
    return rows;
}

}  // namespace facet
