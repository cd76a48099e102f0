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

// Pooled over seeds: the mean over the renders of each MSE (true, against the reference,
// and estimated from the halves), reported as RMSE = its square root; and the spread of
// the per-render ratio estimate / true for the denoisers' estimates.
struct Pooled {
    double mse = 0.0, est_mse = 0.0, lo = INFINITY, hi = 0.0, seconds = 0.0;
    int n = 0;
    void add(double rmse, double est_rmse, double s) {
        // A render whose estimate is not positive (NaN: docs/denoising.md) counts as 0
        if (!(est_rmse >= 0.0)) est_rmse = 0.0;
        mse += rmse * rmse, est_mse += est_rmse * est_rmse, seconds += s, ++n;
        lo = std::min(lo, est_rmse / rmse), hi = std::max(hi, est_rmse / rmse);
    }
    double rmse() const { return std::sqrt(mse / n); }
    double est() const { return std::sqrt(est_mse / n); }
    std::string cell(bool spread) const {
        return spread ? fmt::format("{:.4f} ({:.4f}; {:.2f}–{:.2f})", rmse(), est(), lo, hi)
                      : fmt::format("{:.4f} ({:.4f})", rmse(), est());
    }
    nlohmann::json json() const {
        return {{"rmse", rmse()}, {"est", est()}, {"ratio_lo", lo}, {"ratio_hi", hi}, {"seconds", seconds / n}};
    }
};

}  // namespace

nlohmann::json bench_denoise(ClContext& ctx, bool quick) {
    const std::uint32_t size = quick ? 64 : 128, ref_spp = quick ? 256 : 1024;
    const std::vector<std::uint32_t> seeds =
        quick ? std::vector<std::uint32_t>{0, 1} : std::vector<std::uint32_t>{0, 1, 2, 3};
    const std::string oidn = find_oidn("");
    nlohmann::json out = {{"rows", nlohmann::json::array()}, {"timing", nlohmann::json::array()}};
    bench_print("\n### Denoising ({}², reference {} spp of another seed, its noise subtracted; {} seeds pooled)\n\n",
                size, ref_spp, seeds.size());
    if (oidn.empty()) bench_print("OIDN not found (pip install pyoidn, or $FACET_OIDN): its columns are skipped.\n\n");
    else bench_print("OIDN: {}\n\n", oidn);
    bench_print(
        "RMSE against the reference pooled over the seeds (the root of the mean MSE), in brackets the half-buffer "
        "estimate pooled the same way and, for the denoisers, the range over the seeds of estimate / true; times "
        "in seconds, means over the seeds (facet's: uploading, filtering and reading back; its program is built "
        "once, as a render session builds it while rendering).\n\n");
    Markdown md({"scene", "sampler", "spp", "noisy", "facet", "OIDN", "facet s / render s", "OIDN s"});
    const Denoiser denoiser(ctx);
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
        for (std::uint32_t spp : {4u, 16u, 64u}) {
            Pooled noisy, facet, oidn_p;
            double render_s = 0.0;
            for (std::uint32_t seed : seeds) {
                Scene seeded = scene;
                seeded.settings.seed = scene.settings.seed + seed;
                Renderer r(ctx, seeded, bvh);
                const double render_before = r.stats().render_seconds;
                render_fixed(r, spp);
                render_s += (r.stats().render_seconds - render_before) / double(seeds.size());
                const FilmHalves h = r.halves();
                const AovImages f = render_aovs(ctx, seeded, bvh, std::min(spp, 64u));
                const ErrorMetrics noisy_est = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
                noisy.add(true_rmse(mean_of(h), ref), noisy_est.rmse, 0.0);
                const DenoisedImage d = denoiser.run(size, size, h, f);
                facet.add(true_rmse(d.rgb, ref), estimate_denoised_error(h, d).rmse, d.seconds);
                if (!oidn.empty()) {
                    const DenoisedImage o = denoise_oidn(oidn, size, size, h, f);
                    oidn_p.add(true_rmse(o.rgb, ref), estimate_denoised_error(h, o).rmse, o.seconds);
                }
            }
            nlohmann::json row = {{"scene", c.scene},      {"sampler", sampler},    {"spp", spp},
                                  {"seeds", seeds.size()}, {"noisy", noisy.json()}, {"facet", facet.json()},
                                  {"render_s", render_s}};
            if (!oidn.empty()) row["oidn"] = oidn_p.json();
            md.row({c.scene, sampler, std::to_string(spp), noisy.cell(false), facet.cell(true),
                    oidn.empty() ? "skipped" : oidn_p.cell(true),
                    fmt::format("{:.3f} / {:.2f}", facet.seconds / facet.n, render_s),
                    oidn.empty() ? "-" : fmt::format("{:.2f}", oidn_p.seconds / oidn_p.n)});
            out["rows"].push_back(row);
        }
    }
    bench_print("{}", md.str());

    // The denoiser's time against the render's at larger sizes (the Cornell box)
    bench_print(
        "\n### Denoising time against render time (cornell_box; median of 3 denoises)\n\n"
        "denoise s: what a render with --denoise facet adds after its last sample (Denoiser::run: upload, filter, "
        "read back); the program's build ({:.3f} s here) runs on its own thread while the render does.\n\n",
        denoiser.build_seconds());
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
        const double s = median3([&] { denoiser.run(side, side, h, f); });
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
