// The OpenCL runtime layer: device discovery and selection, one context and queue,
// program builds from the assembled kernel sources, and OpenCL errors reported by
// name together with the call that failed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "host/cl/kernel_source.hpp"

namespace facet {

struct DeviceDesc {
    int index = 0;  // position in list_devices(), the number --device takes
    std::string platform;
    std::string name;
    std::string vendor;
    std::string version;    // CL_DEVICE_VERSION
    std::string c_version;  // CL_DEVICE_OPENCL_C_VERSION
    std::string driver;     // CL_DRIVER_VERSION
    cl_device_type type = 0;
    std::uint64_t global_mem = 0;
    std::uint64_t max_alloc = 0;
    std::uint32_t compute_units = 0;
    std::string type_name() const;  // "GPU", "CPU", "accelerator", ...
};

// Every device of every platform, in a stable order. Throws facet::Error when no
// OpenCL platform is installed.
std::vector<DeviceDesc> list_devices();

// The symbolic name of an OpenCL error code ("CL_OUT_OF_RESOURCES"), or "CL_ERROR_<n>".
const char* cl_error_name(cl_int code);

// Runs `f`, turning a cl::Error into facet::Error("OpenCL error CL_X (n) in clCall while
// <what>"). Use around host code that calls the C++ bindings.
template <typename F>
auto cl_call(const char* what, F&& f) -> decltype(f());

class ClContext {
public:
    // `selector`: empty for the default (the first GPU, else the first CPU, else the
    // first device), a number (index in list_devices()), or a case-insensitive
    // substring of "platform device" names. Throws facet::Error listing the devices
    // when nothing matches.
    static ClContext create(const std::string& selector = "");

    // One context per device that `selector` names: "all" (every device), "gpu", "cpu"
    // or "accelerator" (every device of that type), or a comma-separated list of the
    // selectors create() takes ("0,2", "0,0" for two contexts on one device). Throws
    // facet::Error listing the devices when a part matches none.
    static std::vector<ClContext> create_many(const std::string& selector);

    const cl::Context& context() const { return context_; }
    const cl::Device& device() const { return device_; }
    cl::CommandQueue& queue() { return queue_; }
    const DeviceDesc& desc() const { return desc_; }

private:
    // A context and an in-order queue on one device.
    static ClContext open(const cl::Device& device, const DeviceDesc& desc);

    cl::Context context_;
    cl::Device device_;
    cl::CommandQueue queue_;
    DeviceDesc desc_;
};

struct ProgramBuild {
    cl::Program program;
    AssembledSource source;
    std::string options;
    double seconds = 0.0;     // wall time of the build (from source or from the cache)
    bool from_cache = false;  // loaded from facet's program-binary cache
    std::string cache_file;   // the cache entry used or written ("" when not caching)
};

// The size of the program's device binary, where the driver reports one. Not part of
// build_program, and kept out of timed spans: PoCL answers it by generating machine code
// for every kernel with a generic work-group function, ~1 s for the path tracer, code
// that the first launch then generates again, specialised to its launch geometry.
std::size_t program_binary_bytes(const cl::Program& program);

// The options every facet program is built with (no fast or finite math).
std::string default_build_options();

// The words of the environment variable FACET_CL_VENDOR_OPTIONS, checked: NVIDIA's
// code-generation options alone (each word -cl-nv-*: -cl-nv-maxrregcount=N caps a
// work-item's registers, -cl-nv-opt-level=N), which leave every float result as it is,
// for measuring occupancy against registers (docs/performance.md). Any other word throws
// facet::Error naming it. Empty when unset.
std::string vendor_build_options();

// default_build_options, the device's workarounds, vendor_build_options and
// `extra_options`: what build_program passes to the driver.
std::string build_options_for(const DeviceDesc& dev, const std::string& extra_options = "");

// Assembles `entry` after `prelude` and builds it for the context's device. On failure
// throws facet::Error with the device, the options, the full build log and the path
// where the assembled source was kept.
//
// Program-binary cache: PoCL keeps its own cache, so facet's is used for every other
// driver (or always with FACET_PROGRAM_CACHE=1; never with FACET_PROGRAM_CACHE=0). An
// entry is keyed on the assembled source, the options, the platform, the device, its
// OpenCL version and the driver version, lives in $FACET_CACHE_DIR (default
// $XDG_CACHE_HOME/facet/kernels, else ~/.cache/facet/kernels), is written atomically,
// and a binary the driver refuses falls back to a source build that replaces it.
ProgramBuild build_program(const ClContext& ctx, const std::string& entry, const std::vector<std::string>& prelude = {},
                           const std::string& extra_options = "");

// ---- implementation of the template above ----
[[noreturn]] void throw_cl_error(const char* what, const cl::Error& e);

template <typename F>
auto cl_call(const char* what, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const cl::Error& e) {
        throw_cl_error(what, e);
    }
}

}  // namespace facet
