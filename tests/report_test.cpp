// Error against run time: metrics, the half-buffer estimate, the convergence fit and
// the report files, on the real kernels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "host/bvh/bvh.hpp"
#include "tests/cl_test_env.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/image/image_io.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/report/report.hpp"
#include "host/scene/scene.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

Scene furnace(int size) {
    Scene scene;
    Material m = default_material();
    for (int c = 0; c < 3; ++c) m.diffuse[c] = m.emission[c] = 0.5f;
    scene.materials.push_back(m);
    scene.material_names.push_back("furnace");
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 2, 0, true);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fov_y_degrees = 90.0f;
    scene.settings.width = scene.settings.height = size;
    scene.settings.max_depth = 1024;
    return scene;
}

TEST(Report, MetricsOfKnownImages) {
    std::vector<float> ref(12, 1.0f), img(12, 1.0f);
    img[0] = 2.0f;  // one channel off by 1
    ErrorMetrics m = compare_images(img, ref);
    EXPECT_DOUBLE_EQ(m.mse, 1.0 / 12.0);
    EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(1.0 / 12.0));
    EXPECT_NEAR(m.relmse, 1.0 / (1.01 * 1.01) / 12.0, 1e-12);
    std::vector<float> bad = ref;
    bad[5] = NAN;
    EXPECT_THROW(compare_images(img, bad, "ref.exr"), Error);
    EXPECT_THROW(compare_images(img, std::vector<float>(6, 1.0f), "ref.exr"), Error);
}

TEST(Report, LogLogSlope) {
    std::vector<double> x, y;
    for (int i = 1; i <= 64; i *= 2) x.push_back(i), y.push_back(3.0 / std::sqrt(double(i)));
    EXPECT_NEAR(loglog_slope(x, y), -0.5, 1e-12);
    EXPECT_TRUE(std::isnan(loglog_slope({1.0, 2.0}, {1.0, 2.0})));
}

// The furnace's answer is 1 everywhere: the RMSE against it falls as spp^-1/2 over
// 1.8 decades with independent samples, at least as fast with scrambled Sobol' ones,
// and the half-buffer estimate tracks the true error with either sampler.
void furnace_convergence(int sampler, double steepest, double shallowest) {
    Scene scene = furnace(48);
    scene.settings.sampler = sampler;
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    std::vector<float> ones(3 * r.pixel_count(), 1.0f);
    std::vector<double> spp, rmse;
    ErrorMetrics last_true, last_est;
    for (std::uint32_t target = 1; target <= 64; target *= 2) {
        render_fixed(r, target - r.stats().samples_per_pixel);
        last_true = compare_images(r.image(), ones);
        Renderer::Halves h = r.halves();
        last_est = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
        spp.push_back(double(target));
        rmse.push_back(last_true.rmse);
    }
    double slope = loglog_slope(spp, rmse);
    EXPECT_GE(slope, steepest);
    EXPECT_LE(slope, shallowest);
    EXPECT_GT(last_est.rmse, last_true.rmse / 1.5);
    EXPECT_LT(last_est.rmse, last_true.rmse * 1.5);
}

TEST(Report, FurnaceErrorConvergesAtMonteCarloRate) { furnace_convergence(FC_SAMPLER_INDEPENDENT, -0.6, -0.4); }

TEST(Report, FurnaceErrorConvergesWithSobolAtLeastAsFast) { furnace_convergence(FC_SAMPLER_SOBOL, -1.6, -0.45); }

TEST(Report, ConvergenceWarningFlagsBias) {
    std::vector<PassRecord> passes;
    for (int i = 0; i < 8; ++i) {
        PassRecord p;
        p.pass = i + 1;
        p.spp = 8u << i;
        p.render_s = 0.1 * double(1 << i);
        p.estimate = ErrorMetrics{0.0, 0.01 / std::sqrt(double(1 << i)), 0.0};
        p.reference = ErrorMetrics{0.0, 0.2, 0.0};  // stuck: a biased render
        passes.push_back(p);
    }
    ReportSummary s;
    fit_convergence(passes, s);
    EXPECT_EQ(s.slope_source, "reference");
    EXPECT_NEAR(s.slope, 0.0, 1e-9);
    EXPECT_FALSE(s.slope_warning.empty());
    for (PassRecord& p : passes) p.reference.reset();
    fit_convergence(passes, s);
    EXPECT_NEAR(s.slope, -0.5, 1e-9);
    EXPECT_TRUE(s.slope_warning.empty());
    // Faster than Monte Carlo: suspicious with independent samples, expected with a
    // stratifying sampler up to time^-1.5.
    for (std::size_t i = 0; i < passes.size(); ++i) passes[i].estimate.rmse = 0.01 / double(1 << i);
    fit_convergence(passes, s);
    EXPECT_NEAR(s.slope, -1.0, 1e-9);
    EXPECT_FALSE(s.slope_warning.empty());
    s.stratified = true;
    fit_convergence(passes, s);
    EXPECT_TRUE(s.slope_warning.empty());
}

