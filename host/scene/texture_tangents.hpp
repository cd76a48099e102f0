// Tangent frames for normal maps and anisotropic materials (docs/textures.md, "Normal maps and tangents"): each
// triangle corner's vertex tangent, from the file (glTF TANGENT) or computed the
// MikkTSpace way (Mikkelsen 2008, "Simulation of Wrinkled Surfaces Revisited"), stored
// octahedral-encoded in FcTriTexcoords (kernels/shared/texture_layout.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "kernels/shared/texture_layout.h"

namespace facet {

struct Scene;

// A unit vector as two 16-bit signed normalised integers of its octahedral map (x in
// the low half); kernels/scene/vertex_tangent.cl decodes it.
std::uint32_t encode_octahedral(glm::vec3 unit);

// Gives scene triangle `tri` the world-space tangents of its corners: xyz the tangent,
// w = +1 or -1 the handedness (glTF: bitangent = w cross(n, t)). A corner without a
// usable tangent (zero or not finite) leaves the triangle to compute_tangents.
void set_triangle_tangents(Scene& scene, std::size_t tri, const glm::vec4 (&tangent)[3]);

// Per-vertex tangents for every triangle whose material binds a normal map or is
// anisotropic (material_is_anisotropic) and whose tangents the file did not give,
// written into `texcoords` (indexed like scene.shading):
// per triangle, t = dp/du and the handedness of its uv winding; each corner's t made
// orthogonal to the corner's normal and summed, weighted by the corner's angle, over the
// corners that share the vertex: its position, normal, uv and handedness (so a mirrored
// uv seam splits), then made orthogonal to the normal again (Gram-Schmidt).
void compute_tangents(const Scene& scene, std::vector<FcTriTexcoords>& texcoords);

}  // namespace facet
