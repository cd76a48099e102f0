// Users' assets (issue 15): load time and device memory of glTF, PLY and textured OBJ
// files, the texel pool in its compact formats against the float4 texels it replaced,
// and samples per second with and without the textures (the same scene with every
// material's textures dropped). Figures only.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/texture.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct AssetCase {
    std::string name;
    std::string path;
    std::string texture;  // bound as every material's base colour when not empty (an OBJ without an MTL)
};

// Bytes of every array the renderer uploads but the image.
std::uint64_t device_bytes(const DeviceScene& d) { return d.bytes(); }

double mib(std::uint64_t bytes) { return double(bytes) / double(1u << 20); }

// Msamples/s of the path tracer on `scene` at size² (one warm-up sample, then `spp`).
double samples_per_second(ClContext& ctx, Scene scene, const Bvh& bvh, int size, std::uint32_t spp) {
    scene.settings.width = scene.settings.height = size;
    Renderer r(ctx, scene, bvh);
    render_fixed(r, 1);
    r.reset();
    render_fixed(r, spp);
    return double(spp) * size * size / r.stats().render_seconds * 1e-6;
}

}  // namespace

nlohmann::json bench_assets(ClContext& ctx, const std::string& assets, bool quick) {
    const std::string models = "/usr/share/assimp/models/glTF2";
    const std::vector<AssetCase> cases = {
        {"dragon (PLY, gzip'd ASCII)", (fs::path(assets) / "dragon_stanford" / "dragon_vrip.ply.gz").string(), ""},
        {"2CylinderEngine (glb)", models + "/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", ""},
        {"BoxTextured (glTF + PNG)", models + "/BoxTextured-glTF/BoxTextured.gltf", ""},
        {"spot (OBJ + spot.png as base colour)", (fs::path(assets) / "meshes_common3d" / "spot.obj").string(),
         (fs::path(assets) / "meshes_common3d" / "spot.png").string()},
    };
    const int size = quick ? 96 : 192;
    const std::uint32_t spp = quick ? 2 : 8;
    bench_print("\n### Assets: load time, device memory, samples/s with and without textures ({}², {} spp)\n\n", size,
                spp);
    Markdown md({"asset", "triangles", "textures", "load s", "device MiB", "texel pool MiB", "as float4 texels MiB",
                 "Msamples/s textured", "Msamples/s untextured"});
    nlohmann::json rows = nlohmann::json::array();
    for (const AssetCase& c : cases) {
        if (!fs::exists(c.path) || (!c.texture.empty() && !fs::exists(c.texture))) {
            bench_print("skipping {}: {} not found\n", c.name, c.path);
            continue;
        }
        fmt::print("  [{}]\n", c.name);
        std::fflush(stdout);
        const auto start = Clock::now();
        Scene scene = load_scene(c.path);
        if (!c.texture.empty()) {
            const int t = add_texture(scene, c.texture, TextureSpace::Color, c.name);
            for (Material& m : scene.materials) m.textures.base_color = t;
        }
        const double load_s = std::chrono::duration<double>(Clock::now() - start).count();
        Bvh bvh = build_bvh(scene.vertices);
        const DeviceScene dev = compile(scene, bvh);
        std::uint64_t float4_bytes = 0;  // the texels as the pool stored them before: 16 bytes each
        for (const TextureImage& t : scene.textures) float4_bytes += t.texels.size() * sizeof(float);
        const bool textured = scene_uses_textures(scene);
        const std::uint64_t pool = textured ? dev.texels.size_bytes() : 0;
        const double with = textured ? samples_per_second(ctx, scene, bvh, size, spp) : 0.0;
        Scene plain = scene;
        for (Material& m : plain.materials) m.textures = MaterialTextures{};
        const double without = samples_per_second(ctx, plain, bvh, size, spp);
        md.row({c.name, std::to_string(scene.triangle_count()), std::to_string(scene.textures.size()),
                fmt::format("{:.3f}", load_s), fmt::format("{:.1f}", mib(device_bytes(dev))),
                textured ? fmt::format("{:.3f}", mib(pool)) : "—",
                textured ? fmt::format("{:.3f}", mib(float4_bytes)) : "—", textured ? fmt::format("{:.3f}", with) : "—",
                fmt::format("{:.3f}", without)});
        rows.push_back({{"asset", c.name},
                        {"triangles", scene.triangle_count()},
                        {"textures", scene.textures.size()},
                        {"load_s", load_s},
                        {"device_bytes", device_bytes(dev)},
                        {"texel_pool_bytes", pool},
                        {"float4_texel_bytes", float4_bytes},
                        {"msamples_per_s_textured", with},
                        {"msamples_per_s_untextured", without}});
    }
    bench_print("{}", md.str());
    return rows;
}

}  // namespace facet
