// Sections of facet_bench (bench/bench_main.cpp runs them in one process).
#pragma once

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <CL/opencl.hpp>
#include <nlohmann/json.hpp>

#include "host/cl/runtime.hpp"

namespace facet {

// A batch of rays as both facet's trace kernel and Embree take them.
struct RayBatch {
    std::vector<cl_float4> origins, dirs;  // dirs[i].w = tmax
};

// Wall time and the CPU time of the whole process (every thread, the OpenCL driver's
// included) over the same interval: under contention from other processes the wall
// time stretches while the CPU time stays near the work done, so rates per CPU-second
// compare fairly across runs of a shared machine.
struct Timing {
    double wall = 0.0;
    double cpu = 0.0;
};
double process_cpu_seconds();

// Everything the bench prints as its report, kept for --markdown.
std::string& bench_markdown();

// Prints to stdout and appends to bench_markdown().
template <typename... Args>
void bench_print(fmt::format_string<Args...> f, Args&&... args) {
    std::string s = fmt::format(f, std::forward<Args>(args)...);
    std::fputs(s.c_str(), stdout);
    std::fflush(stdout);
    bench_markdown() += s;
}

// A Markdown table built row by row.
class Markdown {
public:
    explicit Markdown(std::vector<std::string> header) : cols_(header.size()) { row(header); }
    void row(const std::vector<std::string>& cells) {
        text_ += "|";
        for (const auto& c : cells) text_ += " " + c + " |";
        text_ += "\n";
        if (++rows_ == 1) {
            text_ += "|";
            for (std::size_t i = 0; i < cols_; ++i) text_ += "---|";
            text_ += "\n";
        }
    }
    const std::string& str() const { return text_; }

private:
    std::size_t cols_;
    int rows_ = 0;
    std::string text_;
};

// BSDF eval+pdf and sample throughput of every named model; prints a table.
nlohmann::json bench_bsdfs(ClContext& ctx, bool quick);

// Equal-time error of BSDF sampling, environment sampling and MIS under stiff maps.
nlohmann::json bench_ibl(ClContext& ctx, const std::string& assets, bool quick);

// Denoising (issue 30): facet's denoiser and OIDN against a long reference, the half-buffer
// estimate, and denoise time against render time (bench/denoise_bench.cpp).
nlohmann::json bench_denoise(ClContext& ctx, bool quick);

// Load time, device memory and samples/s with and without textures of users' assets.
nlohmann::json bench_assets(ClContext& ctx, const std::string& assets, bool quick);
struct BvhOptions;
nlohmann::json bench_packet(ClContext& ctx, const BvhOptions& bvh_options, bool quick);

// Private and local memory, and on NVIDIA registers and spills, of every kernel of the
// render, AOV and denoise programs as the demo scenes build them.
struct BvhOptions;
nlohmann::json bench_kernel_resources(ClContext& ctx, const BvhOptions& bvh_options);

// Specialised against generic programs: build time cold and warm, binary size, speed.
nlohmann::json bench_specialisation(ClContext& ctx, const std::string& assets, bool quick);

// Instancing: one mesh used by 100 glTF nodes, instanced against copied (instancing_bench.cpp).
nlohmann::json bench_instancing(ClContext& ctx, const std::string& assets, bool quick);

}  // namespace facet
