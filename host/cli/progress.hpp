// The render's progress display: a live line on a terminal; otherwise plain lines, at
// most one every two seconds, plus the first and the last. Printed through
// cli/console.hpp, so a closed stdout only silences it.
#pragma once

#include <cstdint>
#include <string>

#include "host/report/report.hpp"

namespace facet {

// "12.3s", "4m05s", "2h10m"; "?" when not finite.
std::string fmt_seconds(double s);

class Progress {
public:
    explicit Progress(bool quiet);
    void update(const PassRecord& p, std::uint64_t target, double remaining, double msamples, bool last);

private:
    bool quiet_, tty_;
    double last_print_ = -1e9;
};

}  // namespace facet
