// Models of the formats other tools exchange (STL, FBX, Collada, 3DS, ...) read through
// Assimp (Debian's libassimp-dev), appended to a Scene. OBJ, PLY and glTF have readers of
// their own. Every file Assimp opens passes facet's input checks (assimp_io.hpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "host/readers/triangle_mesh.hpp"
#include "host/scene/scene.hpp"

namespace facet {

struct AssimpFormat {
    std::string_view extension;  // ".stl", lower case
    std::string_view name;       // "STL"
};

// The formats read through Assimp, each with its extension.
const std::vector<AssimpFormat>& assimp_formats();

// Whether `ext` (lower case, with its dot) is one of assimp_formats().
bool is_assimp_format(std::string_view ext);

// Appends the model at `path`: its node hierarchy applied to the meshes (each placed once
// per node naming it), polygons triangulated, points and lines dropped (one warning);
// materials as assimp_material.hpp maps them (or options.material_override). Normals:
// the file's, else face normals, unless options.normals forces a rule. What facet does not
// read (animations, skins, lights, cameras, ...) is one warning per kind. Throws
// facet::Error naming the file when Assimp cannot read it or it holds no triangle.
void load_assimp(const std::string& path, Scene& scene, const MeshOptions& options = {});

}  // namespace facet
