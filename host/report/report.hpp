// The error-against-time report of a progressive render: one row per pass, written
// as CSV (atomically, after every pass), a JSON summary beside it, and a log-log
// plot as SVG (plot_svg.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/film/error_metrics.hpp"

namespace facet {

struct PassRecord {
    int pass = 0;
    std::uint64_t spp = 0;
    double wall_s = 0.0;                    // since the command started, kernel build included
    double render_s = 0.0;                  // inside render passes only
    double compile_s = 0.0;                 // the kernel build
    std::optional<ErrorMetrics> reference;  // against --reference
    ErrorMetrics estimate;                  // from the two half-buffers
    // With --denoise, on the row of the image denoised (the last): the denoised image's
    // error estimated from the half-buffers (denoise/denoise_error.hpp) and against --reference.
    std::optional<ErrorMetrics> denoised_estimate;
    std::optional<ErrorMetrics> denoised_reference;
};

struct ReportSummary {
    std::string scene, device, image, reference;
    std::uint64_t spp = 0;
    int width = 0, height = 0;
    double wall_s = 0.0, render_s = 0.0, compile_s = 0.0;
    bool interrupted = false;
    double rejected_samples = 0.0;
    double slope = 0.0;               // fitted log-log slope of RMSE against render time
    double slope_stderr = 0.0;        // its standard error (least squares)
    std::int64_t reference_spp = -1;  // the reference's facet:spp metadata, -1 when unknown
    double noise_floor_mse = 0.0;     // the MSE an unbiased render would show against it
    std::string slope_source;         // "reference" or "estimate"
    std::string slope_warning;        // empty when the slope is near -1/2 (or not judged)
    bool slope_judged = false;        // the fit spans at least a decade of samples per pixel
    // The sampler stratifies (scrambled Sobol'): RMSE may then fall faster than
    // time^-1/2, down to about time^-3/2 for smooth pixels (Owen 1997), so only a slope
    // steeper than that is suspicious. "sampler" names it in the JSON summary.
    bool stratified = false;
    std::string sampler;
    std::string filter;            // the pixel filter's name
    double filter_radius = 0.0;    // pixels
    double clamp = 0.0;            // --clamp (biased) when > 0, else off
    double noise_threshold = 0.0;  // --noise-threshold (relMSE) when > 0
    bool converged = false;        // ended by reaching it
    std::string adaptive;          // "global" or "tiles" with a threshold, else empty
    std::string denoiser;          // the denoiser that ran ("facet", "oidn"), else empty
};

// The fitted slope of RMSE against render time over the passes (reference RMSE when
// there is one, else the estimate), and a warning when it is far from -1/2 beyond twice
// its standard error over a run that spans at least a decade of samples per pixel;
// against a reference, only when the final error is also above the reference's noise
// floor (summary.reference_spp, when known).
void fit_convergence(const std::vector<PassRecord>& passes, ReportSummary& summary);

// The report of a render is a side output: a CSV, JSON summary or SVG plot that cannot be
// written is a warning on stderr (once per file: the CSV is rewritten after every pass),
// never the end of the render nor the loss of its image. Each returns whether it wrote.
bool write_report_csv(const std::string& path, const std::vector<PassRecord>& passes);
bool write_report_json(const std::string& path, const ReportSummary& summary, const std::vector<PassRecord>& passes);
bool write_report_svg(const std::string& path, const std::vector<PassRecord>& passes, const std::string& title);

// Log-log plot of RMSE (reference and estimate) against render time, as SVG (`facet
// plot`, where it is the output: throws facet::Error naming the file on failure).
void write_error_plot_svg(const std::string& path, const std::vector<PassRecord>& passes, const std::string& title);

// Reads a CSV written by write_report_csv (for `facet plot`). Throws facet::Error
// naming the file and line on malformed input.
std::vector<PassRecord> read_report_csv(const std::string& path);

// Writes `text` to `path` through write_file_safely (util/safe_write.hpp): the old file
// or the complete new one.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace facet
