// Indexed triangle meshes appended to a Scene (PLY, glTF).
#include "host/readers/triangle_mesh.hpp"

#include <cmath>

#include <fmt/format.h>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "host/error.hpp"
#include "host/scene/texture_tangents.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

bool usable(glm::vec3 n) {
    const double len = wide_length(n);
    return len > 0.0 && std::isfinite(len);
}

}  // namespace

void add_indexed_mesh(const IndexedMesh& mesh, const glm::mat4& transform, int material, NormalRule rule,
                      bool smooth_missing, Scene& scene, MeshTally& tally) {
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
    const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
    const float side = mirrored ? -1.0f : 1.0f;
    std::vector<glm::vec3> pos(mesh.positions.size());
    for (std::size_t i = 0; i < pos.size(); ++i) pos[i] = glm::vec3(transform * glm::vec4(mesh.positions[i], 1.0f));
    const bool file_normals = rule != NormalRule::Flat && mesh.normals.size() == mesh.positions.size();
    const bool smooth = rule == NormalRule::Smooth || (rule == NormalRule::File && smooth_missing);
    std::vector<glm::dvec3> sums;  // area-weighted, in double (edges up to 1e18)
    if (smooth) {
        sums.assign(pos.size(), glm::dvec3(0.0));
        for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
            const std::uint32_t a = mesh.indices[k], b = mesh.indices[k + 1], c = mesh.indices[k + 2];
            const glm::dvec3 area2 = double(side) * wide_cross(pos[b] - pos[a], pos[c] - pos[a]);
            sums[a] += area2;
            sums[b] += area2;
            sums[c] += area2;
        }
    }
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        const std::uint32_t idx[3] = {mesh.indices[k], mesh.indices[k + 1], mesh.indices[k + 2]};
        glm::vec3 p[3] = {pos[idx[0]], pos[idx[1]], pos[idx[2]]}, n[3];
        if (!(triangle_area(p[0], p[1], p[2]) > 0.0)) {
            ++tally.degenerate;
            continue;
        }
        ++tally.kept;
        const glm::vec3 face_n = side * triangle_normal(p[0], p[1], p[2]);
        for (int c = 0; c < 3; ++c) {
            n[c] = face_n;
            if (file_normals && usable(normal_matrix * mesh.normals[idx[c]])) {
                n[c] = normal_matrix * mesh.normals[idx[c]];
                ++tally.normals.file;
            } else if (smooth && usable(glm::vec3(sums[idx[c]]))) {
                n[c] = unit_or(sums[idx[c]], face_n);
                ++tally.normals.smoothed;
            } else {
                ++tally.normals.flat;
            }
        }
        if (mirrored) {
            std::swap(p[1], p[2]);
            std::swap(n[1], n[2]);
        }
        add_triangle(scene, p[0], p[1], p[2], n[0], n[1], n[2], material);
        if (mesh.texcoords.size() == mesh.positions.size()) {
            const std::uint32_t b = mirrored ? idx[2] : idx[1], c = mirrored ? idx[1] : idx[2];
            set_triangle_texcoords(scene, scene.shading.size() - 1, mesh.texcoords[idx[0]], mesh.texcoords[b],
                                   mesh.texcoords[c]);
        }
        if (mesh.tangents.size() == mesh.positions.size()) {  // the file's; else texture_tangents.cpp's
            const std::uint32_t b = mirrored ? idx[2] : idx[1], c = mirrored ? idx[1] : idx[2];
            const glm::mat3 m(transform);
            auto world = [&](const glm::vec4& v) { return glm::vec4(m * glm::vec3(v), side * v.w); };
            const glm::vec4 t[3] = {world(mesh.tangents[idx[0]]), world(mesh.tangents[b]), world(mesh.tangents[c])};
            set_triangle_tangents(scene, scene.shading.size() - 1, t);
        }
    }
}

void finish_mesh_file(const std::string& path, const MeshTally& tally, NormalRule rule, const char* smoothed_why,
                      const char* flat_why, Scene& scene) {
    if (tally.kept == 0)
        throw Error(fmt::format("{}: no triangle with a non-zero area ({} triangles): nothing to render", path,
                                tally.degenerate));
    if (tally.degenerate > 0)
        scene.warnings.push_back(fmt::format("{}: {} of {} triangles have zero area and were dropped", path,
                                             tally.degenerate, tally.degenerate + tally.kept));
    scene.normal_sources.push_back(describe_normals(path, tally.normals,
                                                    rule == NormalRule::Smooth ? forced_reason(rule) : smoothed_why,
                                                    rule == NormalRule::Flat ? forced_reason(rule) : flat_why));
}

}  // namespace facet
