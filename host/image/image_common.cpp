// What image_io.hpp declares whatever library reads and writes the files
// (image_io.cpp through OpenImageIO, image_io_lean.cpp without it).
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"

namespace facet {

ImageRGB read_reference(const std::string& path, int width, int height) {
    ImageRGB ref = read_image(path);
    if (ref.decoded_srgb)
        throw Error(
            fmt::format("reference {}: an integer (8-bit sRGB) image is tone-mapped and clipped at 1, not "
                        "the linear radiance a render is measured against: give the EXR (or HDR)",
                        path));
    if (ref.width != width || ref.height != height)
        throw Error(fmt::format("reference {}: the reference is {}x{} but the render is {}x{}", path, ref.width,
                                ref.height, width, height));
    for (std::size_t i = 0; i < ref.rgb.size(); ++i)
        if (!std::isfinite(ref.rgb[i]))
            throw Error(fmt::format("reference {}: channel {} of pixel ({}, {}) is not finite", path, i % 3,
                                    (i / 3) % std::size_t(width), (i / 3) / std::size_t(width)));
    return ref;
}

std::string replace_extension(const std::string& path, const std::string& ext) {
    return std::filesystem::path(path).replace_extension(ext).string();
}

}  // namespace facet
