// Loading a scene from a file: a JSON scene (host/readers/json_scene.cpp) or a bare OBJ
// (host/readers/obj_reader.cpp). Every function throws facet::Error with a message that
// names the file (and the line where there is one) and says what is wrong.
#pragma once

#include <string>

#include "host/scene/scene.hpp"

namespace facet {

// Loads a JSON scene (*.json) or a mesh (*.obj, framed by a default camera and lit
// by a default light). Calls build_lights() before returning.
Scene load_scene(const std::string& path);

}  // namespace facet
