// The mip pyramid of a normal map: its smaller levels hold the mean direction of the unit
// normals they cover, and in alpha the length of their mean (1 where they all agree,
// less where the bumps under one texel point apart). The kernels turn that length into
// added roughness (add_normal_spread, kernels/texture/material_textures.cl), so that a
// bumpy surface seen from afar keeps the spread of its bumps instead of flattening into
// the smooth surface the averaged normals would describe (docs/textures.md, "Normal maps").
#pragma once

namespace facet {

struct TextureImage;

// Rebuilds levels 1 and up of `t` (a tangent-space normal map, texels encoding n as
// 0.5 n + 0.5) from its level-0 normals made unit: each smaller texel's RGB encodes the
// unit direction of the mean of the unit normals it covers and its A the mean's length.
// Level 0 is kept as stored, with A = 1.
void build_normal_map_pyramid(TextureImage& t);

}  // namespace facet
