// image_channels.hpp without OpenImageIO (the lean build, FACET_OIIO=OFF): its images are PFM,
// which has no named channels, so no file has the AOV layers `facet denoise` reads.
#ifdef FACET_LEAN_IMAGES

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_channels.hpp"

namespace facet {

namespace {

[[noreturn]] void no_channels(const std::string& path) {
    throw Error(
        fmt::format("{}: this facet is the lean build (without OpenImageIO), which reads no named channels "
                    "(AOV layers of an EXR): use the full build",
                    path));
}

}  // namespace

bool has_channels(const std::string& path, const std::vector<std::string>&) { no_channels(path); }

std::vector<float> read_channels(const std::string& path, const std::vector<std::string>&) { no_channels(path); }

}  // namespace facet

#endif
