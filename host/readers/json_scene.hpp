// JSON scene files (schema in docs/scene-format.md).
#pragma once

#include <string>

#include "host/scene/scene.hpp"

namespace facet {

// Fills `scene` from the JSON scene at `path` (geometry, materials, camera, render
// settings; lights are left to build_lights()). Returns whether the file set a camera.
bool load_json_scene(const std::string& path, Scene& scene);

}  // namespace facet
