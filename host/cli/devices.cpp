// `facet devices`: every OpenCL platform and device, with the index --device takes.
#include <fmt/format.h>

#include "host/cl/runtime.hpp"
#include "host/cli/commands.hpp"

namespace facet {

int run_devices() {
    std::vector<DeviceDesc> devices = list_devices();
    std::string last_platform;
    for (const DeviceDesc& d : devices) {
        if (d.platform != last_platform) {
            fmt::print("{}\n", d.platform);
            last_platform = d.platform;
        }
        fmt::print("  [{}] {} ({})\n", d.index, d.name, d.type_name());
        fmt::print("      {}, {}, driver {}\n", d.version, d.c_version, d.driver);
        fmt::print("      {} compute units, {:.0f} MiB global memory, {:.0f} MiB max allocation\n", d.compute_units,
                   double(d.global_mem) / (1 << 20), double(d.max_alloc) / (1 << 20));
    }
    return kExitOk;
}

}  // namespace facet
