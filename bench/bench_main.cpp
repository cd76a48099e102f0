// facet_bench: BVH build speed, trace throughput against Embree on the same rays in the
// same run, samples per second, program build time and equal-time error, printed as
// Markdown tables (also written with --markdown FILE, and as JSON with --json FILE).
// Figures only; nothing here passes or fails. `make bench` runs it; see bench/README.md.
//
//   facet_bench [--device SEL] [--assets DIR] [--json FILE] [--markdown FILE] [--quick]
//               [--only trace|build|bsdf|ibl|specialisation|kernels|quality|denoise|assets|instancing]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "bench/embree_bench.hpp"
#include "host/film/error_metrics.hpp"
#include "host/bvh/bvh.hpp"
#include "host/bvh/bvh_width.hpp"
#include "host/cl/runtime.hpp"
#include "host/error.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

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
    Tracer(ClContext& ctx, const Bvh& bvh, std::size_t local = 64) : ctx_(ctx), local_(local) {
        program_ = build_program(ctx, "kernels/bench/trace_bench.cl", {bvh_prelude(bvh)}).program;
        nodes_ = cl::Buffer(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                            bvh.nodes.size() * sizeof(FcBvhNode), const_cast<FcBvhNode*>(bvh.nodes.data()));
        tris_ = cl::Buffer(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                           std::max<std::size_t>(1, bvh.triangles.size()) * sizeof(FcTriangle),
                           const_cast<FcTriangle*>(bvh.triangles.data()));
    }

    // Traces the batch `reps` times; returns the best times and the closest hits.
    Timing closest(const RayBatch& rays, int reps, std::vector<float>& t, std::vector<int>& prim) {
        std::size_t n = rays.origins.size();
        cl::Buffer o = buffer(rays.origins), d = buffer(rays.dirs);
        cl::Buffer tb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(float));
        cl::Buffer pb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
        cl::Kernel k(program_, "trace_closest_batch");
        k.setArg(0, nodes_), k.setArg(1, tris_), k.setArg(2, o), k.setArg(3, d), k.setArg(4, tb), k.setArg(5, pb);
        k.setArg(6, cl_int(n));
        Timing best = time_kernel(k, n, reps);
        t.resize(n), prim.resize(n);
        ctx_.queue().enqueueReadBuffer(tb, CL_TRUE, 0, n * sizeof(float), t.data());
        ctx_.queue().enqueueReadBuffer(pb, CL_TRUE, 0, n * sizeof(int), prim.data());
        return best;
    }

    Timing any(const RayBatch& rays, int reps) {
        std::size_t n = rays.origins.size();
        cl::Buffer o = buffer(rays.origins), d = buffer(rays.dirs);
        cl::Buffer hb(ctx_.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
        cl::Kernel k(program_, "trace_any_batch");
        k.setArg(0, nodes_), k.setArg(1, tris_), k.setArg(2, o), k.setArg(3, d), k.setArg(4, hb);
        k.setArg(5, cl_int(n));
        return time_kernel(k, n, reps);
    }

private:
    cl::Buffer buffer(const std::vector<cl_float4>& v) {
        return cl::Buffer(ctx_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(cl_float4),
                          const_cast<cl_float4*>(v.data()));
    }
    Timing time_kernel(cl::Kernel& k, std::size_t n, int reps) {
        Timing best{1e30, 1e30};
        for (int r = 0; r < reps + 1; ++r) {  // the first launch warms up
            auto start = Clock::now();
            double cpu0 = process_cpu_seconds();
            // A fixed local size (PoCL specialises kernels per launch geometry), the
            // global size rounded up to it; the kernels skip the padding.
            std::size_t global = (n + local_ - 1) / local_ * local_;
            ctx_.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(global), cl::NDRange(local_));
            ctx_.queue().finish();
            double cpu = process_cpu_seconds() - cpu0;
            if (r > 0) best.wall = std::min(best.wall, since(start)), best.cpu = std::min(best.cpu, cpu);
        }
        return best;
    }

    ClContext& ctx_;
    std::size_t local_;
    cl::Program program_;
    cl::Buffer nodes_, tris_;
};

