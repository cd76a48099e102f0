// Issue 29's packet paths (kernels/integrator/packet_paths.cl): the Cornell box rendered by
// render_pass (one path per work-item) and by packet_pass (eight paths per work-item in
// float8 lanes), alternated, same seed and samples.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/film/film_layout.hpp"
#include "host/render/features.hpp"
#include "host/render/packet_paths.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/render/scene_buffers.hpp"
#include "host/readers/load_scene.hpp"
#include "host/scene/device_scene.hpp"

namespace facet {

nlohmann::json bench_packet(ClContext& ctx, const BvhOptions& bvh_options, bool quick) {
    namespace fs = std::filesystem;
    Scene scene = load_scene((fs::path(FACET_SOURCE_DIR) / "scenes" / "cornell_box.json").string());
    const std::uint32_t size = quick ? 128 : 256, spp = quick ? 16 : 64;
    scene.settings.width = scene.settings.height = size;
    Bvh bvh = build_bvh(scene.vertices, bvh_options);
    const DeviceScene dev = compile(scene, bvh);
    const std::size_t pixels = std::size_t(size) * size;
    const std::size_t floats = film_floats(pixels);  // render_pass's accumulation layout
    std::vector<float> sums(floats);
    std::vector<std::string> prelude = scene_program_prelude(scene, bvh);
    prelude.push_back("#define FC_PACKET_PATHS 1");
    const ProgramBuild build = build_program(ctx, kRenderProgram, prelude);
    cl::Kernel kernel(build.program, "packet_pass");
    const SceneBuffers buffers = upload_scene(ctx.context(), dev);
    cl::Buffer accum(ctx.context(), CL_MEM_READ_WRITE, floats * sizeof(float));
    kernel.setArg(bind_scene(kernel, buffers), accum);
    auto packet_render = [&]() {
        ctx.queue().enqueueFillBuffer(accum, 0.0f, 0, floats * sizeof(float));
        ctx.queue().finish();
        const auto t0 = std::chrono::steady_clock::now();
        const std::uint32_t rows = std::max<std::uint32_t>(1, (1u << 18) / (size * spp) * 8);
        for (std::uint32_t row = 0; row < size; row += rows) {
            FcRenderParams p = dev.params;
            p.sample_begin = 0;
            p.sample_count = spp;
            p.row_begin = row;
            p.row_count = std::min(rows, size - row);
            ctx.queue().enqueueWriteBuffer(buffers.params, CL_TRUE, 0, sizeof p, &p);
            const std::size_t items = std::size_t(p.row_count) * packet_items_per_row(size);
            ctx.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange((items + 63) / 64 * 64),
                                             cl::NDRange(64));
        }
        ctx.queue().finish();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ctx.queue().enqueueReadBuffer(accum, CL_TRUE, 0, floats * sizeof(float), sums.data());
        return s;
    };
    // the scalar form: a renderer with packets turned off (host/render/packet_paths.hpp)
    const char* was = std::getenv("FACET_PACKET_PATHS");
    const std::string saved = was ? was : "";
    setenv("FACET_PACKET_PATHS", "0", 1);
    Renderer renderer(ctx, scene, bvh);
    if (was) setenv("FACET_PACKET_PATHS", saved.c_str(), 1);
    else unsetenv("FACET_PACKET_PATHS");
    auto scalar_render = [&]() {
        renderer.reset();
        render_fixed(renderer, spp);
        return renderer.stats().render_seconds;
    };
    packet_render();
    scalar_render();
    std::vector<double> tp, ts;
    for (int r = 0; r < (quick ? 2 : 5); ++r) {
        ts.push_back(scalar_render());
        tp.push_back(packet_render());
    }
    std::sort(tp.begin(), tp.end());
    std::sort(ts.begin(), ts.end());
    const double mp = tp[tp.size() / 2], ms = ts[ts.size() / 2];
    // the two images: the mean of both halves, pixel by pixel
    Renderer::Halves h = renderer.halves();
    double mean_s = 0, mean_p = 0, diff2 = 0, rejected = 0;
    std::size_t same = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            const std::size_t k = 3 * i + std::size_t(c);
            const double a = 0.5 * (double(h.rgb[0][k]) + double(h.rgb[1][k]));
            const double b =
                (double(sums[4 * i + std::size_t(c)]) + double(sums[4 * (pixels + i) + std::size_t(c)])) / double(spp);
            mean_s += a;
            mean_p += b;
            diff2 += (a - b) * (a - b);
            if (std::fabs(a - b) <= 1e-4 * std::max(1e-3, std::fabs(a))) ++same;
        }
        rejected += double(sums[4 * i + 3]) + double(sums[4 * (pixels + i) + 3]);
    }
    const double msamples = double(pixels) * spp * 1e-6;
    bench_print("\n### Packet paths: the Cornell box at {}², {} spp (issue 29)\n\n", size, spp);
    bench_print("| kernel | median s | Msamples/s |\n|---|---|---|\n");
    bench_print("| render_pass (1 path a work-item) | {:.3f} | {:.3f} |\n", ms, msamples / ms);
    bench_print("| packet_pass (8 paths a work-item, float8 lanes) | {:.3f} | {:.3f} |\n", mp, msamples / mp);
    bench_print(
        "\npacket ÷ scalar speed {:.2f}; image means {:.6f} / {:.6f}; RMS difference {:.3g}; "
        "pixel channels equal to 1e-4: {:.1f} %; rejected samples {}\n",
        ms / mp, mean_s / (3.0 * pixels), mean_p / (3.0 * pixels), std::sqrt(diff2 / (3.0 * pixels)),
        100.0 * double(same) / (3.0 * pixels), rejected);
    return {{"scalar_s", ms}, {"packet_s", mp}, {"speedup", ms / mp}};
}

}  // namespace facet
