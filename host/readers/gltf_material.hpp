// glTF materials mapped onto facet's models (docs/scene-format.md, "glTF 2.0"), and the
// record of what a file uses that facet does not read. Private to the glTF reader.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet::gltf {

// Features a file uses that facet ignores, each with the places that use it; given as
// one warning per feature: "<file>: <feature> is not supported and is ignored (materials[0]
// 'Truck', materials[2] 'Glass', ...)".
class Ignored {
public:
    void add(const std::string& feature, const std::string& place) { places_[feature].push_back(place); }
    void warn(const std::string& file, std::vector<std::string>& warnings) const;

private:
    std::map<std::string, std::vector<std::string>> places_;
};

// The extensions facet reads: KHR_lights_punctual, KHR_materials_ior,
// KHR_materials_transmission, KHR_materials_emissive_strength.
bool supported_extension(const std::string& name);

// pbrMetallicRoughness with KHR_materials_ior / _transmission / _emissive_strength as a
// facet Material: glTF's mix (Appendix B) by metallic of a dielectric (GGX, alpha =
// roughness^2, Schlick F0 = ((ior - 1)/(ior + 1))^2, over a Lambert base of the base
// colour) and a metal (the same GGX lobe, F0 = the base colour): set_metallic_roughness; transmission >= 0.5
// (non-metal) is rough glass of the IOR tinted by the base colour; emission = emissiveFactor x emissiveStrength.
// baseColorTexture, metallicRoughnessTexture, normalTexture and emissiveTexture (with KHR_texture_transform, texCoord
// 0) are loaded into scene.textures and bound (docs/textures.md). alphaMode MASK/BLEND and other extensions go to
// `ignored`. Throws facet::Error naming `place` for values outside the specification's ranges and for images that
// cannot be read.
Material convert_material(const tinygltf::Material& g, const std::string& file, const std::string& place,
                          Ignored& ignored, const tinygltf::Model& model, Scene& scene);

// glTF's default material (a white rough metal: metallic 1, roughness 1).
Material default_gltf_material();

}  // namespace facet::gltf
