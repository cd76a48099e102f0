// Indexed triangle meshes as PLY and glTF give them (positions, optional normals, three
// indices per triangle), appended to a Scene in world space: one place for the
// transform, the normal rule, mirroring and dropping zero-area triangles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "host/readers/mesh_normals.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// What a JSON scene's meshes[] entry says about a mesh file of any format.
struct MeshOptions {
    glm::mat4 transform{1.0f};
    int material_override = -1;  // an index into scene.materials replacing every material, or -1
    NormalRule normals = NormalRule::File;
};

struct IndexedMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // one per position, or empty
    std::vector<glm::vec2> texcoords;    // one per position (v = 0 at the image's top), or empty
    std::vector<glm::vec4> tangents;     // one per position (xyz, handedness w = +-1: glTF TANGENT), or empty
    std::vector<std::uint32_t> indices;  // three per triangle, each < positions.size()
};

// Totals over every mesh of one file, for its warning and its `facet info` line.
struct MeshTally {
    std::size_t kept = 0, degenerate = 0;
    NormalCounts normals;
};

// Appends `mesh` transformed by `transform` with `material`. Where the mesh has no
// usable normal (or `rule` is Flat), a corner gets the area-weighted vertex normal when
// `smooth_missing` (or `rule` is Smooth), else the face normal. Zero-area triangles are
// dropped and counted. A mirroring transform keeps the front face (two corners swapped).
void add_indexed_mesh(const IndexedMesh& mesh, const glm::mat4& transform, int material, NormalRule rule,
                      bool smooth_missing, Scene& scene, MeshTally& tally);

// After a file's meshes: the error when nothing was kept, the warning for dropped
// triangles, and the normals line (Scene::normal_sources); `smoothed_why` and `flat_why`
// are the format's reasons (describe_normals).
void finish_mesh_file(const std::string& path, const MeshTally& tally, NormalRule rule, const char* smoothed_why,
                      const char* flat_why, Scene& scene);

}  // namespace facet