// Diffuse bounce rays: from every camera-ray hit, `per_hit` cosine-distributed directions
// about the face normal on the side the camera ray came from.
RayBatch diffuse_rays(const Scene& scene, const RayBatch& cam, const std::vector<float>& t,
                      const std::vector<int>& prim, int per_hit) {
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
        p += n * (1e-4f * std::max(1.0f, glm::length(p)));  // enough offset for a bench ray
        glm::vec3 a = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        glm::vec3 s = glm::normalize(glm::cross(a, n)), tt = glm::cross(n, s);
        for (int k = 0; k < per_hit; ++k) {
            float r = std::sqrt(u01(rng)), phi = 6.2831853f * u01(rng);
            glm::vec3 w = glm::normalize(r * std::cos(phi) * s + r * std::sin(phi) * tt +
                                         std::sqrt(std::max(0.0f, 1 - r * r)) * n);
            b.origins.push_back({{p.x, p.y, p.z, 0.0f}});
            b.dirs.push_back({{w.x, w.y, w.z, INFINITY}});
        }
    }
    return b;
}

// Mrays/s of n rays traced in s seconds (0 when nothing was timed).
double mrays(std::size_t n, double s) { return s > 0.0 ? double(n) / s * 1e-6 : 0.0; }

std::string fmt_rate(double v) { return v > 0.0 ? fmt::format("{:.2f}", v) : std::string("—"); }

