// Named channels of an image file, such as the AOV layers of facet's EXR ("albedo.R",
// "normal.X", "depth.Z": host/cli/render_scene.cpp writes them).
#pragma once

#include <string>
#include <vector>

namespace facet {

// Whether the file has every channel of `names`.
bool has_channels(const std::string& path, const std::vector<std::string>& names);

// The channels `names` of the image at `path` (read_image has checked the file), one
// float each a pixel in the order given, top row first. Throws facet::Error naming the
// file and the first channel it lacks.
std::vector<float> read_channels(const std::string& path, const std::vector<std::string>& names);

}  // namespace facet
