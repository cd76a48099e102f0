// `facet plot REPORT.csv`: a render report's error against time as a log-log SVG.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/image/image_io.hpp"
#include "host/report/report.hpp"

namespace facet {

int run_plot(const PlotOptions& opt) {
    std::vector<PassRecord> passes = read_report_csv(opt.report);
    std::string out = opt.out.empty() ? replace_extension(opt.report, ".svg") : opt.out;
    write_error_plot_svg(out, passes, opt.report);
    fmt::print("wrote    {}\n", out);
    return kExitOk;
}

}  // namespace facet
