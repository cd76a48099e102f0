// OBJ meshes (with their MTL materials) appended to a Scene. The text is checked
// line by line first (obj_validate.cpp, mtl_material.cpp) so that malformed files
// give "file:LINE: ..." errors; tinyobjloader then reads it (triangulating polygons).
#include "host/readers/obj_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdint>
#include <map>
#include <unordered_map>

#include <fmt/format.h>
#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "host/error.hpp"
#include "host/scene/material.hpp"
#include "host/readers/mesh_normals.hpp"
#include "host/readers/mtl_material.hpp"
#include "host/readers/obj_validate.hpp"
#include "host/readers/text_parse.hpp"
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
        if (!std::filesystem::exists(mtl_path, ec)) {  // a non-regular one: read_file says so
            asset_warning(scene, fmt::format("{}:{}: material library '{}' not found (looked for '{}'); its "
                                             "materials get the default material",
                                             path, lib.line, lib.name, mtl_path));
            continue;
        }
        const std::string mtl_text = text::read_file(mtl_path, "MTL file");
        auto parsed = parse_mtl(mtl_path, mtl_text, scene.warnings);
        if (parsed.empty())
            scene.warnings.push_back(
                fmt::format("{}:{}: material library '{}' defines no material (empty, or not "
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

// A mesh as tinyobjloader reads it, with the MTL materials facet read beside it.
struct ParsedObj {
    ObjScan scan;
    std::vector<MtlMaterial> mtl;
    tinyobj::ObjReader reader;
};

void parse(const std::string& path, Scene& scene, ParsedObj& obj) {
    const std::string obj_text = text::read_file(path, "OBJ file");
    obj.scan = validate_obj(path, obj_text);
    std::string mtl_text;
    obj.mtl = read_mtllibs(path, obj.scan, scene, mtl_text);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    if (!obj.reader.ParseFromString(obj_text, mtl_text, config))
        throw Error(fmt::format("{}: {}", path, obj.reader.Error()));
}

bool defines(const std::vector<MtlMaterial>& mtl, const std::string& name) {
    for (const MtlMaterial& m : mtl)
        if (m.name == name) return true;
    return false;
}

// Every overridden name must exist; a 'usemtl' of an unknown name is a warning (once).
void check_material_names(const std::string& path, const ParsedObj& obj, const ObjLoadOptions& options, Scene& scene) {
    for (const auto& [name, index] : options.material_map) {
        if (!defines(obj.mtl, name))
            throw Error(fmt::format("{}: material override names '{}', which no material library of this OBJ defines",
                                    path, name));
    }
    std::map<std::string, int> warned;
    for (const ObjNamedRef& use : obj.scan.usemtls) {
        bool libraries_missing = false;  // a library that is missing was warned about already
        for (const ObjNamedRef& lib : obj.scan.mtllibs) {
            std::error_code ec;
            libraries_missing =
                libraries_missing || !std::filesystem::exists(text::join_path(text::directory_of(path), lib.name), ec);
        }
        if (!libraries_missing && !defines(obj.mtl, use.name) && warned[use.name]++ == 0)
            scene.warnings.push_back(
                fmt::format("{}:{}: 'usemtl {}' names no material of the "
                            "material libraries; the default material is used",
                            path, use.line, use.name));
    }
}

// The scene material of each tinyobjloader material id, added on first use.
class ObjMaterials {
public:
    ObjMaterials(const std::string& path, const ParsedObj& obj, const ObjLoadOptions& options, Scene& scene)
        : path_(path), obj_(obj), options_(options), scene_(scene) {}

    int index(int tiny_id) {
        if (options_.material_override >= 0) return options_.material_override;
        const auto& tiny = obj_.reader.GetMaterials();
        if (tiny_id < 0 || static_cast<std::size_t>(tiny_id) >= tiny.size()) {
            if (default_index_ < 0) default_index_ = add_material(scene_, default_material(), "default");
            return default_index_;
        }
        const std::string& name = tiny[static_cast<std::size_t>(tiny_id)].name;
        if (auto it = options_.material_map.find(name); it != options_.material_map.end()) return it->second;
        if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
        return by_name_[name] = add_material(scene_, converted(name), name);
    }

private:
    Material converted(const std::string& name) {
        Material m = default_material();
        const MtlMaterial* mtl = nullptr;
        for (const MtlMaterial& candidate : obj_.mtl)
            if (candidate.name == name) mtl = &candidate;  // the last definition wins
        if (mtl) m = mtl->material;
        // As for JSON materials: a reflectance (Kd, Ks) above 1 is clamped, with a warning.
        if (std::string warning = clamp_reflectance(m, "(Kd, Ks)"); !warning.empty())
            scene_.warnings.push_back(fmt::format("{}: material '{}': {}", path_, name, warning));
        if (std::string problem = validate_material(m); !problem.empty())
            throw Error(fmt::format("{}: material '{}': {}", path_, name, problem));
        if (mtl) bind_mtl_textures(*mtl, m, scene_);
        return m;
    }

    const std::string& path_;
    const ParsedObj& obj_;
    const ObjLoadOptions& options_;
    Scene& scene_;
    std::map<std::string, int> by_name_;
    int default_index_ = -1;
};

// Every index tinyobjloader returns is checked against its own arrays: the validator
// counts statements the same way, but an index out of range here must never be read.
void check_indices(const std::string& path, const tinyobj::ObjReader& reader) {
    const auto& attrib = reader.GetAttrib();
    for (const auto& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            const bool vertex_ok = i.vertex_index >= 0 && std::size_t(i.vertex_index) < attrib.vertices.size() / 3;
            const bool normal_ok = i.normal_index == -1 ||
                                   (i.normal_index >= 0 && std::size_t(i.normal_index) < attrib.normals.size() / 3);
            if (!vertex_ok || !normal_ok)
                throw Error(
                    fmt::format("{}: a face index is out of range for what tinyobjloader read (it reads some "
                                "statements differently from facet's checks); the file is malformed",
                                path));
        }
    }
}

// The mesh in world space: positions and OBJ normals (by the inverse transpose), and
// the smooth, area-weighted vertex normals of each smoothing group ('s 1', 's 2', ...)
// for corners without an OBJ normal; a face with smoothing off ('s off', 's 0', or no
// 's' before it) is flat there. NormalRule::Smooth smooths such faces as one group,
// NormalRule::Flat ignores the file's normals. A mirroring transform reverses the
// winding (and the sign of position cross products): triangles are stored with two
// corners swapped to keep the front face.
struct WorldMesh {
    const tinyobj::attrib_t& attrib;
    NormalRule rule;
    std::vector<glm::vec3> pos;
    std::unordered_map<std::uint64_t, glm::dvec3> smooth;  // (vertex, group): area-weighted sums, in double
    glm::mat3 normal_matrix;
    bool mirrored;
    float side;

    WorldMesh(const tinyobj::ObjReader& reader, const glm::mat4& transform, NormalRule normal_rule)
        : attrib(reader.GetAttrib()), rule(normal_rule),
          normal_matrix(glm::transpose(glm::inverse(glm::mat3(transform)))),
          mirrored(glm::determinant(glm::mat3(transform)) < 0.0f), side(mirrored ? -1.0f : 1.0f) {
        const std::size_t npos = attrib.vertices.size() / 3;
        pos.resize(npos);
        for (std::size_t i = 0; i < npos; ++i) {
            const glm::vec4 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2], 1.0f);
            pos[i] = glm::vec3(transform * p);
        }
        for (const auto& shape : reader.GetShapes()) {
            const auto& idx = shape.mesh.indices;
            for (std::size_t f = 0; 3 * f + 2 < idx.size(); ++f) {
                const unsigned group = this->group(shape.mesh, f);
                if (group == 0) continue;
                const std::size_t a = std::size_t(idx[3 * f].vertex_index),
                                  b = std::size_t(idx[3 * f + 1].vertex_index),
                                  c = std::size_t(idx[3 * f + 2].vertex_index);
                const glm::dvec3 area2 = wide_cross(pos[b] - pos[a], pos[c] - pos[a]);
                for (std::size_t v : {a, b, c}) smooth[key(v, group)] += double(side) * area2;
            }
        }
    }

    static std::uint64_t key(std::size_t vertex, unsigned group) { return (std::uint64_t(vertex) << 32) | group; }

    // The face's smoothing group as the rule reads it (0: flat).
    unsigned group(const tinyobj::mesh_t& mesh, std::size_t face) const {
        if (rule == NormalRule::Flat) return 0;
        if (rule == NormalRule::Smooth) return 1;
        return face < mesh.smoothing_group_ids.size() ? mesh.smoothing_group_ids[face] : 0;
    }

    // The corner's OBJ normal, else its group's smooth one, else (none, zero or invalid)
    // the face's own; `counts` says which.
    glm::vec3 normal(const tinyobj::index_t& i, unsigned group, glm::vec3 face_n, NormalCounts& counts) const {
        if (i.normal_index >= 0 && rule != NormalRule::Flat) {
            const std::size_t k = static_cast<std::size_t>(i.normal_index);
            const glm::vec3 n =
                normal_matrix * glm::vec3(attrib.normals[3 * k], attrib.normals[3 * k + 1], attrib.normals[3 * k + 2]);
            if (usable(n)) {
                ++counts.file;
                return n;
            }
        }
        if (group != 0) {
            const auto it = smooth.find(key(static_cast<std::size_t>(i.vertex_index), group));
            if (it != smooth.end() && usable(glm::vec3(it->second))) {
                ++counts.smoothed;
                return unit_or(it->second, face_n);
            }
        }
        ++counts.flat;
        return face_n;
    }
};

