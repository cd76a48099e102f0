// What each kernel of a built program needs per work-item on its device (issue 29: the
// GPU form's register and private-memory use is reported, not guessed).
//
// Every driver answers clGetKernelWorkGroupInfo: private and local memory, the largest
// work-group and its preferred multiple. Register counts have no standard query; NVIDIA's
// driver prints them when a program is built with -cl-nv-verbose, in ptxas's own words
// ("Used 96 registers", "... bytes stack frame, ... bytes spill stores, ... bytes spill
// loads", per entry function), which parse_ptxas_log reads.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "host/cl/runtime.hpp"

namespace facet {

// ptxas's figures for one entry function; -1 where the log does not say.
struct PtxasFigures {
    int registers = -1;
    int stack_bytes = -1;
    int spill_store_bytes = -1;
    int spill_load_bytes = -1;
};

struct KernelResources {
    std::string kernel;
    std::uint64_t private_bytes = 0;  // CL_KERNEL_PRIVATE_MEM_SIZE, per work-item
    std::uint64_t local_bytes = 0;    // CL_KERNEL_LOCAL_MEM_SIZE, per work-group
    std::size_t max_work_group = 0;   // CL_KERNEL_WORK_GROUP_SIZE
    std::size_t preferred_multiple = 0;
    PtxasFigures ptxas;  // NVIDIA only, from a -cl-nv-verbose build log
};

// The entry functions' figures in a ptxas log, by kernel name.
std::map<std::string, PtxasFigures> parse_ptxas_log(const std::string& log);

// The build option that makes the device's driver report registers ("-cl-nv-verbose" on
// NVIDIA's platform), or "" where no driver option is known.
std::string verbose_build_option(const DeviceDesc& dev);

// Every kernel of `program`, sorted by name, with `build_log`'s ptxas figures where it has them.
std::vector<KernelResources> kernel_resources(const ClContext& ctx, const cl::Program& program,
                                              const std::string& build_log = "");

// Builds `entry` with `prelude` from source, never from facet's program cache (whose
// entries carry no build log) nor the driver's (a kernel with a nonce is added, and left
// out of the report), with verbose_build_option, and reports its kernels.
std::vector<KernelResources> build_and_report_kernels(const ClContext& ctx, const std::string& entry,
                                                      const std::vector<std::string>& prelude = {});

}  // namespace facet
