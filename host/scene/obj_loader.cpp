// OBJ meshes (with their MTL materials) appended to a Scene. The text is checked
// line by line first (obj_validate.cpp, mtl_material.cpp) so that malformed files
// give "file:LINE: ..." errors; tinyobjloader then reads it (triangulating polygons).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "host/error.hpp"
#include "host/scene/load.hpp"
#include "host/scene/material.hpp"
#include "host/scene/mtl_material.hpp"
#include "host/scene/obj_validate.hpp"
#include "host/scene/text_parse.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

// Reads every material library the OBJ names. A missing one is a warning (faces
// using it get the default material); a malformed one is an error.
std::vector<MtlMaterial> read_mtllibs(const std::string& path, const ObjScan& scan, Scene& scene,
                                      std::string& all_mtl_text) {
    std::vector<MtlMaterial> materials;
    const std::string dir = text::directory_of(path);
    for (const ObjNamedRef& lib : scan.mtllibs) {
        const std::string mtl_path = text::join_path(dir, lib.name);
        std::error_code ec;
        if (!std::filesystem::exists(mtl_path, ec)) {   // a non-regular one: read_file says so
            scene.warnings.push_back(fmt::format(
                "{}:{}: material library '{}' not found (looked for '{}'); its materials "
                "get the default material",
                path, lib.line, lib.name, mtl_path));
            continue;
        }
        const std::string mtl_text = text::read_file(mtl_path, "MTL file");
        auto parsed = parse_mtl(mtl_path, mtl_text, scene.warnings);
        if (parsed.empty())
            scene.warnings.push_back(fmt::format("{}:{}: material library '{}' defines no material (empty, or not "
                                                 "an MTL file)",
                                                 path, lib.line, mtl_path));
        materials.insert(materials.end(), parsed.begin(), parsed.end());
        all_mtl_text += mtl_text;
        all_mtl_text += "\n";
    }
    return materials;
}

bool usable(glm::vec3 n) {
    const double len = wide_length(n);
    return len > 0.0 && std::isfinite(len);
}

}  // namespace

void load_obj(const std::string& path, Scene& scene, const glm::mat4& transform,
              int material_override) {
    ObjLoadOptions options;
    options.transform = transform;
    options.material_override = material_override;
    load_obj(path, scene, options);
}

