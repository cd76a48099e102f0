// Denoising (issue 30): facet's denoiser and Intel Open Image Denoise on the demo scenes,
// error against a long reference and the half-buffer estimate (docs/denoising.md), and the
// denoiser's time against the render's. Figures, not tests.
//
// The reference R is a long render of another seed; its own noise is subtracted: for an
// image X independent of R, E[mean (X - R)^2] = mse(X) + mean Var(R), with Var(R) of each
// pixel from R's halves, (R_a - R_b)^2 n_a n_b / n^2 (as host/film/error_metrics.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/bvh/bvh.hpp"
#include "host/denoise/denoise_error.hpp"
#include "host/denoise/denoiser.hpp"
#include "host/denoise/oidn.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/aov.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The reference: its mean image and the mean over pixels and channels of its variance.
struct Reference {
    std::vector<float> rgb;
    double variance = 0.0;
};

Reference reference_of(const FilmHalves& h) {
    Reference r;
    const double n = double(h.samples[0] + h.samples[1]);
    const double wa = double(h.samples[0]) / n, wb = double(h.samples[1]) / n;
    r.rgb.resize(h.rgb[0].size());
    for (std::size_t i = 0; i < r.rgb.size(); ++i) {
        const double a = double(h.rgb[0][i]), b = double(h.rgb[1][i]);
        r.rgb[i] = float(wa * a + wb * b);
        r.variance += (a - b) * (a - b) * wa * wb;
    }
    r.variance /= double(r.rgb.size());
    return r;
}

// The RMSE of `x` against the reference, its noise subtracted (NaN when not positive).
double true_rmse(const std::vector<float>& x, const Reference& ref) {
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double e = double(x[i]) - double(ref.rgb[i]);
        sum += e * e;
    }
    const double mse = sum / double(x.size()) - ref.variance;
    return mse > 0.0 ? std::sqrt(mse) : std::nan("");
}

std::vector<float> mean_of(const FilmHalves& h) {
    const double n = double(h.samples[0] + h.samples[1]);
    std::vector<float> m(h.rgb[0].size());
    for (std::size_t i = 0; i < m.size(); ++i)
        m[i] = float((double(h.samples[0]) * double(h.rgb[0][i]) + double(h.samples[1]) * double(h.rgb[1][i])) / n);
    return m;
}

std::string cell(double rmse, double estimate) { return fmt::format("{:.4f} ({:.4f})", rmse, estimate); }

// The median of three runs of `f`, in seconds.
template <typename F>
double median3(F f) {
    double t[3];
    for (double& s : t) {
        const auto start = std::chrono::steady_clock::now();
        f();
        s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::sort(t, t + 3);
    return t[1];
}

}  // namespace

