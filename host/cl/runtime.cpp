// Device discovery, selection and program builds.
#include "host/cl/runtime.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include <fmt/format.h>
#include <unistd.h>

#include "host/error.hpp"
#include "host/util/safe_write.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

// FACET_DEVICE_MEMORY_MIB: a cap on the memory facet assumes each device has (its global
// memory and its largest allocation), to share a device or to test the out-of-memory paths
// on any machine; unset or empty: the driver's figures.
std::uint64_t device_memory_cap() {
    const char* env = std::getenv("FACET_DEVICE_MEMORY_MIB");
    if (!env || !*env) return UINT64_MAX;
    char* end = nullptr;
    const unsigned long long mib = std::strtoull(env, &end, 10);
    if (*end != '\0' || mib == 0 || mib > (1ull << 40) || env[0] == '-')
        throw Error(fmt::format("FACET_DEVICE_MEMORY_MIB={}: not a whole number of MiB in [1, 2^40]", env));
    return std::uint64_t(mib) << 20;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back())))) s.pop_back();
    return s;
}

struct Found {
    DeviceDesc desc;
    cl::Device device;
};

std::vector<Found> discover() {
    std::vector<cl::Platform> platforms;
    cl_int status = cl::Platform::get(&platforms);  // returns an error code for "no ICD"
    if (status != CL_SUCCESS || platforms.empty())
        throw Error(
            fmt::format("No OpenCL platform found ({}): install an OpenCL driver, e.g. `apt-get install "
                        "pocl-opencl-icd` for the CPU",
                        cl_error_name(status)));
    std::vector<Found> found;
    for (const cl::Platform& platform : platforms) {
        std::vector<cl::Device> devices;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error&) {
            continue;  // a platform without devices (CL_DEVICE_NOT_FOUND)
        }
        for (const cl::Device& d : devices) {
            Found f;
            f.device = d;
            DeviceDesc& desc = f.desc;
            desc.index = static_cast<int>(found.size());
            desc.platform = trimmed(platform.getInfo<CL_PLATFORM_NAME>());
            desc.name = trimmed(d.getInfo<CL_DEVICE_NAME>());
            desc.vendor = trimmed(d.getInfo<CL_DEVICE_VENDOR>());
            desc.version = trimmed(d.getInfo<CL_DEVICE_VERSION>());
            desc.c_version = trimmed(d.getInfo<CL_DEVICE_OPENCL_C_VERSION>());
            desc.driver = trimmed(d.getInfo<CL_DRIVER_VERSION>());
            desc.type = d.getInfo<CL_DEVICE_TYPE>();
            desc.global_mem = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
            desc.max_alloc = d.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
            desc.global_mem = std::min<std::uint64_t>(desc.global_mem, device_memory_cap());
            desc.max_alloc = std::min<std::uint64_t>(desc.max_alloc, device_memory_cap());
            desc.compute_units = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
            found.push_back(std::move(f));
        }
    }
    if (found.empty()) throw Error("OpenCL platforms are installed but none has a device");
    return found;
}

std::string device_list(const std::vector<Found>& found) {
    std::string s;
    for (const Found& f : found)
        s += fmt::format("\n  [{}] {} / {} ({})", f.desc.index, f.desc.platform, f.desc.name, f.desc.type_name());
    return s;
}

const Found& select(const std::vector<Found>& found, const std::string& selector) {
    if (selector.empty()) {
        for (cl_device_type want : {cl_device_type(CL_DEVICE_TYPE_GPU), cl_device_type(CL_DEVICE_TYPE_CPU)})
            for (const Found& f : found)
                if (f.desc.type & want) return f;
        return found.front();
    }
    bool numeric = std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
    if (numeric) {
        std::size_t index = std::stoul(selector.substr(0, 9));
        if (index < found.size()) return found[index];
        throw Error(
            fmt::format("--device {}: no device with that index; devices are:{}", selector, device_list(found)));
    }
    std::string needle = lower(selector);
    for (const Found& f : found)
        if (lower(f.desc.platform + " " + f.desc.name).find(needle) != std::string::npos) return f;
    throw Error(fmt::format("--device '{}': no device name contains it; devices are:{}", selector, device_list(found)));
}

