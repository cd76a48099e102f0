// Issue 29's packet paths (kernels/integrator/packet_paths.cl): the Cornell box rendered by
// render_pass (one path per work-item) and by packet_pass (eight paths per work-item in
// float8 lanes), alternated, same seed and samples.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"

namespace facet {

nlohmann::json bench_packet(ClContext& ctx, const BvhOptions& bvh_options, bool quick) {
    namespace fs = std::filesystem;
    Scene scene = load_scene((fs::path(FACET_SOURCE_DIR) / "scenes" / "cornell_box.json").string());
    const std::uint32_t size = quick ? 128 : 256, spp = quick ? 16 : 64;
    scene.settings.width = scene.settings.height = size;
    Bvh bvh = build_bvh(scene.vertices, bvh_options);
    const std::size_t pixels = std::size_t(size) * size;
    // Two renderers of the same paths: packets forced on, and off (host/render/packet_paths.hpp
    // reads FACET_PACKET_PATHS when a renderer is built).
    const char* was = std::getenv("FACET_PACKET_PATHS");
    const std::string saved = was ? was : "";
    setenv("FACET_PACKET_PATHS", "1", 1);
    Renderer packets(ctx, scene, bvh);
    setenv("FACET_PACKET_PATHS", "0", 1);
    Renderer scalar(ctx, scene, bvh);
    if (was) setenv("FACET_PACKET_PATHS", saved.c_str(), 1);
    else unsetenv("FACET_PACKET_PATHS");
    auto timed = [&](Renderer& r) {
        r.reset();
        render_fixed(r, spp);
        return r.stats().render_seconds;
    };
    timed(packets);
    timed(scalar);
    std::vector<double> tp, ts;
    for (int r = 0; r < (quick ? 2 : 5); ++r) {
        ts.push_back(timed(scalar));
        tp.push_back(timed(packets));
    }
    std::sort(tp.begin(), tp.end());
    std::sort(ts.begin(), ts.end());
    const double mp = tp[tp.size() / 2], ms = ts[ts.size() / 2];
    // the two images: the mean of both halves, pixel by pixel
    const Renderer::Halves hs = scalar.halves(), hp = packets.halves();
    double rejected = 0.0;
    packets.image(&rejected);
    double mean_s = 0, mean_p = 0, diff2 = 0;
    std::size_t same = 0;
    for (std::size_t k = 0; k < 3 * pixels; ++k) {
        const double a = 0.5 * (double(hs.rgb[0][k]) + double(hs.rgb[1][k]));
        const double b = 0.5 * (double(hp.rgb[0][k]) + double(hp.rgb[1][k]));
        mean_s += a;
        mean_p += b;
        diff2 += (a - b) * (a - b);
        if (std::fabs(a - b) <= 1e-4 * std::max(1e-3, std::fabs(a))) ++same;
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