nlohmann::json bench_scene(ClContext& ctx, const BenchCase& c, bool quick, bool build_only, bool facet_only,
                           std::size_t local, const BvhOptions& bvh_options, Markdown& build_md, Markdown& trace_md,
                           Markdown& render_md) {
    Scene scene = load_scene(c.path);
    nlohmann::json j;
    j["scene"] = c.name;
    j["triangles"] = scene.triangle_count();

    // BVH build: best of several single-threaded builds, and a plain 12-bin build (no
    // exact sweep of small ranges) as the SAH-cost yardstick.
    Bvh bvh;
    double best_build = 1e30;
    for (int r = 0; r < (quick ? 1 : 3); ++r) {
        bvh = build_bvh(scene.vertices, bvh_options);
        best_build = std::min(best_build, bvh.stats.build_seconds);
    }
    BvhOptions plain;
    plain.bins = 12;
    plain.exact_max = 0;
    double plain_build = 1e30;
    double plain_sah = 0.0;
    for (int r = 0; r < (quick ? 1 : 2); ++r) {
        Bvh p = build_bvh(scene.vertices, plain);
        plain_build = std::min(plain_build, p.stats.build_seconds);
        plain_sah = p.stats.sah_cost;
    }
    const double tris = double(std::max<std::size_t>(1, scene.triangle_count()));
    j["bvh_build_s"] = best_build;
    j["bvh_mtris_per_s"] = tris / best_build * 1e-6;
    j["bvh_sah_cost"] = bvh.stats.sah_cost;
    j["bvh_plain12_sah_cost"] = plain_sah;
    j["bvh_plain12_mtris_per_s"] = tris / plain_build * 1e-6;
    j["bvh_nodes"] = bvh.stats.nodes;
    j["bvh_leaves"] = bvh.stats.leaves;
    j["bvh_max_depth"] = bvh.stats.max_depth;
    j["bvh_bytes_per_triangle"] = double(bvh.stats.device_bytes) / tris;
    if (build_only) {
        build_md.row({c.name, std::to_string(scene.triangle_count()), fmt::format("{:.1f}", best_build * 1e3),
                      fmt::format("{:.2f}", tris / best_build * 1e-6), fmt::format("{:.3f}", bvh.stats.sah_cost),
                      fmt::format("{:.2f}", tris / plain_build * 1e-6), fmt::format("{:.3f}", plain_sah),
                      fmt::format("{:.0f}", double(bvh.stats.device_bytes) / tris), "—"});
        return j;
    }

    // Trace: camera rays, then diffuse bounce rays from their hits; the same batches
    // go to Embree.
    int size = quick ? 256 : 512;
    Tracer tracer(ctx, bvh, local);
    RayBatch cam = camera_rays(scene, size, size);
    std::vector<float> t;
    std::vector<int> prim;
    int reps = quick ? 1 : 5;
    Timing cam_s = tracer.closest(cam, reps, t, prim);
    std::vector<float> cam_t = t;
    RayBatch diffuse = diffuse_rays(scene, cam, t, prim, quick ? 1 : 4);
    const int threads = int(std::max<std::uint32_t>(1, ctx.desc().compute_units));
    std::string why;
    const bool have_embree = !facet_only && embree_available(&why);
    double embree_build = 0.0;
    auto rate = [](std::size_t n, const Timing& tm) { return mrays(n, tm.wall); };
    auto cpu_rate = [](std::size_t n, const Timing& tm) { return mrays(n, tm.cpu); };
    for (int batch = 0; batch < 2; ++batch) {
        const RayBatch& rays = batch == 0 ? cam : diffuse;
        const char* bname = batch == 0 ? "camera" : "diffuse";
        const std::size_t n = rays.origins.size();
        if (n == 0) continue;
        std::vector<float> ft;
        std::vector<int> fp;
        Timing closest_s = batch == 0 ? cam_s : tracer.closest(rays, reps, ft, fp);
        if (batch == 0) ft = cam_t;
        Timing any_s = tracer.any(rays, reps);
        nlohmann::json b;
        b["rays"] = n;
        b["facet_closest_mrays_per_s"] = rate(n, closest_s);
        b["facet_any_mrays_per_s"] = rate(n, any_s);
        b["facet_closest_mrays_per_cpu_s"] = cpu_rate(n, closest_s);
        b["facet_any_mrays_per_cpu_s"] = cpu_rate(n, any_s);
        if (have_embree) {
            EmbreeTimes e = bench_embree_trace(scene.vertices, rays, threads, reps, ft);
            embree_build = e.build_s;
            nlohmann::json ej;
            ej["threads"] = e.threads;
            ej["packet_width"] = e.packet_width;
            ej["hit_mismatches"] = e.hit_mismatches;
            ej["t_mismatches"] = e.t_mismatches;
            const char* tn[2] = {"1t", "nt"};
            for (int k = 0; k < 2; ++k) {
                ej[fmt::format("intersect1_{}_mrays_per_s", tn[k])] = rate(n, e.closest1[k]);
                ej[fmt::format("intersect_packet_{}_mrays_per_s", tn[k])] = rate(n, e.closestP[k]);
                ej[fmt::format("intersect1M_stream_{}_mrays_per_s", tn[k])] = rate(n, e.closestS[k]);
                ej[fmt::format("occluded1_{}_mrays_per_s", tn[k])] = rate(n, e.any1[k]);
                ej[fmt::format("occluded_packet_{}_mrays_per_s", tn[k])] = rate(n, e.anyP[k]);
                ej[fmt::format("intersect1_{}_mrays_per_cpu_s", tn[k])] = cpu_rate(n, e.closest1[k]);
                ej[fmt::format("occluded1_{}_mrays_per_cpu_s", tn[k])] = cpu_rate(n, e.any1[k]);
            }
            b["embree"] = ej;
            // The goal's ratio: facet on every compute unit against rtcIntersect1 on as
            // many threads, by wall time; and the same per CPU-second.
            b["ratio_closest_vs_intersect1_nt"] = rate(n, closest_s) / std::max(1e-12, rate(n, e.closest1[1]));
            b["ratio_any_vs_occluded1_nt"] = rate(n, any_s) / std::max(1e-12, rate(n, e.any1[1]));
            b["ratio_closest_vs_intersect1_nt_per_cpu_s"] =
                cpu_rate(n, closest_s) / std::max(1e-12, cpu_rate(n, e.closest1[1]));
            b["ratio_any_vs_occluded1_nt_per_cpu_s"] = cpu_rate(n, any_s) / std::max(1e-12, cpu_rate(n, e.any1[1]));
            for (int q = 0; q < 2; ++q) {
                const Timing& f = q == 0 ? closest_s : any_s;
                const Timing* one = q == 0 ? e.closest1 : e.any1;
                const Timing* pk = q == 0 ? e.closestP : e.anyP;
                trace_md.row({c.name, bname, q == 0 ? "closest" : "any", std::to_string(n), fmt_rate(rate(n, f)),
                              fmt_rate(rate(n, one[0])), fmt_rate(rate(n, pk[0])),
                              q == 0 ? fmt_rate(rate(n, e.closestS[0])) : std::string("—"), fmt_rate(rate(n, one[1])),
                              fmt_rate(rate(n, pk[1])), q == 0 ? fmt_rate(rate(n, e.closestS[1])) : std::string("—"),
                              fmt::format("**{:.2f}**", rate(n, f) / std::max(1e-12, rate(n, one[1]))),
                              fmt::format("{:.2f}", cpu_rate(n, f) / std::max(1e-12, cpu_rate(n, one[1]))),
                              q == 0 ? fmt::format("{}/{}", e.hit_mismatches, e.t_mismatches) : std::string("")});
            }
        } else {
            for (int q = 0; q < 2; ++q)
                trace_md.row({c.name, bname, q == 0 ? "closest" : "any", std::to_string(n),
                              fmt_rate(rate(n, q == 0 ? closest_s : any_s)), "—", "—", "—", "—", "—", "—", "—", "—",
                              ""});
        }
        j["trace"][bname] = b;
    }
    if (!have_embree) j["embree_missing"] = why;
    j["embree_build_s"] = embree_build;
    build_md.row({c.name, std::to_string(scene.triangle_count()), fmt::format("{:.1f}", best_build * 1e3),
                  fmt::format("{:.2f}", tris / best_build * 1e-6), fmt::format("{:.3f}", bvh.stats.sah_cost),
                  fmt::format("{:.2f}", tris / plain_build * 1e-6), fmt::format("{:.3f}", plain_sah),
                  fmt::format("{:.0f}", double(bvh.stats.device_bytes) / tris),
                  embree_build > 0 ? fmt::format("{:.2f}", tris / embree_build * 1e-6) : std::string("—")});

    if (facet_only) return j;
    // Render: samples per second of the full path tracer at the bench size.
    scene.settings.width = size;
    scene.settings.height = size;
    Renderer renderer(ctx, scene, bvh);
    render_fixed(renderer, 1);  // warm-up
    renderer.reset();
    std::uint32_t spp = quick ? 2 : 8;
    render_fixed(renderer, spp);
    double rs = renderer.stats().render_seconds;
    j["render_spp"] = spp;
    j["render_msamples_per_s"] = double(spp) * size * size / rs * 1e-6;
    j["kernel_build_s"] = renderer.stats().compile_seconds;
    render_md.row({c.name, fmt::format("{}²", size), fmt::format("{:.3f}", j["render_msamples_per_s"].get<double>()),
                   fmt::format("{:.2f}", renderer.stats().compile_seconds)});
    return j;
}

