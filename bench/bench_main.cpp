// facet_bench: BVH build speed, trace throughput and samples per second, printed as a
// table (and as JSON with --json FILE). Figures only; nothing here passes or fails.
//
//   facet_bench [--device SEL] [--assets DIR] [--json FILE] [--quick]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "bench.hpp"
#include "bvh/bvh.hpp"
#include "cl/runtime.hpp"
#include "error.hpp"
#include "render/renderer.hpp"
#include "scene/load.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct RayBatch {
    std::vector<cl_float4> origins, dirs;   // dirs[i].w = tmax
};

struct BenchCase {
    std::string name;
    std::string path;
};

// Camera rays through pixel centres, as kernels/camera/camera.cl makes them.
RayBatch camera_rays(const Scene& scene, int width, int height) {
    FcCamera cam = make_camera(scene.camera, float(width) / float(height));
    glm::vec3 eye(cam.eye[0], cam.eye[1], cam.eye[2]), fw(cam.forward[0], cam.forward[1], cam.forward[2]);
    glm::vec3 right(cam.right[0], cam.right[1], cam.right[2]), up(cam.up[0], cam.up[1], cam.up[2]);
    RayBatch b;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float sx = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f;
            float sy = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
            glm::vec3 o = eye, d = fw;
            if (cam.projection == FC_PROJECTION_ORTHOGRAPHIC) o = eye + sx * right + sy * up;
            else d = glm::normalize(fw + sx * right + sy * up);
            b.origins.push_back({{o.x, o.y, o.z, 0.0f}});
            b.dirs.push_back({{d.x, d.y, d.z, INFINITY}});
        }
    return b;
}

class Tracer {
public:
    Tracer(ClContext& ctx, const Bvh& bvh) : ctx_(ctx) {
        program_ = build_program(ctx, "kernels/bench/trace_bench.cl").program;
        nodes_ = cl::Buffer(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bvh.nodes.size() * sizeof(FcBvhNode),
                            const_cast<FcBvhNode*>(bvh.nodes.data()));
        tris_ = cl::Buffer(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                           std::max<std::size_t>(1, bvh.triangles.size()) * sizeof(FcTriangle),
                           const_cast<FcTriangle*>(bvh.triangles.data()));
    }

    // Traces the batch `reps` times; returns the best time and the closest hits.
    double closest(const RayBatch& rays, int reps, std::vector<float>& t, std::vector<int>& prim) {
        std::size_t n = rays.origins.size();
        cl::Buffer o = buffer(rays.origins), d = buffer(rays.dirs);
        cl::Buffer tb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(float));
        cl::Buffer pb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
        cl::Kernel k(program_, "trace_closest_batch");
        k.setArg(0, nodes_), k.setArg(1, tris_), k.setArg(2, o), k.setArg(3, d), k.setArg(4, tb), k.setArg(5, pb);
        double best = time_kernel(k, n, reps);
        t.resize(n), prim.resize(n);
        ctx_.queue().enqueueReadBuffer(tb, CL_TRUE, 0, n * sizeof(float), t.data());
        ctx_.queue().enqueueReadBuffer(pb, CL_TRUE, 0, n * sizeof(int), prim.data());
        return best;
    }

    double any(const RayBatch& rays, int reps) {
        std::size_t n = rays.origins.size();
        cl::Buffer o = buffer(rays.origins), d = buffer(rays.dirs);
        cl::Buffer hb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
        cl::Kernel k(program_, "trace_any_batch");
        k.setArg(0, nodes_), k.setArg(1, tris_), k.setArg(2, o), k.setArg(3, d), k.setArg(4, hb);
        return time_kernel(k, n, reps);
    }

private:
    cl::Buffer buffer(const std::vector<cl_float4>& v) {
        return cl::Buffer(ctx_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(cl_float4),
                          const_cast<cl_float4*>(v.data()));
    }
    double time_kernel(cl::Kernel& k, std::size_t n, int reps) {
        double best = 1e30;
        for (int r = 0; r < reps + 1; ++r) {   // the first launch warms up
            auto start = Clock::now();
            ctx_.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
            ctx_.queue().finish();
            if (r > 0) best = std::min(best, since(start));
        }
        return best;
    }

    ClContext& ctx_;
    cl::Program program_;
    cl::Buffer nodes_, tris_;
};

