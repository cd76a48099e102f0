// The JSON scene reader's state and its parts, one per section of the file
// (docs/scene-format.md): json_scene.cpp (the file, render settings, camera),
// json_material.cpp, json_geometry.cpp (meshes, shapes, transforms) and
// json_lights.cpp (punctual lights, the environment). Private to host/readers/.
#pragma once

#include <map>
#include <string>

#include <glm/mat4x4.hpp>

#include "host/readers/json_schema.hpp"
#include "host/scene/scene.hpp"

namespace facet {

struct JsonLoader {
    JsonReader r;
    std::string dir;  // the scene file's directory: file names are relative to it
    Scene& scene;
    std::map<std::string, int> materials;  // JSON material name -> scene index
    int default_index = -1;

    // json_scene.cpp
    void camera(const Json& v, const std::string& path);
    void render(const Json& v, const std::string& path);
    void filter(const Json& v, const std::string& path);
    // json_material.cpp
    void material(const std::string& name, const Json& v, const std::string& path);
    int material_ref(const Json& v, const std::string& path);
    int optional_material(const Json& obj, const std::string& path);
    // json_geometry.cpp
    glm::mat4 transform(const Json& v, const std::string& path);
    void mesh(const Json& v, const std::string& path);
    void shape(const Json& v, const std::string& path);
    // json_lights.cpp
    void light(const Json& v, const std::string& path);
    void environment(const Json& v, const std::string& path);

    // An existing file named by `v` (relative to the scene's directory), its full path.
    std::string existing_file(const Json& v, const std::string& path, const char* what);
};

}  // namespace facet
