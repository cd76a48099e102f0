#include "host/cl/kernel_resources.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "host/cl/kernel_source.hpp"
#include "host/error.hpp"

namespace facet {

std::map<std::string, PtxasFigures> parse_ptxas_log(const std::string& log) {
    static const std::regex entry(R"(Compiling entry function '([^']+)')");
    static const std::regex properties(R"(Function properties for ([A-Za-z_][A-Za-z0-9_]*))");
    static const std::regex frame(R"((\d+) bytes stack frame, (\d+) bytes spill stores, (\d+) bytes spill loads)");
    static const std::regex used(R"(Used (\d+) registers)");
    std::map<std::string, PtxasFigures> out;
    std::string current;
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        // Each figure belongs to the function named last.
        if (std::regex_search(line, m, entry) || std::regex_search(line, m, properties)) {
            current = m[1].str();
            out[current];
        } else if (current.empty()) {
            continue;
        } else if (std::regex_search(line, m, frame)) {
            out[current].stack_bytes = std::stoi(m[1].str());
            out[current].spill_store_bytes = std::stoi(m[2].str());
            out[current].spill_load_bytes = std::stoi(m[3].str());
        } else if (std::regex_search(line, m, used)) {
            out[current].registers = std::stoi(m[1].str());
        }
    }
    return out;
}

std::string verbose_build_option(const DeviceDesc& dev) {
    return dev.platform.find("NVIDIA") != std::string::npos ? "-cl-nv-verbose" : "";
}

std::vector<KernelResources> kernel_resources(const ClContext& ctx, const cl::Program& program,
                                              const std::string& build_log) {
    const std::map<std::string, PtxasFigures> ptxas = parse_ptxas_log(build_log);
    std::vector<KernelResources> out;
    cl_call("querying the kernels' resources", [&] {
        std::vector<cl::Kernel> kernels;
        cl::Program(program).createKernels(&kernels);
        for (const cl::Kernel& k : kernels) {
            KernelResources r;
            r.kernel = k.getInfo<CL_KERNEL_FUNCTION_NAME>();
            // Some drivers pad the name with a terminating zero.
            r.kernel.erase(std::find(r.kernel.begin(), r.kernel.end(), '\0'), r.kernel.end());
            r.private_bytes = k.getWorkGroupInfo<CL_KERNEL_PRIVATE_MEM_SIZE>(ctx.device());
            r.local_bytes = k.getWorkGroupInfo<CL_KERNEL_LOCAL_MEM_SIZE>(ctx.device());
            r.max_work_group = k.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(ctx.device());
            r.preferred_multiple = k.getWorkGroupInfo<CL_KERNEL_PREFERRED_WORK_GROUP_SIZE_MULTIPLE>(ctx.device());
            if (auto it = ptxas.find(r.kernel); it != ptxas.end()) r.ptxas = it->second;
            out.push_back(r);
        }
    });
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.kernel < b.kernel; });
    return out;
}

namespace {

constexpr const char* kNoncePrefix = "fc_resources_nonce_";

}  // namespace

std::vector<KernelResources> build_and_report_kernels(const ClContext& ctx, const std::string& entry,
                                                      const std::vector<std::string>& prelude) {
    // A kernel of its own in every build: NVIDIA's driver answers a program whose code it
    // has compiled before (the AOV program of two scenes that differ only in their lights)
    // from its cache, and then prints no ptxas figures. Left out of the report.
    static std::atomic<std::uint64_t> builds{0};
    const std::uint64_t nonce =
        std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()) * 1000003u + builds++;
    std::vector<std::string> lines = prelude;
    lines.push_back(fmt::format("__kernel void {}{:x}(__global uint* o) {{ o[0] = {}u; }}", kNoncePrefix,
                                nonce & 0xffffffffffffull, std::uint32_t(nonce % 4294967291u)));
    const AssembledSource source = assemble_program(entry, lines);
    const std::string options = build_options_for(ctx.desc(), verbose_build_option(ctx.desc()));
    cl::Program program(ctx.context(), source.text);
    cl_int status = CL_SUCCESS;
    try {
        status = program.build({ctx.device()}, options.c_str());
    } catch (const cl::Error& e) {
        status = e.err();
    }
    std::string log;
    try {
        log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(ctx.device());
    } catch (const cl::Error&) {
        log.clear();
    }
    if (status != CL_SUCCESS)
        throw Error(fmt::format("kernel build failed ({}) for {} with options {}\n--- build log ---\n{}",
                                cl_error_name(status), entry, options, log));
    std::vector<KernelResources> out = kernel_resources(ctx, program, log);
    std::erase_if(out, [](const KernelResources& k) { return k.kernel.rfind(kNoncePrefix, 0) == 0; });
    return out;
}

}  // namespace facet