// Diffuse bounce rays: from every camera-ray hit, a cosine-distributed direction
// about the face normal on the side the camera ray came from.
RayBatch diffuse_rays(const Scene& scene, const RayBatch& cam, const std::vector<float>& t, const std::vector<int>& prim) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    RayBatch b;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < 0.0f) continue;
        glm::vec3 o(cam.origins[i].s[0], cam.origins[i].s[1], cam.origins[i].s[2]);
        glm::vec3 d(cam.dirs[i].s[0], cam.dirs[i].s[1], cam.dirs[i].s[2]);
        const glm::vec3* v = &scene.vertices[3 * std::size_t(prim[i])];
        glm::vec3 n = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
        if (glm::dot(n, d) > 0.0f) n = -n;
        glm::vec3 p = o + t[i] * d;
        p += n * (1e-4f * std::max(1.0f, glm::length(p)));   // enough offset for a bench ray
        glm::vec3 a = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        glm::vec3 s = glm::normalize(glm::cross(a, n)), tt = glm::cross(n, s);
        float r = std::sqrt(u01(rng)), phi = 6.2831853f * u01(rng);
        glm::vec3 w = glm::normalize(r * std::cos(phi) * s + r * std::sin(phi) * tt + std::sqrt(std::max(0.0f, 1 - r * r)) * n);
        b.origins.push_back({{p.x, p.y, p.z, 0.0f}});
        b.dirs.push_back({{w.x, w.y, w.z, INFINITY}});
    }
    return b;
}

nlohmann::json bench_scene(ClContext& ctx, const BenchCase& c, bool quick) {
    Scene scene = load_scene(c.path);
    nlohmann::json j;
    j["scene"] = c.name;
    j["triangles"] = scene.triangle_count();

    // BVH build: best of several single-threaded builds.
    Bvh bvh;
    double best_build = 1e30;
    for (int r = 0; r < (quick ? 1 : 3); ++r) {
        bvh = build_bvh(scene.vertices);
        best_build = std::min(best_build, bvh.stats.build_seconds);
    }
    j["bvh_build_s"] = best_build;
    j["bvh_mtris_per_s"] = double(scene.triangle_count()) / best_build * 1e-6;
    j["bvh_sah_cost"] = bvh.stats.sah_cost;
    j["bvh_nodes"] = bvh.stats.nodes;
    j["bvh_bytes_per_triangle"] = double(bvh.stats.device_bytes) / double(std::max<std::size_t>(1, scene.triangle_count()));

    // Trace: camera rays, then diffuse bounce rays from their hits.
    int size = quick ? 256 : 512;
    Tracer tracer(ctx, bvh);
    RayBatch cam = camera_rays(scene, size, size);
    std::vector<float> t;
    std::vector<int> prim;
    int reps = quick ? 1 : 3;
    double cam_s = tracer.closest(cam, reps, t, prim);
    RayBatch diffuse = diffuse_rays(scene, cam, t, prim);
    std::vector<float> t2;
    std::vector<int> prim2;
    double diff_s = diffuse.origins.empty() ? 0.0 : tracer.closest(diffuse, reps, t2, prim2);
    double diff_any_s = diffuse.origins.empty() ? 0.0 : tracer.any(diffuse, reps);
    j["camera_rays"] = cam.origins.size();
    j["camera_mrays_per_s"] = double(cam.origins.size()) / cam_s * 1e-6;
    j["diffuse_rays"] = diffuse.origins.size();
    j["diffuse_mrays_per_s"] = diff_s > 0 ? double(diffuse.origins.size()) / diff_s * 1e-6 : 0.0;
    j["diffuse_any_mrays_per_s"] = diff_any_s > 0 ? double(diffuse.origins.size()) / diff_any_s * 1e-6 : 0.0;

    // Render: samples per second of the full path tracer at the bench size.
    scene.settings.width = size;
    scene.settings.height = size;
    Renderer renderer(ctx, scene, bvh);
    renderer.render(1);   // warm-up
    renderer.reset();
    std::uint32_t spp = quick ? 2 : 8;
    renderer.render(spp);
    double rs = renderer.stats().render_seconds;
    j["render_spp"] = spp;
    j["render_msamples_per_s"] = double(spp) * size * size / rs * 1e-6;
    j["kernel_build_s"] = renderer.stats().compile_seconds;
    return j;
}

