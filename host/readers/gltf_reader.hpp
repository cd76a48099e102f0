// glTF 2.0 files (.gltf with .bin buffers or data URIs, .glb) appended to a Scene, read
// by Debian's libtinygltf: meshes through the node hierarchy, materials, KHR_lights_punctual
// and the first camera. docs/scene-format.md lists what is read and what is ignored;
// everything ignored is named in a warning. Errors are facet::Error naming the file and
// the place ("model.gltf: meshes[0].primitives[1].attributes.POSITION: accessor 5: ...").
#pragma once

#include <string>

#include "host/readers/triangle_mesh.hpp"
#include "host/scene/scene.hpp"

namespace facet {

struct GltfLoadOptions {
    MeshOptions mesh;         // transform, material override, normal rule
    bool take_camera = true;  // set scene.camera from the first camera a node uses
    std::string camera_name;  // non-empty: the camera of this name instead (--camera NAME)
    bool take_lights = true;  // KHR_lights_punctual into scene.punctual_lights
    bool instancing = true;   // a mesh several nodes use stored once and instanced; off: copied
};

// Appends the default scene's meshes (every node's world transform applied): a mesh one
// node uses is copied into world space; a mesh several nodes use is stored once in object
// space (Scene::meshes) with one instance per node (Scene::instances), unless it emits
// light or `options.instancing` is off (then it is copied for each). Returns whether a
// camera was taken.
bool load_gltf(const std::string& path, Scene& scene, const GltfLoadOptions& options = {});

}  // namespace facet
