// Image-based lighting at equal time: BSDF sampling alone, environment sampling alone
// and MIS, on a diffuse and a glossy sphere under stiff maps. Error is the RMSE
// against a long MIS render of the same scene.
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench.hpp"
#include "bvh/bvh.hpp"
#include "film/error_metrics.hpp"
#include "render/renderer.hpp"
#include "scene/material.hpp"
#include "scene/scene.hpp"
#include "scene/sky.hpp"

namespace facet {
namespace {

Scene spheres_under(const EnvironmentMap& env) {
    Scene scene;
    FcMaterial diffuse = make_material("lambert");
    FcMaterial glossy = make_material("ggx");
    glossy.alpha_x = glossy.alpha_y = 0.1f;
    for (int c = 0; c < 3; ++c) diffuse.diffuse[c] = 0.7f, glossy.diffuse[c] = 0.2f, glossy.specular[c] = 0.5f;
    add_material(scene, diffuse, "diffuse");
    add_material(scene, glossy, "glossy");
    add_sphere(scene, glm::vec3(-1.1f, 0.0f, 0.0f), 1.0f, 4, 0, false);
    add_sphere(scene, glm::vec3(1.1f, 0.0f, 0.0f), 1.0f, 4, 1, false);
    scene.environment = env;
    scene.camera.eye = glm::vec3(0.0f, 0.5f, 6.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fov_y_degrees = 30.0f;
    scene.settings.width = 96;
    scene.settings.height = 64;
    scene.settings.max_depth = 4;
    return scene;
}

// Renders for `seconds` (in passes of `pass` samples); returns the image and its spp.
std::vector<float> render_for(ClContext& ctx, Scene scene, int strategy, double seconds, std::uint32_t pass,
                              std::uint64_t* spp) {
    scene.settings.strategy = strategy;
    build_lights(scene);
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(ctx, scene, bvh);
    while (r.stats().render_seconds < seconds) r.render(pass);
    *spp = r.stats().samples_per_pixel;
    return r.image();
}

}  // namespace

nlohmann::json bench_ibl(ClContext& ctx, const std::string& assets, bool quick) {
    namespace fs = std::filesystem;
    std::vector<std::pair<std::string, EnvironmentMap>> maps;
    maps.push_back({"generated sun-sky", sun_sky_environment(SunSkyParams{}, 1024)});
    set_environment_scale(maps.back().second, glm::vec3(0.05f));
    for (const char* name : {"sunrise.exr", "city.exr"}) {
        fs::path p = fs::path(assets) / "env_blender" / name;
        if (!fs::exists(p)) {
            bench_print("skipping {}: not found\n", p.string());
            continue;
        }
        std::vector<std::string> warnings;
        maps.push_back({name, load_environment_map(p.string(), glm::vec3(1.0f), glm::mat3(1.0f), warnings)});
    }
    const double budget = quick ? 0.5 : 2.0;
    bench_print("\n### Equal-time IBL ({:.1f} s each; RMSE against a {:.0f} s MIS render)\n\n", budget, budget * 8);
    bench_print("| map | BSDF only RMSE (spp) | light only RMSE (spp) | MIS RMSE (spp) |\n|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    for (auto& [name, env] : maps) {
        Scene scene = spheres_under(env);
        std::uint64_t ref_spp = 0;
        std::vector<float> ref = render_for(ctx, scene, FC_STRATEGY_MIS, budget * 8, 16, &ref_spp);
        nlohmann::json row{{"map", name}, {"reference_spp", ref_spp}};
        std::string line = fmt::format("| {} |", name);
        for (auto [label, strategy] : {std::pair{"bsdf", FC_STRATEGY_BSDF}, std::pair{"light", FC_STRATEGY_LIGHT},
                                       std::pair{"mis", FC_STRATEGY_MIS}}) {
            std::uint64_t spp = 0;
            Scene s = scene;
            s.settings.seed = 1234;   // independent of the reference's samples
            std::vector<float> img = render_for(ctx, s, strategy, budget, 4, &spp);
            double rmse = compare_images(img, ref).rmse;
            row[label] = {{"rmse", rmse}, {"spp", spp}};
            line += fmt::format(" {:.4g} ({}) |", rmse, spp);
        }
        bench_print("{}\n", line);
        std::fflush(stdout);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace facet
