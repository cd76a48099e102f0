#include "host/report/report.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "host/util/console.hpp"
#include "host/error.hpp"
#include "host/util/safe_write.hpp"

namespace facet {
namespace {

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string(); }

const char* kHeader =
    "pass,spp,wall_s,render_s,compile_s,mse,rmse,relmse,est_mse,est_rmse,est_relmse,denoised_est_mse,"
    "denoised_est_rmse,denoised_mse,denoised_rmse";

// Runs `write`; a facet::Error is a warning naming `path`, said once per path.
bool side_output(const std::string& path, const std::function<void()>& write) {
    try {
        write();
        return true;
    } catch (const Error& e) {
        static std::mutex mutex;
        static std::set<std::string> warned;
        const std::lock_guard<std::mutex> lock(mutex);
        if (warned.insert(path).second)
            say(stderr, "facet: warning: the report {} was not written ({}); the render and its image go on\n", path,
                e.what());
        return false;
    }
}

}  // namespace

void write_text_atomically(const std::string& path, const std::string& text) {
    write_bytes_safely(path, "report", text);
}

namespace {

// Least squares of log(y) on log(x): the slope and its standard error (NaN when fewer
// than 3 points or no spread).
struct SlopeFit {
    double slope = std::nan(""), stderr_ = std::nan("");
};
SlopeFit fit_loglog(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> lx, ly;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] > 0.0 && y[i] > 0.0) lx.push_back(std::log(x[i])), ly.push_back(std::log(y[i]));
    SlopeFit f;
    const std::size_t n = lx.size();
    if (n < 3) return f;
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < n; ++i) mx += lx[i] / double(n), my += ly[i] / double(n);
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < n; ++i) sxx += (lx[i] - mx) * (lx[i] - mx), sxy += (lx[i] - mx) * (ly[i] - my);
    if (!(sxx > 0.0)) return f;
    f.slope = sxy / sxx;
    double rss = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = ly[i] - my - f.slope * (lx[i] - mx);
        rss += r * r;
    }
    f.stderr_ = std::sqrt(rss / double(n - 2) / sxx);
    return f;
}

}  // namespace

void fit_convergence(const std::vector<PassRecord>& passes, ReportSummary& summary) {
    std::vector<double> t, e;
    bool with_reference = !passes.empty() && passes.back().reference.has_value();
    // The first passes carry launch overheads, and with very few samples the
    // half-buffer estimate of heavy-tailed pixels runs low: fit from 8 spp on.
    const std::uint64_t min_spp = with_reference ? 4 : 8;
    std::uint64_t first_spp = 0, last_spp = 0;
    for (const PassRecord& p : passes) {
        if (p.spp < min_spp) continue;
        if (first_spp == 0) first_spp = p.spp;
        last_spp = p.spp;
        t.push_back(p.render_s);
        e.push_back(with_reference ? p.reference->rmse : p.estimate.rmse);
    }
    summary.slope_source = with_reference ? "reference" : "estimate";
    const SlopeFit fit = fit_loglog(t, e);
    summary.slope = fit.slope;
    summary.slope_stderr = fit.stderr_;
    summary.slope_warning.clear();
    summary.slope_judged = std::isfinite(summary.slope) && last_spp >= 10 * first_spp;
    if (!summary.slope_judged) return;  // too short a run to judge the rate
    // Judged with the fit's own uncertainty: heavy-tailed pixels (caustics through glass)
    // make the error curve jump, and a slope only 2 standard errors from -1/2 is no sign
    // of a broken sampler.
    const double slack = 2.0 * (std::isfinite(fit.stderr_) ? fit.stderr_ : 0.0);
    const double steepest = summary.stratified ? -1.6 : -0.65;
    bool too_flat = summary.slope - slack > -0.35;
    const bool too_steep = summary.slope + slack < steepest;
    if (too_flat && with_reference) {
        // Against a reference the error levels off at the reference's own noise: with n_ref
        // samples in the reference and the render's half-buffer variance estimate v at n
        // spp, an unbiased render's MSE against it is about v (1 + n / n_ref). Only an error
        // well above that floor suggests bias.
        const PassRecord& last = passes.back();
        const double n = double(last.spp);
        const double ref_share = summary.reference_spp > 0 ? n / double(summary.reference_spp) : 0.0;
        const double floor = last.estimate.rmse * last.estimate.rmse * (1.0 + ref_share);
        summary.noise_floor_mse = floor;
        if (!(last.reference->rmse * last.reference->rmse > 2.0 * floor)) too_flat = false;
    }
    if (too_flat || too_steep) {
        summary.slope_warning = fmt::format(
            "RMSE falls as time^{:.2f} (+-{:.2f}), far from the time^{} of an unbiased estimator: {}", summary.slope,
            fit.stderr_, summary.stratified ? "-0.5 to -1.5" : "-0.5",
            too_flat ? (with_reference ? "the render may be biased against the reference (its error is above the "
                                         "reference's noise floor)"
                                       : "a sampler may be broken")
                     : "convergence faster than Monte Carlo: check the reference or the run length");
    }
}

