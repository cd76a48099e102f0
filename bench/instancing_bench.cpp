// Instancing, both ways: Spot the cow (5856 triangles) as one glTF mesh used by 100 nodes in a 10 x 10 grid,
// loaded instanced (stored once, a two-level BVH) and copied into the world
// (GltfLoadOptions::instancing off): load time, BVH build and compile time, device memory
// and render speed, the two taken alternately (A, B, A, B, ...) and reported as medians.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <unistd.h>

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/error.hpp"
#include "host/readers/gltf_reader.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/device_scene.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// `mesh`'s triangles (positions and shading normals, not indexed) as a glTF mesh used by
// side x side nodes on a grid in x and z, each turned about y.
void write_grid(const Scene& mesh, int side, const std::string& path) {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.scenes.emplace_back();
    m.defaultScene = 0;
    std::vector<float> pos, nrm;
    for (std::size_t t = 0; t < mesh.shading.size(); ++t) {
        const float* n[3] = {mesh.shading[t].n0, mesh.shading[t].n1, mesh.shading[t].n2};
        for (int c = 0; c < 3; ++c) {
            const glm::vec3& p = mesh.vertices[3 * t + std::size_t(c)];
            pos.insert(pos.end(), {p.x, p.y, p.z});
            nrm.insert(nrm.end(), {n[c][0], n[c][1], n[c][2]});
        }
    }
    tinygltf::Buffer buf;
    auto add = [&](const std::vector<float>& v) {
        tinygltf::BufferView bv;
        bv.buffer = 0;
        bv.byteOffset = buf.data.size();
        bv.byteLength = v.size() * 4;
        const auto* b = reinterpret_cast<const unsigned char*>(v.data());
        buf.data.insert(buf.data.end(), b, b + v.size() * 4);
        m.bufferViews.push_back(bv);
        tinygltf::Accessor a;
        a.bufferView = int(m.bufferViews.size() - 1);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.type = TINYGLTF_TYPE_VEC3;
        a.count = v.size() / 3;
        m.accessors.push_back(a);
        return int(m.accessors.size() - 1);
    };
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = add(pos);
    prim.attributes["NORMAL"] = add(nrm);
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    buf.uri = fs::path(path).stem().string() + ".bin";
    m.buffers.push_back(buf);
    tinygltf::Mesh gm;
    gm.primitives.push_back(prim);
    m.meshes.push_back(gm);
    const Bounds b = scene_bounds(mesh);
    const float step = 1.2f * std::max(b.hi.x - b.lo.x, b.hi.z - b.lo.z);
    for (int i = 0; i < side * side; ++i) {
        tinygltf::Node node;
        node.mesh = 0;
        const glm::quat q = glm::angleAxis(0.7f * float(i), glm::vec3(0, 1, 0));
        node.rotation = {q.x, q.y, q.z, q.w};
        node.translation = {double(step) * (i % side), 0.0, double(step) * (i / side)};
        m.nodes.push_back(node);
        m.scenes[0].nodes.push_back(i);
    }
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&m, path, false, false, true, false))
        throw Error("instancing bench: could not write " + path);
}

struct Run {
    double load_s = 0, build_s = 0, msamples = 0;
    std::size_t device_bytes = 0, device_triangles = 0, world_triangles = 0;
};

Run run_once(ClContext& ctx, const std::string& path, bool instanced, bool quick) {
    Run r;
    Scene scene;
    GltfLoadOptions options;
    options.instancing = instanced;
    auto start = Clock::now();
    load_gltf(path, scene, options);
    r.load_s = since(start);
    scene.camera = frame_camera(scene);
    scene.environment = constant_environment(glm::vec3(1.0f));
    scene.settings.width = scene.settings.height = quick ? 64 : 128;
    scene.settings.max_depth = 2;
    build_lights(scene);
    start = Clock::now();
    const Bvh bvh = build_bvh(scene.vertices);
    const DeviceScene dev = compile(scene, bvh);
    r.build_s = since(start);
    r.device_triangles = dev.tris.size();
    r.world_triangles = scene.placed_triangle_count();
    r.device_bytes = dev.nodes.size_bytes() + dev.tris.size_bytes() + dev.shading.size_bytes() +
                     dev.instancing.instances.size() * sizeof(FcInstance) +
                     dev.instancing.tree.size() * sizeof(FcBvhNode);
    Renderer renderer(ctx, scene, bvh);
    render_fixed(renderer, 1);  // the first launch generates machine code
    renderer.reset();
    const std::uint32_t spp = quick ? 2 : 8;
    render_fixed(renderer, spp);
    r.msamples = double(spp) * double(renderer.pixel_count()) / renderer.stats().render_seconds * 1e-6;
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

nlohmann::json bench_instancing(ClContext& ctx, const std::string& assets, bool quick) {
    const fs::path spot = fs::path(assets) / "meshes_common3d" / "spot.obj";
    if (!fs::exists(spot)) {
        bench_print("\nInstancing skipped: {} not found.\n", spot.string());
        return {};
    }
    const fs::path dir = fs::temp_directory_path() / fmt::format("facet_bench_instancing_{}", ::getpid());
    fs::create_directories(dir);
    const std::string path = (dir / "spot_grid.gltf").string();
    write_grid(load_scene(spot.string()), 10, path);
    const int reps = quick ? 1 : 3;
    std::vector<Run> runs[2];
    for (int k = 0; k < reps; ++k)
        for (int instanced = 1; instanced >= 0; --instanced)
            runs[instanced].push_back(run_once(ctx, path, instanced != 0, quick));
    fs::remove_all(dir);
    bench_print(
        "\n### Instancing: Spot the cow used by 100 glTF nodes\n\nLoad = load_gltf; build = build_bvh + compile (the "
        "shared mesh's BVH, the top level, the device arrays); device MiB = BVH nodes and leaf blocks, triangles, "
        "shading data, instances and their tree; render at {}², max depth 2, constant environment. Medians of {} "
        "runs taken alternately.\n\n",
        quick ? 64 : 128, reps);
    bench_print("| scene | triangles in the world | on the device | load s | build s | device MiB | Msamples/s |\n");
    bench_print("|---|---|---|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    for (int instanced = 1; instanced >= 0; --instanced) {
        std::vector<double> load, build, rate;
        for (const Run& r : runs[instanced]) {
            load.push_back(r.load_s);
            build.push_back(r.build_s);
            rate.push_back(r.msamples);
        }
        const Run& r = runs[instanced].front();
        const char* name = instanced ? "instanced" : "copied";
        bench_print("| {} | {} | {} | {:.3f} | {:.3f} | {:.1f} | {:.3f} |\n", name, r.world_triangles,
                    r.device_triangles, median(load), median(build), double(r.device_bytes) / (1 << 20), median(rate));
        rows.push_back({{"scene", name},
                        {"world_triangles", r.world_triangles},
                        {"device_triangles", r.device_triangles},
                        {"load_s", median(load)},
                        {"build_s", median(build)},
                        {"device_bytes", r.device_bytes},
                        {"msamples_per_s", median(rate)}});
    }
    return rows;
}

}  // namespace facet
