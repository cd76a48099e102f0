// cli/progress.hpp: the progress line fits the terminal (at 80 columns it used to wrap
// and fill the screen), starts with the percentage done and keeps the fields, in order of
// importance, that still fit.
#include <gtest/gtest.h>

#include "host/cli/progress.hpp"

namespace facet {
namespace {

PassRecord record() {
    PassRecord p;
    p.pass = 12;
    p.spp = 1536;
    p.wall_s = 75.0;
    p.render_s = 70.0;
    p.estimate = ErrorMetrics{1e-4, 1e-2, 1e-3};
    return p;
}

TEST(ProgressLine, FitsTheTerminalAndShowsThePercentage) {
    for (std::size_t columns : {40u, 60u, 79u, 120u, 200u}) {
        const std::string line = progress_line(record(), 4096, 120.0, 1.234, columns);
        EXPECT_LE(line.size(), columns) << line;
        EXPECT_EQ(line.rfind(" 38%", 0), 0u) << line;  // 1536 / 4096
    }
    const std::string wide = progress_line(record(), 4096, 120.0, 1.234, 200);
    for (const char* field :
         {"1536/4096 spp", "2m00s left", "rmse~1.000e-02", "1m15s elapsed", "Msamples/s", "pass 12"})
        EXPECT_NE(wide.find(field), std::string::npos) << field << " in " << wide;
    const std::string narrow = progress_line(record(), 4096, 120.0, 1.234, 40);
    EXPECT_NE(narrow.find("spp"), std::string::npos) << narrow;
    EXPECT_EQ(narrow.find("rmse"), std::string::npos) << narrow;
}

TEST(ProgressLine, LogLinesStartWithThePass) {
    // tests/faults/signals.sh waits for "^pass" in a render's log.
    const std::string line = progress_line(record(), 4096, 120.0, 1.234, 200, true);
    EXPECT_EQ(line.rfind("pass 12   38%  1536/4096 spp", 0), 0u) << line;
    EXPECT_EQ(line.find("pass", 1), std::string::npos) << line;
}

TEST(ProgressLine, TimeLimitSetsThePercentage) {
    // --time ends the render first: 70 s done, 30 s left is 70%.
    EXPECT_EQ(progress_line(record(), 1u << 24, 30.0, 1.0, 80).rfind(" 70%", 0), 0u);
}

TEST(ProgressLine, NoSppTargetShowsTheSamplesAndTheTimesShare) {
    // --time alone: no spp target, the percentage is the time's (70 s of 100 s).
    const std::string line = progress_line(record(), 0, 30.0, 1.0, 200);
    EXPECT_EQ(line.rfind(" 70%  1536 spp  30.0s left", 0), 0u) << line;
}

}  // namespace
}  // namespace facet
