#include "host/cli/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "host/util/console.hpp"

namespace facet {

std::string fmt_seconds(double s) {
    if (!std::isfinite(s)) return "?";
    if (s < 60) return fmt::format("{:.1f}s", s);
    if (s < 3600) return fmt::format("{}m{:02d}s", int(s) / 60, int(s) % 60);
    return fmt::format("{}h{:02d}m", int(s) / 3600, (int(s) % 3600) / 60);
}

Progress::Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDOUT_FILENO)) {}

int terminal_columns() {
    winsize ws{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    return 80;
}

std::string progress_line(const PassRecord& p, std::uint64_t target, double remaining, double msamples,
                          std::size_t columns, bool pass_first) {
    // Done: the larger of the samples' and the time's share (--time may end the render first).
    double done = target > 0 ? double(p.spp) / double(target) : 0.0;
    if (std::isfinite(remaining) && p.render_s + remaining > 0.0)
        done = std::max(done, p.render_s / (p.render_s + remaining));
    done = std::clamp(done, 0.0, 1.0);
    // The fields by priority: each is kept only while the line fits (no wrapping at 80 columns).
    std::string err;
    if (p.reference) err = fmt::format("rmse {:.3e}", p.reference->rmse);
    else if (std::isfinite(p.estimate.rmse)) err = fmt::format("rmse~{:.3e} (est.)", p.estimate.rmse);
    const std::string fields[] = {fmt::format("{:3.0f}%", 100.0 * done),
                                  target > 0 ? fmt::format("{}/{} spp", p.spp, target) : fmt::format("{} spp", p.spp),
                                  fmt::format("{} left", fmt_seconds(remaining)),
                                  err,
                                  fmt::format("{} elapsed", fmt_seconds(p.wall_s)),
                                  fmt::format("{:.3f} Msamples/s", msamples),
                                  fmt::format("pass {}", p.pass)};
    // A log (not a terminal) starts each line with "pass N", which scripts wait for.
    std::string line = pass_first ? fmt::format("pass {}", p.pass) : std::string();
    for (const std::string& f : fields) {
        if (pass_first && &f == &fields[std::size(fields) - 1]) continue;
        if (f.empty()) continue;
        const std::size_t extra = (line.empty() ? 0 : 2) + f.size();
        if (line.size() + extra > columns) continue;
        if (!line.empty()) line += "  ";
        line += f;
    }
    return line;
}

void Progress::update(const PassRecord& p, std::uint64_t target, double remaining, double msamples, bool last) {
    if (quiet_) return;
    if (tty_) {
        // One column short of the width: a full line would wrap on some terminals.
        const std::size_t columns = std::size_t(std::max(terminal_columns() - 1, 20));
        const std::string line = progress_line(p, target, remaining, msamples, columns);
        say(stdout, "\r{:<{}}{}", line, columns, last ? "\n" : "");
    } else if (last || p.wall_s - last_print_ >= 2.0 || p.pass == 1) {
        say(stdout, "{}\n", progress_line(p, target, remaining, msamples, 200, true));
        last_print_ = p.wall_s;
    }
}

}  // namespace facet