TEST(Report, NoBiasWarningAtTheReferenceNoiseFloor) {
    // An unbiased render measured against a 64 spp reference: its error against the
    // reference levels off at the reference's own noise, sqrt(v (1 + n / 64)).
    std::vector<PassRecord> passes;
    for (int i = 0; i < 8; ++i) {
        PassRecord p;
        p.pass = i + 1;
        p.spp = 8u << i;
        p.render_s = 0.1 * double(1 << i);
        const double v = 0.04 / double(p.spp);  // the render's variance
        p.estimate = ErrorMetrics{v, std::sqrt(v), 0.0};
        const double floor_mse = v + 0.04 / 64.0;
        p.reference = ErrorMetrics{floor_mse, std::sqrt(floor_mse), 0.0};
        passes.push_back(p);
    }
    ReportSummary s;
    fit_convergence(passes, s);
    ASSERT_TRUE(s.slope_judged);
    EXPECT_GT(s.slope, -0.35) << "the curve flattens: without the floor it would be flagged";
    EXPECT_FALSE(s.slope_warning.empty()) << "without the reference's sample count the floor is v alone";
    s.reference_spp = 64;
    fit_convergence(passes, s);
    EXPECT_TRUE(s.slope_warning.empty()) << s.slope_warning;
    // A real bias stays flagged: the error is far above the floor.
    for (PassRecord& p : passes) p.reference->rmse = 0.2;
    fit_convergence(passes, s);
    EXPECT_FALSE(s.slope_warning.empty());
}

TEST(Report, HeavyTailedEstimateIsNotABrokenSampler) {
    // The half-buffer estimate of a scene with rare bright paths (glass under a sun)
    // jumps when a firefly lands in one half: the fitted slope is flat, but with an
    // uncertainty that covers -1/2, so no "broken sampler" warning.
    const double jumps[] = {1.0, 3.0, 0.9, 2.5, 0.8, 2.2, 0.7, 1.9};
    std::vector<PassRecord> passes;
    for (int i = 0; i < 8; ++i) {
        PassRecord p;
        p.pass = i + 1;
        p.spp = 8u << i;
        p.render_s = 0.1 * double(1 << i);
        p.estimate = ErrorMetrics{0.0, jumps[i] * 0.05 / std::sqrt(std::sqrt(double(1 << i))), 0.0};
        passes.push_back(p);
    }
    ReportSummary s;
    fit_convergence(passes, s);
    ASSERT_TRUE(s.slope_judged);
    EXPECT_GT(s.slope, -0.35);
    EXPECT_GT(s.slope_stderr, 0.05);
    EXPECT_TRUE(s.slope_warning.empty()) << s.slope_warning;
    // The same slope on a smooth curve is flagged.
    for (int i = 0; i < 8; ++i) passes[std::size_t(i)].estimate.rmse = 0.05 / std::pow(double(1 << i), 0.2);
    fit_convergence(passes, s);
    EXPECT_FALSE(s.slope_warning.empty());
}

TEST(Report, CsvRoundTripAndPlot) {
    const test::TempDir tmp;
    const fs::path& dir = tmp.dir();
    std::vector<PassRecord> passes(3);
    for (int i = 0; i < 3; ++i) {
        passes[i].pass = i + 1;
        passes[i].spp = std::uint64_t(1) << i;
        passes[i].render_s = 0.5 * (i + 1);
        passes[i].estimate = ErrorMetrics{0.25, 0.5, 0.1};
    }
    passes[2].reference = ErrorMetrics{0.04, 0.2, 0.3};
    passes[2].denoised_estimate = ErrorMetrics{0.01, 0.1, 0.0};
    passes[2].denoised_reference = ErrorMetrics{0.0121, 0.11, 0.0};
    std::string csv = (dir / "r.csv").string();
    write_report_csv(csv, passes);
    std::vector<PassRecord> back = read_report_csv(csv);
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[2].spp, 4u);
    EXPECT_FALSE(back[0].reference.has_value());
    ASSERT_TRUE(back[2].reference.has_value());
    EXPECT_DOUBLE_EQ(back[2].reference->rmse, 0.2);
    EXPECT_FALSE(back[1].denoised_estimate.has_value());
    ASSERT_TRUE(back[2].denoised_estimate.has_value() && back[2].denoised_reference.has_value());
    EXPECT_DOUBLE_EQ(back[2].denoised_estimate->rmse, 0.1);
    EXPECT_DOUBLE_EQ(back[2].denoised_reference->rmse, 0.11);
    write_error_plot_svg((dir / "r.svg").string(), back, "test");
    EXPECT_GT(fs::file_size(dir / "r.svg"), 500u);
    std::ofstream(dir / "bad.csv") << "pass,spp,wall_s\n1,x,2\n";
    try {
        read_report_csv((dir / "bad.csv").string());
        FAIL() << "a malformed report must be refused";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
    }
}

TEST(Report, BadReferencesAreRefused) {
    const test::TempDir tmp;
    const fs::path& dir = tmp.dir();
    std::vector<float> rgb(3 * 4 * 2, 0.5f);
    write_exr((dir / "small.exr").string(), 4, 2, rgb);
    auto message = [&](const std::string& path, int w, int h) {
        try {
            read_reference(path, w, h);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message((dir / "small.exr").string(), 8, 8).find("4x2"), std::string::npos);
    EXPECT_NE(message((dir / "missing.exr").string(), 4, 2).find("missing.exr"), std::string::npos);
    rgb[7] = NAN;
    write_exr((dir / "nan.exr").string(), 4, 2, rgb);
    std::string m = message((dir / "nan.exr").string(), 4, 2);
    EXPECT_NE(m.find("not finite"), std::string::npos) << m;
    EXPECT_NE(m.find("nan.exr"), std::string::npos) << m;
    EXPECT_EQ(read_reference((dir / "small.exr").string(), 4, 2).width, 4);
}

}  // namespace
}  // namespace facet