bool write_report_csv(const std::string& path, const std::vector<PassRecord>& passes) {
    std::string text = std::string(kHeader) + "\n";
    for (const PassRecord& p : passes) {
        const double nan = std::nan("");
        ErrorMetrics r = p.reference.value_or(ErrorMetrics{nan, nan, nan});
        ErrorMetrics de = p.denoised_estimate.value_or(ErrorMetrics{nan, nan, nan});
        ErrorMetrics dr = p.denoised_reference.value_or(ErrorMetrics{nan, nan, nan});
        text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", p.pass, p.spp, num(p.wall_s),
                            num(p.render_s), num(p.compile_s), num(r.mse), num(r.rmse), num(r.relmse),
                            num(p.estimate.mse), num(p.estimate.rmse), num(p.estimate.relmse), num(de.mse),
                            num(de.rmse), num(dr.mse), num(dr.rmse));
    }
    return side_output(path, [&] { write_text_atomically(path, text); });
}

bool write_report_svg(const std::string& path, const std::vector<PassRecord>& passes, const std::string& title) {
    return side_output(path, [&] { write_error_plot_svg(path, passes, title); });
}

bool write_report_json(const std::string& path, const ReportSummary& s, const std::vector<PassRecord>& passes) {
    nlohmann::json j;
    j["scene"] = s.scene;
    j["device"] = s.device;
    j["image"] = s.image;
    j["reference"] = s.reference;
    j["width"] = s.width;
    j["height"] = s.height;
    j["spp"] = s.spp;
    j["passes"] = passes.size();
    j["wall_s"] = s.wall_s;
    j["render_s"] = s.render_s;
    j["compile_s"] = s.compile_s;
    j["interrupted"] = s.interrupted;
    j["rejected_samples"] = s.rejected_samples;
    auto metrics = [](const ErrorMetrics& m) {
        return nlohmann::json{{"mse", m.mse}, {"rmse", m.rmse}, {"relmse", m.relmse}};
    };
    if (!passes.empty()) {
        if (passes.back().reference) j["final_error"] = metrics(*passes.back().reference);
        j["final_estimate"] = metrics(passes.back().estimate);
        if (passes.back().denoised_estimate) j["final_denoised_estimate"] = metrics(*passes.back().denoised_estimate);
        if (passes.back().denoised_reference) j["final_denoised_error"] = metrics(*passes.back().denoised_reference);
    }
    if (!s.denoiser.empty()) j["denoiser"] = s.denoiser;
    j["rmse_time_slope"] = std::isfinite(s.slope) ? nlohmann::json(s.slope) : nlohmann::json();
    j["rmse_time_slope_source"] = s.slope_source;
    j["rmse_time_slope_judged"] = s.slope_judged;
    j["rmse_time_slope_stderr"] = std::isfinite(s.slope_stderr) ? nlohmann::json(s.slope_stderr) : nlohmann::json();
    if (s.reference_spp > 0) j["reference_spp"] = s.reference_spp;
    if (!s.sampler.empty()) j["sampler"] = s.sampler;
    if (!s.filter.empty()) j["filter"] = {{"type", s.filter}, {"radius", s.filter_radius}};
    // The clamp trades variance for bias: the estimates above do not see the bias.
    j["clamp"] = s.clamp > 0.0 ? nlohmann::json(s.clamp) : nlohmann::json();
    if (s.noise_threshold > 0.0)
        j["adaptive"] = {{"noise_threshold_relmse", s.noise_threshold}, {"reached", s.converged}, {"mode", s.adaptive}};
    if (s.clamp > 0.0) j["clamp_note"] = "each sample clamped: the image is biased (darker) where samples exceed it";
    j["estimator"] = "half-buffer: (a - b)^2 n_a n_b / n^2 per pixel, unbiased for the variance of the image";
    if (!s.slope_warning.empty()) j["warning"] = s.slope_warning;
    return side_output(path, [&] { write_text_atomically(path, j.dump(2) + "\n"); });
}

std::vector<PassRecord> read_report_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(fmt::format("{}: cannot open", path));
    std::string line;
    if (!std::getline(in, line) || line.rfind("pass,spp,wall_s", 0) != 0)
        throw Error(fmt::format("{}:1: not a facet report (expected the header '{}')", path, kHeader));
    std::vector<PassRecord> out;
    int number = 1;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty()) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) f.push_back(cell);
        while (f.size() < 15) f.push_back("");
        auto val = [&](int i) {
            if (f[i].empty()) return std::nan("");
            try {
                std::size_t used = 0;
                double v = std::stod(f[i], &used);
                if (used != f[i].size()) throw std::invalid_argument(f[i]);
                return v;
            } catch (const std::exception&) {
                throw Error(fmt::format("{}:{}: column {} is not a number: '{}'", path, number, i + 1, f[i]));
            }
        };
        PassRecord p;
        p.pass = int(val(0));
        p.spp = std::uint64_t(val(1));
        p.wall_s = val(2), p.render_s = val(3), p.compile_s = val(4);
        if (!f[6].empty()) p.reference = ErrorMetrics{val(5), val(6), val(7)};
        p.estimate = ErrorMetrics{val(8), val(9), val(10)};
        if (!f[12].empty()) p.denoised_estimate = ErrorMetrics{val(11), val(12), std::nan("")};
        if (!f[14].empty()) p.denoised_reference = ErrorMetrics{val(13), val(14), std::nan("")};
        out.push_back(p);
    }
    return out;
}

}  // namespace facet
