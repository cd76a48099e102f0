#include "host/denoise/oidn.hpp"

#include <dlfcn.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The part of OIDN's C API (OpenImageDenoise/oidn.h, version 2) facet calls.
using Device = void*;
using Filter = void*;
constexpr int kDeviceDefault = 0;  // OIDN_DEVICE_TYPE_DEFAULT
constexpr int kFormatFloat3 = 3;   // OIDN_FORMAT_FLOAT3
constexpr int kErrorNone = 0;      // OIDN_ERROR_NONE

struct Api {
    Device (*new_device)(int);
    void (*commit_device)(Device);
    int (*get_device_error)(Device, const char**);
    void (*release_device)(Device);
    Filter (*new_filter)(Device, const char*);
    void (*set_shared_image)(Filter, const char*, void*, int, std::size_t, std::size_t, std::size_t, std::size_t,
                             std::size_t);
    void (*set_bool)(Filter, const char*, bool);
    void (*commit_filter)(Filter);
    void (*execute_filter)(Filter);
    void (*release_filter)(Filter);
};

template <typename F>
void bind(void* lib, const std::string& library, const char* name, F& f) {
    f = reinterpret_cast<F>(::dlsym(lib, name));
    if (!f) throw Error(fmt::format("{}: not Intel Open Image Denoise 2 (no {})", library, name));
}

// The library loaded once per process (OIDN keeps threads; it is never unloaded).
const Api& load(const std::string& library) {
    static std::string loaded;
    static Api api{};
    if (!loaded.empty()) {
        if (loaded != library) throw Error(fmt::format("{}: OIDN is already loaded from {}", library, loaded));
        return api;
    }
    void* lib = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib) throw Error(fmt::format("{}: cannot load Intel Open Image Denoise: {}", library, ::dlerror()));
    bind(lib, library, "oidnNewDevice", api.new_device);
    bind(lib, library, "oidnCommitDevice", api.commit_device);
    bind(lib, library, "oidnGetDeviceError", api.get_device_error);
    bind(lib, library, "oidnReleaseDevice", api.release_device);
    bind(lib, library, "oidnNewFilter", api.new_filter);
    bind(lib, library, "oidnSetSharedFilterImage", api.set_shared_image);
    bind(lib, library, "oidnSetFilterBool", api.set_bool);
    bind(lib, library, "oidnCommitFilter", api.commit_filter);
    bind(lib, library, "oidnExecuteFilter", api.execute_filter);
    bind(lib, library, "oidnReleaseFilter", api.release_filter);
    loaded = library;
    return api;
}

// Throws with OIDN's message when the device holds an error.
void check(const Api& api, Device device, const std::string& library, const char* what) {
    const char* message = nullptr;
    if (api.get_device_error(device, &message) != kErrorNone)
        throw Error(fmt::format("{}: OIDN failed while {}: {}", library, what, message ? message : "no message"));
}

// Folders a pip-installed package may be in.
std::vector<fs::path> python_site_folders() {
    std::vector<fs::path> roots;
    if (const char* venv = std::getenv("VIRTUAL_ENV")) roots.push_back(fs::path(venv) / "lib");
    if (const char* home = std::getenv("HOME")) roots.push_back(fs::path(home) / ".local/lib");
    roots.push_back("/usr/local/lib");
    roots.push_back("/usr/lib");
    std::vector<fs::path> out;
    for (const fs::path& root : roots) {
        std::error_code ec;
        for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.rfind("python3", 0) != 0) continue;
            out.push_back(it->path() / "site-packages");
            out.push_back(it->path() / "dist-packages");
        }
    }
    return out;
}

}  // namespace

std::string find_oidn(const std::string& given, std::string* looked) {
    if (!given.empty()) return given;
    if (const char* env = std::getenv("FACET_OIDN"); env && *env) return env;
    std::string places;
    for (const fs::path& site : python_site_folders()) {
        const fs::path lib = site / "pyoidn/oidn/lib/libOpenImageDenoise.so.2";
        std::error_code ec;
        if (fs::exists(lib, ec)) return lib.string();
        places += (places.empty() ? "" : ", ") + site.string();
    }
    if (void* lib = ::dlopen("libOpenImageDenoise.so.2", RTLD_LAZY | RTLD_LOCAL)) {
        ::dlclose(lib);
        return "libOpenImageDenoise.so.2";
    }
    if (looked) *looked = "$FACET_OIDN, pyoidn in " + places + ", the dynamic loader's path";
    return "";
}

DenoisedImage denoise_oidn(const std::string& library, std::uint32_t width, std::uint32_t height,
                           const FilmHalves& halves, const AovImages& features) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t pixels = std::size_t(width) * height;
    if (halves.samples[0] == 0 || halves.samples[1] == 0)
        throw Error("denoise: needs at least 2 samples per pixel (one in each half-image)");
    for (const std::vector<float>* v : {&halves.rgb[0], &halves.rgb[1], &features.albedo, &features.normal})
        if (v->size() != 3 * pixels) throw Error("denoise: an image's size differs from the render's");
    const Api& api = load(library);
    Device device = api.new_device(kDeviceDefault);
    if (!device) throw Error(fmt::format("{}: OIDN made no device", library));
    DenoisedImage out;
    try {
        api.commit_device(device);
        check(api, device, library, "opening its device");
        for (int k = 0; k < 2; ++k) {
            out.half[k].assign(3 * pixels, 0.0f);
            Filter filter = api.new_filter(device, "RT");
            check(api, device, library, "making the RT filter");
            auto image = [&](const char* name, const std::vector<float>& v) {
                api.set_shared_image(filter, name, const_cast<float*>(v.data()), kFormatFloat3, width, height, 0, 0, 0);
            };
            image("color", halves.rgb[k]);
            image("albedo", features.albedo);
            image("normal", features.normal);
            image("output", out.half[k]);
            api.set_bool(filter, "hdr", true);
            api.commit_filter(filter);
            api.execute_filter(filter);
            api.release_filter(filter);
            check(api, device, library, "denoising");
        }
    } catch (...) {
        api.release_device(device);
        throw;
    }
    api.release_device(device);
    out.rgb.resize(3 * pixels);
    for (std::size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] = 0.5f * (out.half[0][i] + out.half[1][i]);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace facet
