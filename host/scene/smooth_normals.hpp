// `--smooth-normals [ANGLE]`: shading normals recomputed for every triangle of a loaded
// scene, smooth across an edge where the faces meet at less than ANGLE degrees and sharp
// where they meet at more (Blender's "Shade Auto Smooth", and the crease angle of
// tinyobjloader's and Assimp's normal generators). Applied after any reader, so an OBJ, a
// PLY, a glTF and a JSON scene's meshes are smoothed alike (docs/scene-format.md, "Normals").
#pragma once

#include <cstddef>
#include <string>

namespace facet {

struct Scene;

// The crease angle of a bare `--smooth-normals`: Blender's default auto-smooth angle.
constexpr float kDefaultSmoothAngle = 30.0f;

struct SmoothTally {
    std::size_t triangles = 0;  // triangles whose corners were given new normals
    std::size_t smooth = 0;     // corners averaged with a neighbouring face
    std::size_t sharp = 0;      // corners left with their own face's normal (crease, border, lone)
};

// Replaces the shading normals of every world and shared-mesh triangle. A corner's normal
// is the sum of the face normals of the triangles that share its position (exactly: the
// files' shared vertices), within `angle_degrees` (0 to 180) of its own face, each
// weighted by its angle at that corner (Thürmer & Wüthrich 1998, "Computing vertex normals
// from polygonal facets", which does not depend on how the surface is tessellated). A
// face's normal follows the side its old shading normals faced, so a file whose winding
// disagrees with its normals keeps the side the file meant. Degenerate triangles keep
// their normals. Also appends a line to scene.normal_sources.
SmoothTally smooth_normals(Scene& scene, float angle_degrees);

}  // namespace facet
