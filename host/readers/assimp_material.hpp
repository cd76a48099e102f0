// Assimp's materials (aiMaterial) as facet's Material: the mapping is the MTL reader's,
// from the keys Assimp fills for every format (docs/scene-format.md, "Other formats").
#pragma once

#include <set>
#include <string>

#include <assimp/scene.h>

#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// - PBR keys (base colour, metallic, roughness: FBX's and glTF-like exporters'): GGX,
//   glTF's metallic-roughness mix, alpha = roughness^2;
// - a specular colour with a shininess > 0: normalized Blinn-Phong (Ks, exponent);
// - otherwise Lambert with the diffuse colour.
// Emissive colour is the emission. Textures: diffuse / base colour, emissive and normal
// maps, from files beside the model (Windows paths and absolute paths of the exporting
// machine resolved to the model's folder) or embedded in it (aiTexture). What is not read
// (opacity, other texture kinds, uncompressed embedded images) is added to `ignored`, one
// line per kind. `file` is the model's path, for the texture messages.
Material assimp_material(const aiScene& ai, unsigned index, const std::string& file, Scene& scene,
                         std::set<std::string>& ignored);

}  // namespace facet
