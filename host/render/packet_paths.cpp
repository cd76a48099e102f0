#include "host/render/packet_paths.hpp"

#include <cstdlib>
#include <cstring>

#include "kernels/shared/render_layout.h"

namespace facet {

bool packet_paths_for(const DeviceDesc& device, unsigned native_float_vector_width, FeatureMask features,
                      std::uint32_t sampler, bool generic) {
    const char* env = std::getenv("FACET_PACKET_PATHS");
    if (env && std::strcmp(env, "0") == 0) return false;
    const bool covered = !generic && features == area_lights_feature() && sampler == FC_SAMPLER_SOBOL;
    if (env && std::strcmp(env, "1") == 0) return covered;
    return covered && (device.type & CL_DEVICE_TYPE_CPU) != 0 && native_float_vector_width >= 8;
}

}  // namespace facet