// The face's OBJ uvs (v flipped: OBJ's v runs up the image, facet's down) on the
// triangle just added; none when a corner has no 'vt'.
void add_texcoords(const tinyobj::attrib_t& attrib, const tinyobj::index_t* corner, bool mirrored, Scene& scene) {
    glm::vec2 uv[3];
    for (int c = 0; c < 3; ++c) {
        const int k = corner[c].texcoord_index;
        if (k < 0 || 2 * std::size_t(k) + 1 >= attrib.texcoords.size()) return;
        uv[c] = glm::vec2(attrib.texcoords[2 * std::size_t(k)], 1.0f - attrib.texcoords[2 * std::size_t(k) + 1]);
    }
    if (mirrored) std::swap(uv[1], uv[2]);
    set_triangle_texcoords(scene, scene.shading.size() - 1, uv[0], uv[1], uv[2]);
}

// Triangles of zero area (repeated or collinear corners, also from triangulating a
// degenerate polygon) are never hit and carry no light: dropped, with a warning.
void add_faces(const std::string& path, const tinyobj::ObjReader& reader, const WorldMesh& mesh,
               ObjMaterials& materials, Scene& scene) {
    std::size_t degenerate = 0, kept = 0;
    NormalCounts counts;
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; 3 * f + 2 < idx.size(); ++f) {
            glm::vec3 p[3], n[3];
            for (std::size_t c = 0; c < 3; ++c) p[c] = mesh.pos[static_cast<std::size_t>(idx[3 * f + c].vertex_index)];
            if (!(triangle_area(p[0], p[1], p[2]) > 0.0)) {
                ++degenerate;
                continue;
            }
            ++kept;
            const glm::vec3 fn = mesh.side * triangle_normal(p[0], p[1], p[2]);
            const unsigned group = mesh.group(shape.mesh, f);
            for (std::size_t c = 0; c < 3; ++c) n[c] = mesh.normal(idx[3 * f + c], group, fn, counts);
            if (mesh.mirrored) {
                std::swap(p[1], p[2]);
                std::swap(n[1], n[2]);
            }
            const int tiny_id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            add_triangle(scene, p[0], p[1], p[2], n[0], n[1], n[2], materials.index(tiny_id));
            add_texcoords(reader.GetAttrib(), &idx[3 * f], mesh.mirrored, scene);
        }
    }
    if (kept == 0)
        throw Error(fmt::format("{}: every face has zero area ({} triangles): nothing to render", path, degenerate));
    if (degenerate > 0)
        scene.warnings.push_back(
            fmt::format("{}: {} of {} triangles have zero area and were dropped", path, degenerate, degenerate + kept));
    scene.normal_sources.push_back(describe_normals(
        path, counts,
        mesh.rule == NormalRule::Smooth ? forced_reason(mesh.rule) : "area-weighted within the smoothing group",
        mesh.rule == NormalRule::Flat ? forced_reason(mesh.rule) : "no normal in the file, smoothing off"));
}

}  // namespace

void load_obj(const std::string& path, Scene& scene, const glm::mat4& transform, int material_override) {
    ObjLoadOptions options;
    options.transform = transform;
    options.material_override = material_override;
    load_obj(path, scene, options);
}

void load_obj(const std::string& path, Scene& scene, const ObjLoadOptions& options) {
    ParsedObj obj;
    parse(path, scene, obj);
    check_material_names(path, obj, options, scene);
    ObjMaterials materials(path, obj, options, scene);
    check_indices(path, obj.reader);
    const WorldMesh mesh(obj.reader, options.transform, options.normals);
    add_faces(path, obj.reader, mesh, materials, scene);
}

}  // namespace facet
