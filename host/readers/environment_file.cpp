#include "host/readers/environment_file.hpp"

#include <new>
#include <utility>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"

namespace facet {

EnvironmentMap load_environment_map(const std::string& path, const glm::vec3& scale, const glm::mat3& world_to_map,
                                    std::vector<std::string>& warnings) {
    ImageRGB img = read_image(path);  // throws facet::Error naming the file
    if (!img.note.empty()) warnings.push_back(img.note);
    try {
        return environment_from_pixels(img.width, img.height, std::move(img.rgb), scale, world_to_map, path, warnings);
    } catch (const std::bad_alloc&) {
        throw Error(fmt::format("environment map '{}': not enough memory for its {}x{} texels and sampling tables",
                                path, img.width, img.height));
    }
}

}  // namespace facet
