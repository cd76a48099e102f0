// Image-based lighting: the cost of the environment's sampling distribution (its build on
// the host, env_sample on the device), then equal time for BSDF sampling alone,
// environment sampling alone, MIS and MIS with MIS compensation (Karlik et al. 2019), on a
// diffuse and a glossy sphere under stiff maps.
// Error is the RMSE against a long MIS render of the same scene.
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/film/error_metrics.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/sky.hpp"

namespace facet {
namespace {

Scene spheres_under(const EnvironmentMap& env) {
    Scene scene;
    Material diffuse = make_material("lambert");
    Material glossy = make_material("ggx");
    glossy.alpha_x = glossy.alpha_y = 0.1f;
    for (int c = 0; c < 3; ++c) diffuse.diffuse[c] = 0.7f, glossy.diffuse[c] = 0.2f, glossy.f0[c] = 0.5f;
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
    ProgressiveOptions po;
    po.target_spp = std::uint64_t(1) << 40;
    po.time_limit_s = seconds;
    po.fixed_pass = pass;
    render_progressive(r, po);
    *spp = r.stats().samples_per_pixel;
    return r.image();
}

// Host milliseconds to build the map's sampling distribution (best of 3), and device
// env_sample calls per second.
std::pair<double, double> sampling_cost(ClContext& ctx, const cl::Program& program, EnvironmentMap env, bool quick) {
    double build_ms = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
        auto t0 = std::chrono::steady_clock::now();
        build_environment_distribution(env);
        build_ms = std::min(build_ms,
                            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    const cl::Context& c = ctx.context();
    cl::Buffer params(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcEnvironment), &env.params);
    cl::Buffer texels(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, env.texels.size() * sizeof(float), env.texels.data());
    cl::Buffer dist(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, env.distribution.size() * sizeof(float),
                    env.distribution.data());
    const std::size_t items = quick ? (1u << 14) : (1u << 16);
    const cl_uint per_item = 64;
    cl::Buffer out(c, CL_MEM_WRITE_ONLY, items * sizeof(float));
    cl::Kernel k(program, "env_sample_throughput");
    k.setArg(0, params);
    k.setArg(1, texels);
    k.setArg(2, dist);
    k.setArg(3, cl_uint(5));
    k.setArg(4, per_item);
    k.setArg(5, out);
    double best_s = 1e30;
    for (int rep = 0; rep < 4; ++rep) {  // the first launch warms up
        auto t0 = std::chrono::steady_clock::now();
        ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(items), cl::NDRange(64));
        ctx.queue().finish();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (rep > 0) best_s = std::min(best_s, s);
    }
    return {build_ms, double(items) * per_item / best_s * 1e-6};
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
    nlohmann::json sampling = nlohmann::json::array();
    {
        bench_print(
            "\n### Environment sampling (distribution built on one host thread, best of 3; env_sample on the device)\n\n");
        bench_print("| map | size | distribution build ms | env_sample M/s |\n|---|---|---|---|\n");
        cl::Program program = build_program(ctx, "kernels/bench/ibl_bench.cl").program;
        std::vector<std::pair<std::string, EnvironmentMap>> timed = {
            {"generated sun-sky", sun_sky_environment(SunSkyParams{}, quick ? 1024 : 2048)}};
        for (std::size_t i = 1; i < maps.size(); ++i) timed.push_back(maps[i]);
        for (auto& [name, env] : timed) {
            auto [build_ms, rate] = sampling_cost(ctx, program, env, quick);
            bench_print("| {} | {}x{} | {:.1f} | {:.1f} |\n", name, env.params.width, env.params.height, build_ms,
                        rate);
            std::fflush(stdout);
            sampling.push_back({{"map", name},
                                {"width", env.params.width},
                                {"height", env.params.height},
                                {"distribution_build_ms", build_ms},
                                {"env_sample_m_per_s", rate}});
        }
    }
    const double budget = quick ? 0.5 : 2.0;
    bench_print("\n### Equal-time IBL ({:.1f} s each; RMSE against a {:.0f} s MIS render)\n\n", budget, budget * 8);
    bench_print(
        "| map | BSDF only RMSE (spp) | light only RMSE (spp) | MIS RMSE (spp) | MIS compensated RMSE (spp) "
        "|\n|---|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    for (auto& [name, env] : maps) {
        Scene scene = spheres_under(env);
        std::uint64_t ref_spp = 0;
        std::vector<float> ref = render_for(ctx, scene, FC_STRATEGY_MIS, budget * 8, 16, &ref_spp);
        nlohmann::json row{{"map", name}, {"reference_spp", ref_spp}};
        std::string line = fmt::format("| {} |", name);
        for (auto [label, strategy] :
             {std::pair{"bsdf", FC_STRATEGY_BSDF}, std::pair{"light", FC_STRATEGY_LIGHT},
              std::pair{"mis", FC_STRATEGY_MIS}, std::pair{"mis_compensated", FC_STRATEGY_MIS}}) {
            std::uint64_t spp = 0;
            Scene s = scene;
            // MIS compensation (environment_map.hpp) only in its own column
            s.environment.sampling =
                std::string(label) == "mis_compensated" ? EnvironmentSampling::compensated : EnvironmentSampling::plain;
            s.settings.seed = 1234;  // independent of the reference's samples
            std::vector<float> img = render_for(ctx, s, strategy, budget, 4, &spp);
            double rmse = compare_images(img, ref).rmse;
            row[label] = {{"rmse", rmse}, {"spp", spp}};
            line += fmt::format(" {:.4g} ({}) |", rmse, spp);
        }
        bench_print("{}\n", line);
        std::fflush(stdout);
        rows.push_back(row);
    }
    return {{"sampling", sampling}, {"equal_time", rows}};
}

}  // namespace facet