nlohmann::json bench_denoise(ClContext& ctx, bool quick) {
    const std::uint32_t size = quick ? 64 : 128, ref_spp = quick ? 256 : 1024;
    const std::string oidn = find_oidn("");
    nlohmann::json out = {{"rows", nlohmann::json::array()}, {"timing", nlohmann::json::array()}};
    bench_print("\n### Denoising ({}², reference {} spp of another seed, its noise subtracted)\n\n", size, ref_spp);
    if (oidn.empty()) bench_print("OIDN not found (pip install pyoidn, or $FACET_OIDN): its columns are skipped.\n\n");
    else bench_print("OIDN: {}\n\n", oidn);
    bench_print("RMSE against the reference, in brackets the half-buffer estimate; times in seconds.\n\n");
    Markdown md({"scene", "sampler", "spp", "noisy", "facet", "OIDN", "facet s / render s", "OIDN s"});
    // Warm-up: the denoiser's program built once
    {
        FilmHalves h;
        h.samples[0] = h.samples[1] = 1;
        h.rgb[0].assign(3 * 16, 0.5f), h.rgb[1] = h.rgb[0];
        AovImages f;
        f.albedo.assign(3 * 16, 0.5f), f.normal.assign(3 * 16, 0.0f), f.depth.assign(16, 1.0f);
        denoise(ctx, 4, 4, h, f);
    }
    struct Case {
        const char* scene;
        int sampler;
    };
    for (Case c : {Case{"cornell_box", FC_SAMPLER_SOBOL}, Case{"cornell_box", FC_SAMPLER_INDEPENDENT},
                   Case{"spheres_sky", FC_SAMPLER_SOBOL}, Case{"material_grid", FC_SAMPLER_SOBOL}}) {
        Scene scene = load_scene((fs::path(FACET_SOURCE_DIR) / "scenes" / (std::string(c.scene) + ".json")).string());
        scene.settings.width = scene.settings.height = size;
        scene.settings.sampler = c.sampler;
        const char* sampler = c.sampler == FC_SAMPLER_SOBOL ? "sobol" : "independent";
        const Bvh bvh = build_bvh(scene.vertices);
        Scene ref_scene = scene;
        ref_scene.settings.seed = scene.settings.seed + 4242;
        Renderer ref_renderer(ctx, ref_scene, bvh);
        render_fixed(ref_renderer, ref_spp);
        const Reference ref = reference_of(ref_renderer.halves());
        Renderer r(ctx, scene, bvh);
        for (std::uint32_t spp : {4u, 16u, 64u}) {
            r.reset();
            const double render_before = r.stats().render_seconds;
            render_fixed(r, spp);
            const double render_s = r.stats().render_seconds - render_before;
            const FilmHalves h = r.halves();
            const AovImages f = render_aovs(ctx, scene, bvh, std::min(spp, 64u));
            const ErrorMetrics noisy_est = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
            const DenoisedImage d = denoise(ctx, size, size, h, f);
            const double noisy = true_rmse(mean_of(h), ref), facet = true_rmse(d.rgb, ref);
            const double facet_est = estimate_denoised_error(h, d).rmse;
            nlohmann::json row = {{"scene", c.scene},       {"sampler", sampler},          {"spp", spp},
                                  {"noisy_rmse", noisy},    {"noisy_est", noisy_est.rmse}, {"facet_rmse", facet},
                                  {"facet_est", facet_est}, {"facet_s", d.seconds},        {"render_s", render_s}};
            std::string oidn_cell = "skipped", oidn_s = "-";
            if (!oidn.empty()) {
                const DenoisedImage o = denoise_oidn(oidn, size, size, h, f);
                const double rmse = true_rmse(o.rgb, ref), est = estimate_denoised_error(h, o).rmse;
                oidn_cell = cell(rmse, est), oidn_s = fmt::format("{:.2f}", o.seconds);
                row["oidn_rmse"] = rmse, row["oidn_est"] = est, row["oidn_s"] = o.seconds;
            }
            md.row({c.scene, sampler, std::to_string(spp), cell(noisy, noisy_est.rmse), cell(facet, facet_est),
                    oidn_cell, fmt::format("{:.3f} / {:.2f}", d.seconds, render_s), oidn_s});
            out["rows"].push_back(row);
        }
    }
    bench_print("{}", md.str());

    // The denoiser's time against the render's at larger sizes (the Cornell box)
    bench_print("\n### Denoising time against render time (cornell_box; median of 3 denoises)\n\n");
    Markdown tm(
        {"size", "denoise s", "render s 16 spp", "render s 64 spp", "denoise / render 16", "denoise / render 64"});
    for (std::uint32_t side : quick ? std::vector<std::uint32_t>{128} : std::vector<std::uint32_t>{256, 512}) {
        Scene scene = load_scene((fs::path(FACET_SOURCE_DIR) / "scenes" / "cornell_box.json").string());
        scene.settings.width = scene.settings.height = side;
        const Bvh bvh = build_bvh(scene.vertices);
        Renderer r(ctx, scene, bvh);
        render_fixed(r, 1);  // warm-up
        double render[2];
        for (int k = 0; k < 2; ++k) {
            r.reset();
            const double before = r.stats().render_seconds;
            render_fixed(r, k == 0 ? 16 : 64);
            render[k] = r.stats().render_seconds - before;
        }
        const FilmHalves h = r.halves();
        const AovImages f = render_aovs(ctx, scene, bvh, 16);
        const double s = median3([&] { denoise(ctx, side, side, h, f); });
        tm.row({fmt::format("{}²", side), fmt::format("{:.3f}", s), fmt::format("{:.2f}", render[0]),
                fmt::format("{:.2f}", render[1]), fmt::format("{:.1f} %", 100.0 * s / render[0]),
                fmt::format("{:.1f} %", 100.0 * s / render[1])});
        out["timing"].push_back(
            {{"size", side}, {"denoise_s", s}, {"render16_s", render[0]}, {"render64_s", render[1]}});
    }
    bench_print("{}", tm.str());
    return out;
}

}  // namespace facet
