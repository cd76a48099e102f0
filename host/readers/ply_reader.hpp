// PLY meshes (ASCII, binary little and big endian; gzip'd too) appended to a Scene,
// read by Assimp's PLY importer (Debian's libassimp-dev). Errors are facet::Error
// naming the file.
#pragma once

#include <string>

#include "host/readers/triangle_mesh.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// Appends the faces of the PLY at `path` (polygons of any size, triangulated) with the
// default material, or options.material_override. Normals: the file's (nx ny nz), else
// area-weighted vertex normals (a PLY's faces share vertices; scans are smooth
// surfaces), unless options.normals forces a rule. Texture coordinates (u v or s t) are
// kept for textures (v flipped, as OBJ's).
void load_ply(const std::string& path, Scene& scene, const MeshOptions& options = {});

}  // namespace facet
