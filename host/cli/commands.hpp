// The commands of the facet CLI.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace facet {

struct RenderOptions {
    std::string scene;
    std::optional<int> spp, width, height, max_depth;
    std::optional<std::uint32_t> seed;
    std::optional<double> time_limit;
    std::string device;
    std::string out;
    float exposure = 0.0f;
    bool quiet = false;
};

struct InfoOptions {
    std::string scene;
};

// Exit statuses of `facet render` (documented in the README).
constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;           // bad command line (the message names the option)
constexpr int kExitInterrupted = 130;   // stopped by SIGINT/SIGTERM; the image so far was written

int run_devices();
int run_info(const InfoOptions& opt);
int run_render(const RenderOptions& opt);

}  // namespace facet
