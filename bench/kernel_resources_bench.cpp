// The kernels' resources per work-item on the bench's device (issue 29): for the
// render, AOV and denoise programs as each demo scene builds them, the private and local
// memory the driver reports and, on NVIDIA, ptxas's registers, stack and spills. On a GPU
// these bound occupancy; on PoCL they show what a work-item keeps off the stack.
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/cl/kernel_resources.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/features.hpp"

namespace facet {

namespace {

std::string figure(int v) { return v < 0 ? "—" : std::to_string(v); }

}  // namespace

nlohmann::json bench_kernel_resources(ClContext& ctx, const BvhOptions& bvh_options) {
    namespace fs = std::filesystem;
    const bool verbose = !verbose_build_option(ctx.desc()).empty();
    bench_print(
        "\n### Kernel resources per work-item\n\nEach program as the scene's render builds it (specialised, BVH {}-wide), built from "
        "source. Private and local memory as the driver reports them (clGetKernelWorkGroupInfo); registers, stack "
        "and spills from ptxas ({}).\n\n",
        bvh_options.width, verbose ? "-cl-nv-verbose" : "NVIDIA's driver only: — here");
    Markdown md({"scene", "program", "kernel", "private B", "local B", "max work-group", "preferred multiple",
                 "registers", "stack B", "spill stores B", "spill loads B"});
    nlohmann::json rows = nlohmann::json::array();
    auto report = [&](const std::string& scene, const std::string& program, const std::vector<KernelResources>& ks) {
        for (const KernelResources& k : ks) {
            md.row({scene, program, k.kernel, std::to_string(k.private_bytes), std::to_string(k.local_bytes),
                    std::to_string(k.max_work_group), std::to_string(k.preferred_multiple), figure(k.ptxas.registers),
                    figure(k.ptxas.stack_bytes), figure(k.ptxas.spill_store_bytes), figure(k.ptxas.spill_load_bytes)});
            rows.push_back({{"scene", scene},
                            {"program", program},
                            {"kernel", k.kernel},
                            {"private_bytes", k.private_bytes},
                            {"local_bytes", k.local_bytes},
                            {"max_work_group", k.max_work_group},
                            {"preferred_multiple", k.preferred_multiple},
                            {"registers", k.ptxas.registers},
                            {"stack_bytes", k.ptxas.stack_bytes},
                            {"spill_store_bytes", k.ptxas.spill_store_bytes},
                            {"spill_load_bytes", k.ptxas.spill_load_bytes}});
        }
    };
    for (const char* name : {"cornell_box", "spheres_sky", "material_grid", "glass_metal_sky"}) {
        const fs::path path = fs::path(FACET_SOURCE_DIR) / "scenes" / (std::string(name) + ".json");
        const Scene scene = load_scene(path.string());
        const Bvh bvh = build_bvh(scene.vertices, bvh_options);
        const std::vector<std::string> prelude = scene_program_prelude(scene, bvh);
        report(name, "render", build_and_report_kernels(ctx, "kernels/integrator/path.cl", prelude));
        report(name, "aov", build_and_report_kernels(ctx, "kernels/aov/aov.cl", prelude));
    }
    report("(any)", "denoise", build_and_report_kernels(ctx, "kernels/denoise/denoise.cl"));
    bench_print("{}", md.str());
    return rows;
}

}  // namespace facet
