#include "host/cli/progress.hpp"

#include <unistd.h>

#include <cmath>

#include <fmt/format.h>

#include "host/cli/console.hpp"

namespace facet {

std::string fmt_seconds(double s) {
    if (!std::isfinite(s)) return "?";
    if (s < 60) return fmt::format("{:.1f}s", s);
    if (s < 3600) return fmt::format("{}m{:02d}s", int(s) / 60, int(s) % 60);
    return fmt::format("{}h{:02d}m", int(s) / 3600, (int(s) % 3600) / 60);
}

Progress::Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDOUT_FILENO)) {}

void Progress::update(const PassRecord& p, std::uint64_t target, double remaining, double msamples, bool last) {
    if (quiet_) return;
    std::string err;
    if (p.reference) err = fmt::format("  rmse {:.3e}", p.reference->rmse);
    else if (std::isfinite(p.estimate.rmse)) err = fmt::format("  rmse~{:.3e} (est.)", p.estimate.rmse);
    std::string line = fmt::format("pass {:3d}  {:>7}/{} spp  {:>7} elapsed  {:>7} left  {:7.3f} Msamples/s{}", p.pass,
                                   p.spp, target, fmt_seconds(p.wall_s), fmt_seconds(remaining), msamples, err);
    if (tty_) {
        say(stdout, "\r{:<120}{}", line, last ? "\n" : "");
    } else if (last || p.wall_s - last_print_ >= 2.0 || p.pass == 1) {
        say(stdout, "{}\n", line);
        last_print_ = p.wall_s;
    }
}

}  // namespace facet