int run(int argc, char** argv) {
    CLI::App app{"facet_bench: BVH build, trace and render throughput (figures, not tests)"};
    std::string device, assets = (fs::path(FACET_SOURCE_DIR) / ".." / "shared" / "assets").string(), json_out;
    bool quick = false;
    app.add_option("--device", device, "OpenCL device (index or name part)");
    app.add_option("--assets", assets, "Folder of the shared assets (skipped when absent)");
    app.add_option("--json", json_out, "Also write the figures as JSON to this file");
    app.add_flag("--quick", quick, "Smaller images and fewer repetitions");
    std::string only;
    app.add_option("--only", only, "Run one section: trace, bsdf, ibl or specialisation");
    CLI11_PARSE(app, argc, argv);

    ClContext ctx = ClContext::create(device);
    std::vector<BenchCase> cases = {{"cornell_box", (fs::path(FACET_SOURCE_DIR) / "scenes" / "cornell_box.json").string()}};
    for (auto [name, rel] : {std::pair{"bunny", "meshes_common3d/stanford-bunny.obj"},
                             std::pair{"dragon_res2", "dragon_stanford/dragon_vrip_res2.obj"}}) {
        fs::path p = fs::path(assets) / rel;
        if (fs::exists(p)) cases.push_back({name, p.string()});
        else fmt::print("skipping {}: {} not found\n", name, p.string());
    }
    fmt::print("device: {} / {} ({})\n\n", ctx.desc().platform, ctx.desc().name, ctx.desc().driver);
    nlohmann::json all;
    all["device"] = ctx.desc().platform + " / " + ctx.desc().name;
    if (!only.empty() && only != "trace" && only != "bsdf" && only != "ibl" && only != "specialisation")
        throw Error(fmt::format("--only {}: expected trace, bsdf, ibl or specialisation", only));
    auto wanted = [&](const char* section) { return only.empty() || only == section; };
    if (wanted("trace")) {
        fmt::print("| scene | triangles | BVH build Mtris/s (1 thread) | SAH cost | bytes/tri | camera Mrays/s | diffuse Mrays/s | diffuse any-hit Mrays/s | render Msamples/s | kernel build s |\n");
        fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
    }
    for (const BenchCase& c : cases) {
        if (!wanted("trace")) break;
        nlohmann::json j = bench_scene(ctx, c, quick);
        fmt::print("| {} | {} | {:.2f} | {:.1f} | {:.0f} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {:.2f} |\n", c.name,
                   j["triangles"].get<std::size_t>(), j["bvh_mtris_per_s"].get<double>(), j["bvh_sah_cost"].get<double>(),
                   j["bvh_bytes_per_triangle"].get<double>(), j["camera_mrays_per_s"].get<double>(),
                   j["diffuse_mrays_per_s"].get<double>(), j["diffuse_any_mrays_per_s"].get<double>(),
                   j["render_msamples_per_s"].get<double>(), j["kernel_build_s"].get<double>());
        std::fflush(stdout);
        all["scenes"].push_back(j);
    }
    if (wanted("bsdf")) all["bsdfs"] = bench_bsdfs(ctx, quick);
    if (wanted("ibl")) all["ibl"] = bench_ibl(ctx, assets, quick);
    if (wanted("specialisation")) all["specialisation"] = bench_specialisation(ctx, assets, quick);
    if (!json_out.empty()) std::ofstream(json_out) << all.dump(2) << "\n";
    return 0;
}

}  // namespace
}  // namespace facet

int main(int argc, char** argv) {
    try {
        return facet::run(argc, argv);
    } catch (const std::exception& e) {
        fmt::print(stderr, "facet_bench: error: {}\n", e.what());
        return 1;
    }
}
