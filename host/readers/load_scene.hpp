// Loading a scene from a file: a JSON scene (host/readers/json_scene.cpp), a bare OBJ
// (obj_reader.cpp), PLY (ply_reader.cpp) or model of another format read through Assimp
// (assimp_reader.cpp: STL, FBX, Collada, 3DS, ...), or a glTF 2.0 file (gltf_reader.cpp). Every function throws
// facet::Error with a message that names the file (and the line where there is one) and says what is wrong.
#pragma once

#include <string>

#include "host/scene/scene.hpp"

namespace facet {

// Loads a JSON scene (*.json), a mesh (*.obj, *.ply, *.ply.gz, assimp_formats(), framed by a default
// camera and lit by a default light) or a glTF 2.0 file (*.gltf, *.glb: its own camera
// and lights where it has them, else the defaults). Calls build_lights() before returning.
// `camera_name` (--camera NAME) picks a glTF file's camera by name; other scenes have no
// named cameras and refuse it. `strict_assets` (--strict) makes a missing or unreadable
// texture or material library an error instead of a warning (Scene::strict_assets).
Scene load_scene(const std::string& path, const std::string& camera_name = "", bool strict_assets = false);

}  // namespace facet
