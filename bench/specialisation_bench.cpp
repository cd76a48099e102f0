// Kernel specialisation, both sides of the trade: build time cold and warm, binary
// size, and samples per second, for the program specialised to each scene against the
// generic one, in one run.
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench.hpp"
#include "bvh/bvh.hpp"
#include "render/features.hpp"
#include "render/renderer.hpp"
#include "scene/load.hpp"

namespace facet {

nlohmann::json bench_specialisation(ClContext& ctx, const std::string& assets, bool quick) {
    namespace fs = std::filesystem;
    std::vector<std::pair<std::string, std::string>> scenes;
    for (const char* s : {"cornell_box.json", "material_grid.json", "spheres_sky.json"})
        scenes.push_back({s, (fs::path(FACET_SOURCE_DIR) / "scenes" / s).string()});
    fs::path dragon = fs::path(assets) / "dragon_stanford" / "dragon_vrip_res2.obj";
    if (fs::exists(dragon)) scenes.push_back({"dragon_res2.obj", dragon.string()});
    bench_print("\n### Program build: kernel specialisation\n\nTime to first image = program build + the first launch (PoCL generates\n"
               "machine code at the first launch); cold: a nonce kernel defeats the driver's caches; warm: the\n"
               "same program again.\n\n");
    bench_print("| scene | program | features | cold build + first launch s | warm s | binary KiB | Msamples/s |\n");
    bench_print("|---|---|---|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    const auto nonce = std::chrono::steady_clock::now().time_since_epoch().count();
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
                r.render(1);
                return std::pair{std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                                 r.build().binary_bytes};
            };
            auto [cold_s, binary_bytes] = first_image();
            double warm_s = first_image().first;
            Renderer r(ctx, scene, bvh, generic);
            r.render(1);
            r.reset();
            std::uint32_t spp = quick ? 4 : 16;
            r.render(spp);
            double rate = double(spp) * double(r.pixel_count()) / r.stats().render_seconds * 1e-6;
            bench_print("| {} | {} | {} | {:.2f} | {:.3f} | {:.0f} | {:.3f} |\n", name, generic ? "generic" : "specialised",
                       describe_features(mask), cold_s, warm_s, double(binary_bytes) / 1024.0, rate);
            std::fflush(stdout);
            rows.push_back({{"scene", name}, {"program", generic ? "generic" : "specialised"},
                            {"features", describe_features(mask)}, {"cold_first_image_s", cold_s},
                            {"warm_first_image_s", warm_s}, {"binary_bytes", binary_bytes},
                            {"msamples_per_s", rate}});
        }
    }
    return rows;
}

}  // namespace facet