void load_obj(const std::string& path, Scene& scene, const ObjLoadOptions& options) {
    const std::string obj_text = text::read_file(path, "OBJ file");
    const ObjScan scan = validate_obj(path, obj_text);
    std::string mtl_text;
    const std::vector<MtlMaterial> mtl = read_mtllibs(path, scan, scene, mtl_text);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(obj_text, mtl_text, config)) {
        throw Error(fmt::format("{}: {}", path, reader.Error()));
    }

    // MTL material name -> scene material index, made on first use.
    for (const auto& [name, index] : options.material_map) {
        bool found = false;
        for (const MtlMaterial& m : mtl) found = found || m.name == name;
        if (!found) {
            throw Error(
                fmt::format("{}: material override names '{}', which no material "
                            "library of this OBJ defines",
                            path, name));
        }
    }
    std::map<std::string, int> warned;
    for (const ObjNamedRef& use : scan.usemtls) {
        bool found = false;   // a library that is missing was warned about already
        for (const ObjNamedRef& lib : scan.mtllibs) {
            std::error_code ec;
            found = found || !std::filesystem::exists(text::join_path(text::directory_of(path), lib.name), ec);
        }
        for (const MtlMaterial& m : mtl) found = found || m.name == use.name;
        if (!found && warned[use.name]++ == 0) {
            scene.warnings.push_back(
                fmt::format("{}:{}: 'usemtl {}' names no material of the "
                            "material libraries; the default material is used",
                            path, use.line, use.name));
        }
    }
    std::map<std::string, int> by_name;
    int default_index = -1;
    auto scene_material = [&](int tiny_id) {
        if (options.material_override >= 0) return options.material_override;
        const auto& tiny = reader.GetMaterials();
        if (tiny_id < 0 || static_cast<std::size_t>(tiny_id) >= tiny.size()) {
            if (default_index < 0)
                default_index = add_material(scene, default_material(), "default");
            return default_index;
        }
        const std::string& name = tiny[static_cast<std::size_t>(tiny_id)].name;
        if (auto it = options.material_map.find(name); it != options.material_map.end()) {
            return it->second;
        }
        if (auto it = by_name.find(name); it != by_name.end()) return it->second;
        FcMaterial m = default_material();
        for (const MtlMaterial& candidate : mtl) {
            if (candidate.name == name) m = candidate.material;  // the last definition wins
        }
        // As for JSON materials: a reflectance above 1 creates energy; clamped, with a warning.
        bool clamped = false;
        for (int c = 0; c < 3; ++c) {
            clamped = clamped || m.diffuse[c] > 1.0f || m.specular[c] > 1.0f;
            m.diffuse[c] = std::min(m.diffuse[c], 1.0f);
            m.specular[c] = std::min(m.specular[c], 1.0f);
        }
        if (clamped)
            scene.warnings.push_back(fmt::format(
                "{}: material '{}': a reflectance (Kd, Ks) above 1 creates energy; clamped to 1", path, name));
        if (std::string problem = validate_material(m); !problem.empty())
            throw Error(fmt::format("{}: material '{}': {}", path, name, problem));
        return by_name[name] = add_material(scene, m, name);
    };

    // Every index tinyobjloader returns is checked against its own arrays: the validator
    // counts statements the same way, but an index out of range here must never be read.
    const auto& attrib = reader.GetAttrib();
    for (const auto& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            const bool vertex_ok = i.vertex_index >= 0 && std::size_t(i.vertex_index) < attrib.vertices.size() / 3;
            const bool normal_ok = i.normal_index == -1 ||
                                   (i.normal_index >= 0 && std::size_t(i.normal_index) < attrib.normals.size() / 3);
            if (!vertex_ok || !normal_ok)
                throw Error(fmt::format("{}: a face index is out of range for what tinyobjloader read (it reads some "
                                        "statements differently from facet's checks); the file is malformed",
                                        path));
        }
    }

    // Positions in world space; normals by the inverse transpose.
    const std::size_t npos = attrib.vertices.size() / 3;
    std::vector<glm::vec3> pos(npos);
    for (std::size_t i = 0; i < npos; ++i) {
        const glm::vec4 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                          attrib.vertices[3 * i + 2], 1.0f);
        pos[i] = glm::vec3(options.transform * p);
    }
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(options.transform)));
    // A mirroring transform reverses the winding (and the sign of position cross
    // products): triangles are stored with two corners swapped to keep the front face.
    const bool mirrored = glm::determinant(glm::mat3(options.transform)) < 0.0f;
    const float side = mirrored ? -1.0f : 1.0f;
    auto obj_normal = [&](int index) {
        const std::size_t i = static_cast<std::size_t>(index);
        return normal_matrix * glm::vec3(attrib.normals[3 * i], attrib.normals[3 * i + 1],
                                         attrib.normals[3 * i + 2]);
    };

    // Smooth, area-weighted vertex normals for corners without an OBJ normal.
    std::vector<glm::dvec3> smooth(npos, glm::dvec3(0.0));
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t k = 0; k + 2 < idx.size(); k += 3) {
            const int a = idx[k].vertex_index, b = idx[k + 1].vertex_index,
                      c = idx[k + 2].vertex_index;
            const glm::dvec3 area2 =
                wide_cross(pos[static_cast<std::size_t>(b)] - pos[static_cast<std::size_t>(a)],
                           pos[static_cast<std::size_t>(c)] - pos[static_cast<std::size_t>(a)]);
            for (int v : {a, b, c}) smooth[static_cast<std::size_t>(v)] += double(side) * area2;
        }
    }

    // Triangles of zero area (repeated or collinear corners, also from triangulating a
    // degenerate polygon) are never hit and carry no light: dropped, with a warning.
    std::size_t degenerate = 0, kept = 0;
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; 3 * f + 2 < idx.size(); ++f) {
            glm::vec3 p[3], n[3];
            for (int c = 0; c < 3; ++c)
                p[c] = pos[static_cast<std::size_t>(idx[3 * f + c].vertex_index)];
            if (!(triangle_area(p[0], p[1], p[2]) > 0.0)) {
                ++degenerate;
                continue;
            }
            ++kept;
            const glm::vec3 fn = side * triangle_normal(p[0], p[1], p[2]);
            for (int c = 0; c < 3; ++c) {
                const tinyobj::index_t& i = idx[3 * f + c];
                n[c] = i.normal_index >= 0 ? obj_normal(i.normal_index)
                                           : unit_or(smooth[static_cast<std::size_t>(i.vertex_index)], fn);
                if (!usable(n[c])) n[c] = fn;  // zero or invalid normal: the face's own
            }
            if (mirrored) {
                std::swap(p[1], p[2]);
                std::swap(n[1], n[2]);
            }
            const int tiny_id =
                f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            add_triangle(scene, p[0], p[1], p[2], n[0], n[1], n[2], scene_material(tiny_id));
        }
    }
    if (kept == 0)
        throw Error(fmt::format("{}: every face has zero area ({} triangles): nothing to render", path, degenerate));
    if (degenerate > 0)
        scene.warnings.push_back(fmt::format("{}: {} of {} triangles have zero area and were dropped", path,
                                             degenerate, degenerate + kept));
}

}  // namespace facet