// Keeps a failed program's source where the user can read it; returns the path.
std::string keep_source(const std::string& text) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path dir = fs::temp_directory_path(ec);
    if (ec) dir = ".";
    fs::path path = dir / fmt::format("facet-failed-{:016x}.cl", std::hash<std::string>{}(text));
    std::ofstream(path) << text;
    return path.string();
}

// FNV-1a, 64 bits: the cache key of a program.
std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

bool use_program_cache(const DeviceDesc& dev) {
    const char* env = std::getenv("FACET_PROGRAM_CACHE");
    if (env && std::string(env) == "0") return false;
    if (env && std::string(env) == "1") return true;
    return dev.platform.find("Portable Computing Language") == std::string::npos;
}

std::filesystem::path program_cache_dir() {
    namespace fs = std::filesystem;
    if (const char* d = std::getenv("FACET_CACHE_DIR"); d && *d) return fs::path(d);
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "facet" / "kernels";
    if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "facet" / "kernels";
    return fs::temp_directory_path() / "facet-kernels";
}

std::string cache_file_for(const DeviceDesc& dev, const std::string& source, const std::string& options) {
    std::uint64_t key = fnv1a(source);
    for (const std::string* part : {&options, &dev.platform, &dev.name, &dev.version, &dev.driver})
        key = fnv1a(*part, fnv1a(std::string(1, '\0'), key));
    return (program_cache_dir() / fmt::format("{:016x}.bin", key)).string();
}

std::vector<unsigned char> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes_atomically(const std::string& path, const std::vector<unsigned char>& bytes) {
    // A temporary private to this process, so two renders filling the same entry at once each
    // write their own file and the last rename wins with a whole binary.
    try {
        write_bytes_safely(path, "program cache entry",
                           std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } catch (const Error&) {
        // a cache that cannot be written is no error
    }
}

// Builds from a cached binary; false when there is none or the driver refuses it.
bool build_from_cache(const ClContext& ctx, ProgramBuild& build) {
    std::vector<unsigned char> bytes = read_bytes(build.cache_file);
    if (bytes.empty()) return false;
    try {
        cl::Program::Binaries binaries{bytes};
        std::vector<cl_int> status;
        build.program = cl::Program(ctx.context(), {ctx.device()}, binaries, &status);
        if (status.empty() || status[0] != CL_SUCCESS) return false;
        return build.program.build({ctx.device()}, build.options.c_str()) == CL_SUCCESS;
    } catch (const cl::Error&) {
        return false;
    }
}

}  // namespace