// Equal-time quality: each demo scene rendered for a fixed time; the error is the
// progressive CLI's reference-free estimate from the two half-images
// (film/error_metrics.hpp), so lower is better at equal time.
nlohmann::json bench_quality(ClContext& ctx, bool quick) {
    namespace fs = std::filesystem;
    const double seconds = quick ? 0.5 : 2.0;
    const int size = quick ? 96 : 128;
    bench_print("\n### Equal-time quality ({:.1f} s of rendering at {}², after a warm-up pass)\n\n", seconds, size);
    bench_print("| scene | samples/pixel | Msamples/s | est. RMSE | est. relMSE |\n|---|---|---|---|---|\n");
    nlohmann::json rows = nlohmann::json::array();
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(FACET_SOURCE_DIR) / "scenes"))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        Scene scene = load_scene(f.string());
        scene.settings.width = scene.settings.height = size;
        Bvh bvh = build_bvh(scene.vertices);
        Renderer r(ctx, scene, bvh);
        render_fixed(r, 1);
        r.reset();
        ProgressiveOptions po;  // passes of 2 samples for `seconds`
        po.target_spp = std::uint64_t(1) << 40;
        po.time_limit_s = seconds;
        po.fixed_pass = 2;
        render_progressive(r, po);
        Renderer::Halves h = r.halves();
        ErrorMetrics m = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
        std::uint64_t spp = r.stats().samples_per_pixel;
        double rate = double(spp) * double(r.pixel_count()) / r.stats().render_seconds * 1e-6;
        bench_print("| {} | {} | {:.3f} | {:.4g} | {:.4g} |\n", f.stem().string(), spp, rate, m.rmse, m.relmse);
        std::fflush(stdout);
        rows.push_back({{"scene", f.stem().string()},
                        {"seconds", r.stats().render_seconds},
                        {"spp", spp},
                        {"msamples_per_s", rate},
                        {"est_rmse", m.rmse},
                        {"est_relmse", m.relmse}});
    }
    return rows;
}

