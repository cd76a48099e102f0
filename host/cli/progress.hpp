// The render's progress display: a live line on a terminal, as wide as the terminal;
// otherwise plain lines, at
// most one every two seconds, plus the first and the last. Printed through
// util/console.hpp, so a closed stdout only silences it.
#pragma once

#include <cstdint>
#include <string>

#include "host/report/report.hpp"

namespace facet {

// "12.3s", "4m05s", "2h10m"; "?" when not finite.
std::string fmt_seconds(double s);

// The terminal's width in columns (TIOCGWINSZ on stdout; 80 when it is not a terminal).
int terminal_columns();

// The progress line within `columns`: percentage done, spp, time left, the error, time
// elapsed, speed and pass number, in that order of importance, each kept if it still fits
// (`target` 0: no spp target, only --time; the percentage is then the time's);
// `pass_first` (a log, not a terminal): "pass N" leads the line, as scripts expect.
std::string progress_line(const PassRecord& p, std::uint64_t target, double remaining, double msamples,
                          std::size_t columns, bool pass_first = false);

class Progress {
public:
    explicit Progress(bool quiet);
    void update(const PassRecord& p, std::uint64_t target, double remaining, double msamples, bool last);

private:
    bool quiet_, tty_;
    double last_print_ = -1e9;
};

}  // namespace facet
