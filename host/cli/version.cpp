// `facet --version`: the version, the commit and build type it was configured from
// (FACET_VERSION, FACET_GIT_COMMIT and FACET_BUILD_TYPE, defined for this file alone by
// CMakeLists.txt, so no other object changes with the commit), and the OpenCL devices found.
#include <fmt/format.h>

#include "host/cl/runtime.hpp"
#include "host/cli/commands.hpp"
#include "host/error.hpp"

#ifndef FACET_VERSION
#define FACET_VERSION "unknown"
#endif
#ifndef FACET_GIT_COMMIT
#define FACET_GIT_COMMIT "unknown"
#endif
#ifndef FACET_BUILD_TYPE
#define FACET_BUILD_TYPE "unknown"
#endif

namespace facet {

std::string version_report() {
    std::string out =
        fmt::format("facet {}\ncommit     {}\nbuild      {}\n", FACET_VERSION, FACET_GIT_COMMIT, FACET_BUILD_TYPE);
    std::vector<DeviceDesc> devices;
    try {
        devices = list_devices();
    } catch (const Error&) {  // no platform (no ICD installed): said, not an error
    }
    if (devices.empty())
        return out + "platforms  none found: install an OpenCL driver, e.g. `apt-get install pocl-opencl-icd`\n";
    std::string last_platform;
    for (const DeviceDesc& d : devices) {
        if (d.platform != last_platform) {
            out += fmt::format("platform   {}\n", d.platform);
            last_platform = d.platform;
        }
        out += fmt::format("  [{}] {} ({}, {})\n", d.index, d.name, d.type_name(), d.version);
    }
    return out;
}

}  // namespace facet
