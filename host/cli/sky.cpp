// `facet sky OUT.exr`: the generated sun-and-sky environment map (docs/environment.md).
// The map is light (the sun is thousands of times the sky), so OUT must be a format that
// holds linear floats (EXR, HDR, ...): a PNG would clip it to 8 bits of 0..1.
#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"
#include "host/scene/sky.hpp"

namespace facet {

int run_sky(const SkyOptions& opt) {
    check_output_path(opt.out, "OUT");
    std::string why;
    if (!can_write_float_image(opt.out, &why))
        throw Error(
            fmt::format("OUT {}: the sky is linear light (the sun thousands of times brighter than the sky), "
                        "which this format cannot hold: give an .exr or .hdr name",
                        opt.out));
    SunSkyParams params;
    params.elevation_degrees = opt.elevation;
    params.azimuth_degrees = opt.azimuth;
    params.turbidity = opt.turbidity;
    write_sun_sky_exr(opt.out, opt.width, params);
    fmt::print("wrote    {} ({}x{})\n", opt.out, opt.width, opt.width / 2);
    return kExitOk;
}

}  // namespace facet