int run(int argc, char** argv) {
    CLI::App app{
        "facet_bench: BVH build, trace (against Embree), render throughput, program build and equal-time "
        "error (figures, not tests)"};
    std::string device, assets = (fs::path(FACET_SOURCE_DIR) / ".." / "shared" / "assets").string(), json_out, md_out;
    bool quick = false;
    app.add_option("--device", device, "OpenCL device (index or name part)");
    app.add_option("--assets", assets, "Folder of the shared assets (skipped when absent)");
    app.add_option("--json", json_out, "Also write the figures as JSON to this file");
    app.add_option("--markdown", md_out, "Also write the tables as Markdown to this file");
    app.add_flag("--quick", quick, "Smaller images and fewer repetitions");
    std::size_t trace_local = 64;
    app.add_option("--trace-local", trace_local, "Work-group size of the trace kernels (default 64, as the renderer)")
        ->check(CLI::Range(1, 1024));
    BvhOptions bvh_options;
    app.add_option("--bvh-leaf", bvh_options.max_leaf_size, "BVH knob: largest leaf (default 8)");
    app.add_option("--bvh-block", bvh_options.block_size,
                   "BVH knob: triangles per leaf test in the SAH, 1, 2, 4 or 8 (default 4, the leaf blocks' lanes)");
    app.add_option("--bvh-width", bvh_options.width,
                   "BVH node width, 4 or 8 (default: FACET_BVH_WIDTH when set, else the device's, as the CLI picks it)")
        ->check(CLI::IsMember({0, 4, 8}));
    app.add_option("--bvh-quantised", bvh_options.quantised,
                   "8-wide BVH: 1 quantised child boxes (80-byte nodes), 0 float boxes (default: FACET_BVH_QUANTISED "
                   "when set, else the build's default)")
        ->check(CLI::IsMember({-1, 0, 1}));
    app.add_option("--bvh-intersection-cost", bvh_options.intersection_cost,
                   "BVH knob: SAH cost of a triangle block test against a node visit (default 4)");
    bool facet_only = false;
    app.add_flag("--facet-only", facet_only,
                 "Trace section: facet's traversal alone (no Embree, no render), for profiles and instruction counts");
    std::string scene_filter;
    app.add_option("--scene", scene_filter, "Trace section: only the scenes whose name contains this");
    std::string only;
    // The sections, in the order they run; "build" is the trace section's BVH build alone.
    const std::vector<std::string> sections = {"trace",          "build",      "bsdf",    "ibl",
                                               "specialisation", "kernels",    "quality", "denoise",
                                               "assets",         "instancing", "packet"};
    std::string section_list;
    for (const std::string& s : sections) section_list += (section_list.empty() ? "" : ", ") + s;
    app.add_option("--only", only, "Run one section: " + section_list);
    CLI11_PARSE(app, argc, argv);
    if (!only.empty() && std::find(sections.begin(), sections.end(), only) == sections.end())
        throw Error(fmt::format("--only {}: expected one of {}", only, section_list));
    auto wanted = [&](const char* section) {
        return only.empty() || only == section || (only == "build" && std::string(section) == "trace");
    };

    ClContext ctx = ClContext::create(device);
    if (bvh_options.width == 0)
        bvh_options.width = bvh_width_for(ctx.desc().type == CL_DEVICE_TYPE_GPU,
                                          ctx.device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>());
    const bool small_quantised = resolve_quantised(bvh_options, 0),
               large_quantised = resolve_quantised(bvh_options, kQuantiseAboveTriangles + 1);
    bench_print("BVH node width: {}{}\n", bvh_options.width,
                bvh_options.width != 8 ? ""
                : small_quantised      ? " (quantised boxes)"
                : large_quantised      ? fmt::format(" (quantised boxes above {} triangles)", kQuantiseAboveTriangles)
                                       : "");
    std::vector<BenchCase> cases = {
        {"cornell_box", (fs::path(FACET_SOURCE_DIR) / "scenes" / "cornell_box.json").string()}};
    if (wanted("trace")) {
        for (auto [name, rel] : {std::pair{"bunny", "meshes_common3d/stanford-bunny.obj"},
                                 std::pair{"dragon_res2", "dragon_stanford/dragon_vrip_res2.obj"}}) {
            fs::path p = fs::path(assets) / rel;
            if (fs::exists(p)) cases.push_back({name, p.string()});
            else bench_print("skipping {}: {} not found\n", name, p.string());
        }
        fs::path ply = fs::path(assets) / "dragon_stanford" / "dragon_vrip.ply.gz";  // read by load_scene
        if (!fs::exists(ply)) bench_print("skipping dragon: {} not found\n", ply.string());
        else cases.push_back({"dragon", ply.string()});
    }
    const std::string device_label = fmt::format("{} / {} ({}, {} compute units)", ctx.desc().platform, ctx.desc().name,
                                                 ctx.desc().driver, ctx.desc().compute_units);
    bench_print("## facet bench\n\nDevice: {}. Host: {} hardware threads.\n", device_label,
                std::thread::hardware_concurrency());
    nlohmann::json all;
    all["device"] = ctx.desc().platform + " / " + ctx.desc().name;
    all["device_type"] = ctx.desc().type_name();
    all["compute_units"] = ctx.desc().compute_units;
    all["driver"] = ctx.desc().driver;
    if (wanted("trace")) {
        std::string why;
        if (!embree_available(&why) && only != "build") bench_print("\nEmbree figures skipped: {}.\n", why);
        const int threads = int(std::max<std::uint32_t>(1, ctx.desc().compute_units));
        Markdown build_md({"scene", "triangles", "facet build ms", "facet Mtris/s (1 thread)", "SAH cost",
                           "plain 12-bin Mtris/s", "plain 12-bin SAH", "device bytes/tri",
                           "Embree build Mtris/s (1 thread)"});
        Markdown trace_md({"scene", "rays", "query", "rays in batch", "facet Mrays/s", "Embree 1t ×1",
                           "Embree 1t packet", "Embree 1t stream", fmt::format("Embree {}t ×1", threads),
                           fmt::format("Embree {}t packet", threads), fmt::format("Embree {}t stream", threads),
                           fmt::format("facet ÷ Embree {}t ×1", threads), std::string("same, per CPU-second"),
                           "hit/t mismatches"});
        Markdown render_md({"scene", "image", "render Msamples/s", "render program build s"});
        for (const BenchCase& c : cases) {
            if (!scene_filter.empty() && c.name.find(scene_filter) == std::string::npos) continue;
            fmt::print("  [{}]\n", c.name);
            std::fflush(stdout);
            all["scenes"].push_back(bench_scene(ctx, c, quick, only == "build", facet_only, trace_local, bvh_options,
                                                build_md, trace_md, render_md));
        }
        bench_print(
            "\n### BVH build (one thread; SAH cost normalised by the root's area, a node visit 1, a 4-triangle block test 4)\n\n{}",
            build_md.str());
        if (only != "build") {
            bench_print(
                "\n### Trace: the same rays, facet's kernel on the OpenCL device against Embree on the host\n\n"
                "×1 = rtcIntersect1 / rtcOccluded1; packet = rtcIntersect{{N}}/rtcOccluded{{N}} with the widest native "
                "N; stream = rtcIntersect1M (incoherent flag). {}t = as many threads as the device's compute units; "
                "the ratio column (bold) is facet against Embree ×1 on {} threads by wall time (the goal's ratio); \"per CPU-second\" divides each side's rays by the CPU time the whole process used, which other processes on a shared machine do not inflate. Embree's hit/t mismatches count rays where it and facet disagree on hit or miss / on the distance (1e-3 relative). facet's trace kernels run in work-groups of {}.\n\n{}",
                threads, threads, trace_local, trace_md.str());
            bench_print("\n### Render\n\n{}", render_md.str());
        }
    }
    if (wanted("bsdf")) all["bsdfs"] = bench_bsdfs(ctx, quick);
    if (wanted("ibl")) all["ibl"] = bench_ibl(ctx, assets, quick);
    if (wanted("specialisation")) all["specialisation"] = bench_specialisation(ctx, assets, quick);
    if (wanted("kernels")) all["kernels"] = bench_kernel_resources(ctx, bvh_options);
    if (wanted("quality")) all["quality"] = bench_quality(ctx, quick);
    if (wanted("denoise")) all["denoise"] = bench_denoise(ctx, quick);
    if (wanted("assets")) all["assets"] = bench_assets(ctx, assets, quick);
    if (wanted("instancing")) all["instancing"] = bench_instancing(ctx, assets, quick);
    if (wanted("packet")) all["packet"] = bench_packet(ctx, bvh_options, quick);
    if (!json_out.empty()) {
        if (fs::path(json_out).has_parent_path()) fs::create_directories(fs::path(json_out).parent_path());
        std::ofstream(json_out) << all.dump(2) << "\n";
    }
    if (!md_out.empty()) {
        if (fs::path(md_out).has_parent_path()) fs::create_directories(fs::path(md_out).parent_path());
        std::ofstream(md_out) << bench_markdown();
    }
    return 0;
}

}  // namespace

double process_cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string& bench_markdown() {
    static std::string text;
    return text;
}

}  // namespace facet

int main(int argc, char** argv) {
    try {
        return facet::run(argc, argv);
    } catch (const std::exception& e) {
        fmt::print(stderr, "facet_bench: error: {}\n", e.what());
        return 1;
    }
}
