// OBJ meshes (with their MTL materials) appended to a Scene (host/readers/obj_reader.cpp).
// Errors are facet::Error naming the file and line.
#pragma once

#include <map>
#include <string>

#include <glm/mat4x4.hpp>

#include "host/readers/mesh_normals.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// Appends the triangles and materials of an OBJ (and its MTL) to `scene`.
// `transform` is applied to positions (its inverse transpose to normals);
// `material_override`, when >= 0, is an index into scene.materials that replaces
// every material of the mesh.
void load_obj(const std::string& path, Scene& scene, const glm::mat4& transform = glm::mat4(1.0f),
              int material_override = -1);

struct ObjLoadOptions {
    glm::mat4 transform{1.0f};
    int material_override = -1;               // as above
    std::map<std::string, int> material_map;  // MTL material name -> scene material index
    NormalRule normals = NormalRule::File;    // the file's normals and smoothing groups, or forced
};

// As above, with a per-MTL-material override (`material_map`); a name in the map
// that the MTL does not define is an error.
void load_obj(const std::string& path, Scene& scene, const ObjLoadOptions& options);

}  // namespace facet
