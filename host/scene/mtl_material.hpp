// Wavefront MTL materials: a strict reader (every number checked, errors name the
// file and line) and the mapping of MTL parameters onto FcMaterial.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shared/scene.h"

namespace facet {

struct MtlMaterial {
    std::string name;
    FcMaterial material{};
    // Kept as read for the models still to come; FcMaterial has no field for them yet.
    float dissolve = 1.0f;  // d (1 = opaque)
    float metallic = 0.0f;  // Pm
    int illum = 2;
};

// Parses the MTL text of `path`. Mapping: Kd -> diffuse, Ks -> specular, Ke ->
// emission, Ni -> ior (default 1.5); roughness = Pr when given, else converted from
// the Blinn-Phong exponent Ns as sqrt(2 / (Ns + 2)) (Walter et al. 2007, eq. 36's
// inverse, Beckmann alpha); alpha_x = alpha_y = roughness; model Lambert for now.
// Texture statements (map_Kd, bump, ...) add a warning to `warnings`: textures are
// not supported yet and are ignored (the warning also says when the file is missing).
// Throws facet::Error "file.mtl:LINE: ..." on malformed numbers or misplaced statements.
std::vector<MtlMaterial> parse_mtl(const std::string& path, std::string_view text,
                                   std::vector<std::string>& warnings);

}  // namespace facet
