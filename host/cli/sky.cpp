// `facet sky OUT.exr`: the generated sun-and-sky environment map (docs/environment.md).
#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/scene/sky.hpp"

namespace facet {

int run_sky(const SkyOptions& opt) {
    SunSkyParams params;
    params.elevation_degrees = opt.elevation;
    params.azimuth_degrees = opt.azimuth;
    params.turbidity = opt.turbidity;
    write_sun_sky_exr(opt.out, opt.width, params);
    fmt::print("wrote    {} ({}x{})\n", opt.out, opt.width, opt.width / 2);
    return kExitOk;
}

}  // namespace facet
