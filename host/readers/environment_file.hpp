// Environment maps read from image files (EXR, Radiance .hdr, anything
// host/image/image_io.hpp reads through OpenImageIO).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "host/scene/environment_map.hpp"

namespace facet {

// Reads `path` and builds the map (environment_from_pixels: sanitised, with its
// sampling distribution). Throws facet::Error naming the file when it cannot be read.
EnvironmentMap load_environment_map(const std::string& path, const glm::vec3& scale, const glm::mat3& world_to_map,
                                    std::vector<std::string>& warnings);

}  // namespace facet
