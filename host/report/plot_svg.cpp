// Log-log plot of error against render time as a self-contained SVG (no plotting
// tool needed): RMSE against the reference, the half-buffer estimate, and a line of
// slope -1/2 through the last point for comparison.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "host/report/report.hpp"

namespace facet {
namespace {

struct Series {
    std::string name, colour, dash;
    std::vector<std::pair<double, double>> points;  // (time, rmse), both > 0
};

struct Axes {
    double x0, x1, y0, y1;  // log10 ranges
    double left = 70, right = 560, top = 40, bottom = 330;
    double px(double x) const { return left + (std::log10(x) - x0) / (x1 - x0) * (right - left); }
    double py(double y) const { return bottom - (std::log10(y) - y0) / (y1 - y0) * (bottom - top); }
};

std::string polyline(const Axes& a, const Series& s) {
    std::string pts;
    for (auto [x, y] : s.points) pts += fmt::format("{:.1f},{:.1f} ", a.px(x), a.py(y));
    return fmt::format(
        "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" stroke-dasharray=\"{}\" points=\"{}\"/>\n", s.colour,
        s.dash, pts);
}

}  // namespace

void write_error_plot_svg(const std::string& path, const std::vector<PassRecord>& passes, const std::string& title) {
    Series ref{"RMSE vs reference", "#c0392b", "none", {}};
    Series est{"RMSE, half-buffer estimate", "#2471a3", "6,4", {}};
    for (const PassRecord& p : passes) {
        if (!(p.render_s > 0)) continue;
        if (p.reference && p.reference->rmse > 0) ref.points.push_back({p.render_s, p.reference->rmse});
        if (p.estimate.rmse > 0 && std::isfinite(p.estimate.rmse)) est.points.push_back({p.render_s, p.estimate.rmse});
    }
    std::vector<Series> series;
    if (!ref.points.empty()) series.push_back(ref);
    if (!est.points.empty()) series.push_back(est);
    // The -1/2 guide through the last point of the main series.
    if (!series.empty() && series.front().points.size() >= 2) {
        auto [tx, ty] = series.front().points.back();
        double t0 = series.front().points.front().first;
        series.push_back({"slope -1/2", "#7f8c8d", "2,3", {{t0, ty * std::sqrt(tx / t0)}, {tx, ty}}});
    }
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Series& s : series)
        for (auto [x, y] : s.points)
            xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"600\" height=\"400\" font-family=\"sans-serif\" font-size=\"12\">\n"
        "<rect width=\"600\" height=\"400\" fill=\"white\"/>\n";
    svg += fmt::format("<text x=\"300\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n", title);
    if (series.empty()) {
        svg +=
            "<text x=\"300\" y=\"200\" text-anchor=\"middle\">no error data (fewer than two samples per pixel?)</text>\n</svg>\n";
        write_text_atomically(path, svg);
        return;
    }
    Axes a{std::floor(std::log10(xmin)), std::ceil(std::log10(xmax)), std::floor(std::log10(ymin)),
           std::ceil(std::log10(ymax))};
    if (a.x1 <= a.x0) a.x1 = a.x0 + 1;
    if (a.y1 <= a.y0) a.y1 = a.y0 + 1;
    for (double e = a.x0; e <= a.x1; ++e) {
        double x = a.px(std::pow(10.0, e));
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/>"
            "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">1e{4}</text>\n",
            x, a.top, a.bottom, a.bottom + 16, int(e));
    }
    for (double e = a.y0; e <= a.y1; ++e) {
        double y = a.py(std::pow(10.0, e));
        svg += fmt::format(
            "<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"#ddd\"/>"
            "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">1e{5}</text>\n",
            y, a.left, a.right, a.left - 6, y + 4, int(e));
    }
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">render time (s)</text>\n",
                       (a.left + a.right) / 2, a.bottom + 34);
    svg += fmt::format("<text x=\"18\" y=\"{0}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {0})\">RMSE</text>\n",
                       (a.top + a.bottom) / 2);
    int row = 0;
    for (const Series& s : series) {
        svg += polyline(a, s);
        double ly = a.top + 14 + 16 * row++;
        svg += fmt::format(
            "<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" stroke-width=\"2\" stroke-dasharray=\"{4}\"/>"
            "<text x=\"{5}\" y=\"{6}\">{7}</text>\n",
            a.right - 190, ly, a.right - 160, s.colour, s.dash, a.right - 154, ly + 4, s.name);
    }
    svg += "</svg>\n";
    write_text_atomically(path, svg);
}

}  // namespace facet