std::string DeviceDesc::type_name() const {
    if (type & CL_DEVICE_TYPE_GPU) return "GPU";
    if (type & CL_DEVICE_TYPE_CPU) return "CPU";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

std::vector<DeviceDesc> list_devices() {
    return cl_call("listing OpenCL devices", [] {
        std::vector<DeviceDesc> out;
        for (Found& f : discover()) out.push_back(f.desc);
        return out;
    });
}

ClContext ClContext::open(const cl::Device& device, const DeviceDesc& desc) {
    ClContext ctx;
    ctx.device_ = device;
    ctx.desc_ = desc;
    ctx.context_ = cl::Context(device);
    ctx.queue_ = cl::CommandQueue(ctx.context_, device);
    return ctx;
}

ClContext ClContext::create(const std::string& selector) {
    return cl_call("creating the OpenCL context", [&] {
        std::vector<Found> found = discover();
        const Found& f = select(found, selector);
        return open(f.device, f.desc);
    });
}

std::vector<ClContext> ClContext::create_many(const std::string& selector) {
    return cl_call("creating the OpenCL contexts", [&] {
        std::vector<Found> found = discover();
        auto context_of = [](const Found& f) { return open(f.device, f.desc); };
        std::vector<ClContext> out;
        const std::string which = lower(selector);
        const std::pair<const char*, cl_device_type> types[] = {{"all", CL_DEVICE_TYPE_ALL},
                                                                {"gpu", CL_DEVICE_TYPE_GPU},
                                                                {"cpu", CL_DEVICE_TYPE_CPU},
                                                                {"accelerator", CL_DEVICE_TYPE_ACCELERATOR}};
        for (const auto& [name, type] : types) {
            if (which != name) continue;
            for (const Found& f : found)
                if (f.desc.type & type) out.push_back(context_of(f));
            if (out.empty())
                throw Error(fmt::format("--device {}: no such device; devices are:{}", selector, device_list(found)));
            return out;
        }
        std::size_t begin = 0;
        do {
            const std::size_t comma = selector.find(',', begin);
            const std::string part = selector.substr(begin, comma == std::string::npos ? comma : comma - begin);
            if (part.empty() && selector.find(',') != std::string::npos)
                throw Error(fmt::format("--device {}: an empty entry in the list", selector));
            out.push_back(context_of(select(found, part)));
            begin = comma == std::string::npos ? comma : comma + 1;
        } while (begin != std::string::npos);
        return out;
    });
}

std::size_t program_binary_bytes(const cl::Program& program) {
    try {
        std::vector<std::size_t> sizes = program.getInfo<CL_PROGRAM_BINARY_SIZES>();
        return sizes.empty() ? 0 : sizes[0];
    } catch (const cl::Error&) {
        return 0;
    }
}

std::string default_build_options() {
    // Strict IEEE behaviour on purpose: NaN/Inf checks must survive (no fast/finite math).
    return "-cl-std=CL1.2";
}

std::string vendor_build_options() {
    const char* env = std::getenv("FACET_CL_VENDOR_OPTIONS");
    if (!env) return "";
    std::istringstream words(env);
    std::string word, out;
    while (words >> word) {
        if (word.rfind("-cl-nv-", 0) != 0)
            throw Error(
                fmt::format("FACET_CL_VENDOR_OPTIONS: '{}' is not one of NVIDIA's -cl-nv-* code-generation "
                            "options, the only ones taken (others could change float results)",
                            word));
        out += (out.empty() ? "" : " ") + word;
    }
    return out;
}

std::string build_options_for(const DeviceDesc& dev, const std::string& extra_options) {
    std::string options = default_build_options();
    if (const std::string vendor = vendor_build_options(); !vendor.empty()) options += " " + vendor;
    // Oclgrind 21.10 cannot run LLVM's bit-reversal intrinsic, which clang makes of the
    // sampler's vector bit reversal (kernels/util/sampler.cl): it gets the table version.
    if (dev.platform.find("Oclgrind") != std::string::npos) options += " -DFC_NO_BITREVERSE_INTRINSIC";
    if (!extra_options.empty()) options += " " + extra_options;
    return options;
}

ProgramBuild build_program(const ClContext& ctx, const std::string& entry, const std::vector<std::string>& prelude,
                           const std::string& extra_options) {
    ProgramBuild build;
    build.source = assemble_program(entry, prelude);
    build.options = build_options_for(ctx.desc(), extra_options);
    auto start = std::chrono::steady_clock::now();
    const bool caching = use_program_cache(ctx.desc());
    if (caching) {
        build.cache_file = cache_file_for(ctx.desc(), build.source.text, build.options);
        build.from_cache = build_from_cache(ctx, build);
    }
    cl_int status = CL_SUCCESS;
    if (!build.from_cache) {
        try {
            build.program = cl::Program(ctx.context(), build.source.text);
            status = build.program.build({ctx.device()}, build.options.c_str());
        } catch (const cl::BuildError& e) {
            status = e.err();
        } catch (const cl::Error& e) {
            status = e.err();
        }
    }
    build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status == CL_SUCCESS) {
        if (caching && !build.from_cache) {
            try {
                std::vector<std::vector<unsigned char>> binaries = build.program.getInfo<CL_PROGRAM_BINARIES>();
                if (!binaries.empty() && !binaries[0].empty()) write_bytes_atomically(build.cache_file, binaries[0]);
            } catch (const cl::Error&) {
                // the driver gives no binary: nothing to cache
            }
        }
    }
    if (status != CL_SUCCESS) {
        std::string log;
        try {
            log = build.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(ctx.device());
        } catch (const cl::Error&) {
            log = "(no build log available)";
        }
        std::string kept = keep_source(build.source.text);
        throw Error(
            fmt::format("kernel build failed ({}) for {}\n  device: {} / {} ({})\n  options: {}\n  source: {} "
                        "(assembled from {}, kept at {})\n--- build log ---\n{}",
                        cl_error_name(status), entry, ctx.desc().platform, ctx.desc().name, ctx.desc().driver,
                        build.options, entry, build.source.origin, kept, trimmed(log)));
    }
    return build;
}

}  // namespace facet
