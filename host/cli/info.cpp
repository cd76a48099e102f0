// `facet info SCENE`: what the scene holds and what it will need on the device.
#include <fmt/format.h>

#include <cstdlib>
#include <string>

#include "host/bvh/bvh.hpp"
#include "host/cli/commands.hpp"
#include "host/render/features.hpp"
#include "host/render/packet_paths.hpp"
#include "host/readers/load_scene.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"

namespace facet {

// How packet_pass traces its rays on 8-wide nodes (packet_trace_for), for `facet info`.
static std::string packet_rays_said(FeatureMask features, std::size_t triangles) {
    if (features & feature::kALPHA) return "their rays traced one by one (cut-outs)";
    const char* env = std::getenv("FACET_PACKET_TRACE");
    const std::string why = env && (std::string(env) == "0" || std::string(env) == "1")
                                ? fmt::format("FACET_PACKET_TRACE={}", env)
                                : fmt::format("{} triangles: in packets up to {}, each ray to the leaves up to {}",
                                              triangles, kPacketTraceUpToTriangles, kPacketTraceTogetherUpToTriangles);
    const bool together = packet_trace_for(triangles) && packet_trace_min_for(triangles) == 1u;
    return fmt::format("their rays traced {} ({}){}", packet_trace_for(triangles) ? "in packets" : "one by one", why,
                       together ? ", in a tree whose SAH counts leaf triangles, not blocks" : "");
}

int run_info(const InfoOptions& opt) {
    Scene scene = load_scene(opt.scene);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "facet: warning: {}\n", w);
    Bvh bvh = build_bvh(scene.vertices);
    const BvhStats& b = bvh.stats;
    const DeviceScene dev = compile(scene, bvh);  // with the shared meshes' trees and the instances
    const std::size_t bvh_bytes = scene.instances.empty() ? b.device_bytes
                                                          : dev.nodes.size_bytes() + dev.tris.size_bytes() +
                                                                dev.instancing.instances.size() * sizeof(FcInstance) +
                                                                dev.instancing.tree.size() * sizeof(FcBvhNode);
    std::size_t shading_bytes = dev.shading.size_bytes() + scene.materials.size() * sizeof(FcMaterial) +
                                scene.lights.size() * sizeof(FcLight) + scene.light_cdf.size() * sizeof(float);
    std::size_t film_bytes = 2 * std::size_t(scene.settings.width) * scene.settings.height * 16;  // two halves
    fmt::print("scene       {}\n", scene.source_path);
    if (scene.instances.empty()) {
        fmt::print("triangles   {}\n", scene.triangle_count());
    } else {
        fmt::print("triangles   {} in the world, {} on the device ({} + {} in shared meshes)\n",
                   scene.placed_triangle_count(), scene.stored_triangle_count(), scene.triangle_count(),
                   scene.stored_triangle_count() - scene.triangle_count());
        fmt::print(
            "instances   {} of {} shared meshes (meshes that emit light are copied into the world: lights "
            "are sampled in world space)\n",
            scene.instances.size(), scene.meshes.size());
    }
    if (!scene.spheres.empty()) fmt::print("spheres     {} (analytic)\n", scene.spheres.size());
    fmt::print("materials   {}\n", scene.materials.size());
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        bool emits = m.emission[0] > 0 || m.emission[1] > 0 || m.emission[2] > 0;
        fmt::print("  [{}] {:<20} {}{}\n", i, scene.material_names[i], describe_material(m),
                   emits
                       ? fmt::format(" emission ({:.3f}, {:.3f}, {:.3f})", m.emission[0], m.emission[1], m.emission[2])
                       : "");
    }
    for (const std::string& line : scene.normal_sources) fmt::print("normals     {}\n", line);
    std::size_t area = 0, punctual = 0;
    for (const FcLight& l : scene.lights) {
        if (l.type == FC_LIGHT_AREA_TRIANGLE) ++area;
        else if (l.type != FC_LIGHT_ENVIRONMENT) ++punctual;
    }
    fmt::print("lights      {} area (emitting triangles), {} punctual, environment: {}\n", area, punctual,
               !scene.environment.params.enabled ? "none"
               : scene.environment.params.width == 0
                   ? "constant"
                   : fmt::format("{}x{} map", scene.environment.params.width, scene.environment.params.height));
    const std::size_t texture_bytes = dev.texture_data.bytes();
    if (scene_uses_textures(scene))
        fmt::print("textures    {} images, {:.2f} MiB with mip-maps and uvs\n", scene.textures.size(),
                   double(texture_bytes) / (1 << 20));
    fmt::print("features    {}\n", describe_features(scene_features(scene)));
    fmt::print(
        "bvh         {} nodes, {} leaves, depth {}, max leaf {}, SAH cost {:.2f}, built in {:.3f} s ({}-wide{})\n",
        b.nodes, b.leaves, b.max_depth, b.max_leaf_size, b.sah_cost, b.build_seconds, b.width,
        b.width == 8 ? (b.quantised ? ", quantised boxes" : ", float boxes") : "");
    // What `facet render` builds on a CPU with 8-wide float vectors (bvh_width_for).
    BvhOptions wide;
    wide.width = 8;
    wide.layout_triangles = scene.stored_triangle_count();
    const char* forced = std::getenv("FACET_BVH_QUANTISED");
    fmt::print("bvh layout  8-wide on CPUs with 8-wide vectors, {} boxes ({}); 4-wide on GPUs\n",
               resolve_quantised(wide, wide.layout_triangles) ? "quantised" : "float",
               forced && *forced
                   ? fmt::format("FACET_BVH_QUANTISED={}", forced)
                   : fmt::format("{} triangles: quantised above {}", wide.layout_triangles, kQuantiseAboveTriangles));
    // How `facet render` runs the paths on such a CPU (packet_paths_for).
    DeviceDesc cpu;
    cpu.type = CL_DEVICE_TYPE_CPU;
    const char* packets_off = std::getenv("FACET_PACKET_PATHS");
    fmt::print("paths       {}\n",
               packet_paths_for(cpu, 8, scene_features(scene), lights_in_packets(scene), dev.params.sampler, false)
                   ? fmt::format("in packets of 8 on CPUs with 8-wide vectors, of 16 with 16-wide ones, {}{}; one "
                                 "a work-item on GPUs",
                                 lambertian_materials(scene)
                                     ? ""
                                     : "plain microfacet bases (docs/performance.md) in lanes, other BSDFs per lane, ",
                                 packet_rays_said(scene_features(scene), b.triangles))
               : packets_off && std::string(packets_off) == "0"
                   ? std::string("one a work-item (FACET_PACKET_PATHS=0)")
                   : fmt::format("one a work-item ({})", packet_paths_requirements()));
    fmt::print("image       {}x{}, {} spp, max depth {}\n", scene.settings.width, scene.settings.height,
               scene.settings.spp, scene.settings.max_depth);
    fmt::print("device mem  {:.2f} MiB (bvh {:.2f}, shading {:.2f}, textures {:.2f}, film {:.2f})\n",
               double(dev.bytes() + film_bytes) / (1 << 20),  // every array of kernels/shared/scene_arrays.h
               double(bvh_bytes) / (1 << 20), double(shading_bytes) / (1 << 20), double(texture_bytes) / (1 << 20),
               double(film_bytes) / (1 << 20));
    return kExitOk;
}

}  // namespace facet
