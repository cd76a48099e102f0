// Wavefront MTL materials: a strict reader (every number checked, errors name the
// file and line) and the mapping of MTL parameters onto the host's Material.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "host/scene/material.hpp"

namespace facet {

struct MtlMaterial {
    std::string name;
    Material material;
    // Kept as read for the models still to come; Material has no field for them yet.
    float dissolve = 1.0f;  // d (1 = opaque)
    float metallic = 0.0f;  // Pm
    int illum = 2;
};

// Parses the MTL text of `path`. Kd, Ks, Ke (emission), Ns, Ni (ior, default 1.5),
// illum and the PBR extension's Pr/Pm choose the model: GGX for Pr/Pm, normalized
// Blinn-Phong for Ks > 0 with illum >= 2, Lambert otherwise (mtl_material.cpp, finish()).
// Texture statements (map_Kd, bump, ...) add a warning to `warnings`: textures are
// not supported yet and are ignored (the warning also says when the file is missing).
// Throws facet::Error "file.mtl:LINE: ..." on malformed numbers or misplaced statements.
std::vector<MtlMaterial> parse_mtl(const std::string& path, std::string_view text, std::vector<std::string>& warnings);

}  // namespace facet
