// JSON scene files: meshes (OBJ, PLY, glTF and Assimp files, chosen by extension), shapes (spheres, quads) and their
// transforms.
#include <optional>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/error.hpp"
#include "host/readers/json_loader.hpp"
#include "host/readers/gltf_reader.hpp"
#include "host/readers/gzip_file.hpp"
#include "host/readers/obj_reader.hpp"
#include "host/readers/assimp_reader.hpp"
#include "host/readers/ply_reader.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

// "rotate": [angle_degrees, axis_x, axis_y, axis_z] or a list of them, applied in order.
glm::mat4 rotation(const JsonReader& r, const Json& rot, const std::string& p) {
    glm::mat4 rotation(1.0f);
    const bool list = rot.is_array() && !rot.empty() && rot[0].is_array();
    const std::size_t n = list ? rot.size() : 1;
    for (std::size_t i = 0; i < n; ++i) {
        const Json& one = list ? rot[i] : rot;
        const std::string pi = list ? JsonReader::index(p, i) : p;
        if (!one.is_array() || one.size() != 4)
            r.fail(pi, "expected [angle_degrees, axis_x, axis_y, axis_z] (or a list of them)");
        const float angle = static_cast<float>(r.number(one[0], JsonReader::index(pi, 0)));
        glm::vec3 axis;
        for (int a = 0; a < 3; ++a) {
            const auto ai = static_cast<std::size_t>(a + 1);
            axis[a] = static_cast<float>(r.number(one[ai], JsonReader::index(pi, ai)));
        }
        if (!(glm::length(axis) > 0.0f)) r.fail(pi, "rotation axis is zero");
        rotation = glm::rotate(glm::mat4(1.0f), glm::radians(angle), glm::normalize(axis)) * rotation;
    }
    return rotation;
}

}  // namespace

glm::mat4 JsonLoader::transform(const Json& v, const std::string& path) {
    r.object(v, path, {"scale", "rotate", "translate"});
    glm::vec3 scale(1.0f);
    if (v.contains("scale")) {
        const std::string p = JsonReader::key(path, "scale");
        scale = v["scale"].is_number() ? glm::vec3(static_cast<float>(r.number(v["scale"], p))) : r.vec3(v["scale"], p);
        if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) r.fail(p, "must not be zero");
    }
    const glm::mat4 rotate =
        v.contains("rotate") ? rotation(r, v["rotate"], JsonReader::key(path, "rotate")) : glm::mat4(1.0f);
    glm::vec3 translate(0.0f);
    if (v.contains("translate")) translate = r.vec3(v["translate"], JsonReader::key(path, "translate"));
    return glm::translate(glm::mat4(1.0f), translate) * rotate * glm::scale(glm::mat4(1.0f), scale);
}

void JsonLoader::mesh(const Json& v, const std::string& path) {
    r.object(v, path, {"file", "material", "materials", "transform", "normals"});
    r.require(v, path, "file");
    const std::string full = existing_file(v["file"], JsonReader::key(path, "file"), "mesh file");
    ObjLoadOptions options;
    if (v.contains("material"))
        options.material_override = material_ref(v["material"], JsonReader::key(path, "material"));
    if (v.contains("materials")) {
        const std::string p = JsonReader::key(path, "materials");
        if (!v["materials"].is_object()) r.fail(p, "expected an object {\"mtl name\": \"material\"}");
        for (const auto& item : v["materials"].items())
            options.material_map[item.key()] = material_ref(item.value(), JsonReader::key(p, item.key()));
    }
    if (v.contains("transform")) options.transform = transform(v["transform"], JsonReader::key(path, "transform"));
    if (v.contains("normals")) {
        const std::string p = JsonReader::key(path, "normals");
        const std::string name = r.string(v["normals"], p);
        const std::optional<NormalRule> rule = normal_rule_from_name(name);
        if (!rule) r.fail(p, fmt::format("unknown normal rule '{}' (expected file, smooth or flat)", name));
        options.normals = *rule;
    }
    const std::string ext = extension_under_gz(full);
    MeshOptions mesh_options;
    mesh_options.transform = options.transform;
    mesh_options.material_override = options.material_override;
    mesh_options.normals = options.normals;
    if ((ext == ".ply" || ext == ".gltf" || ext == ".glb" || is_assimp_format(ext)) && !options.material_map.empty())
        r.fail(JsonReader::key(path, "materials"),
               "maps MTL material names, which only an OBJ has (use 'material' to replace every material)");
    try {
        if (ext == ".ply") {
            load_ply(full, scene, mesh_options);
        } else if (is_assimp_format(ext)) {
            load_assimp(full, scene, mesh_options);
        } else if (ext == ".gltf" || ext == ".glb") {
            GltfLoadOptions gltf_options;
            gltf_options.mesh = mesh_options;
            gltf_options.take_camera = false;
            load_gltf(full, scene, gltf_options);
        } else {
            load_obj(full, scene, options);
        }
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}: {}", r.file(), path, e.what()));
    }
}

namespace {

void sphere(JsonLoader& l, const Json& v, const std::string& path) {
    const JsonReader& r = l.r;
    auto k = [&](const char* key) { return JsonReader::key(path, key); };
    r.object(v, path, {"type", "center", "radius", "subdivisions", "material", "inward", "tessellate"});
    r.require(v, path, "center");
    r.require(v, path, "radius");
    const glm::vec3 center = r.vec3(v["center"], k("center"));
    const float radius = r.number_in(v["radius"], k("radius"), 0, 1e30, true);
    int subdivisions = 3;
    if (v.contains("subdivisions"))
        subdivisions = static_cast<int>(r.integer(v["subdivisions"], k("subdivisions"), 0, 8));
    const bool inward = v.contains("inward") && r.boolean(v["inward"], k("inward"));
    // Analytic unless a mesh is asked for ("subdivisions" alone only says how fine it would be).
    const bool tessellate = v.contains("tessellate") && r.boolean(v["tessellate"], k("tessellate"));
    if (tessellate) add_sphere(l.scene, center, radius, subdivisions, l.optional_material(v, path), inward);
    else add_analytic_sphere(l.scene, center, radius, l.optional_material(v, path), inward);
}

void quad(JsonLoader& l, const Json& v, const std::string& path) {
    const JsonReader& r = l.r;
    auto k = [&](const char* key) { return JsonReader::key(path, key); };
    r.object(v, path, {"type", "corner", "edge1", "edge2", "material"});
    for (const char* key : {"corner", "edge1", "edge2"}) r.require(v, path, key);
    const glm::vec3 corner = r.vec3(v["corner"], k("corner"));
    const glm::vec3 e1 = r.vec3(v["edge1"], k("edge1"));
    const glm::vec3 e2 = r.vec3(v["edge2"], k("edge2"));
    if (!(glm::length(wide_cross(e1, e2)) > 0.0)) r.fail(path, "edge1 and edge2 span no area");
    add_quad(l.scene, corner, e1, e2, l.optional_material(v, path));
}

}  // namespace

void JsonLoader::shape(const Json& v, const std::string& path) {
    if (!v.is_object()) r.fail(path, "expected an object");
    r.require(v, path, "type");
    const std::string type = r.string(v["type"], JsonReader::key(path, "type"));
    if (type == "sphere") sphere(*this, v, path);
    else if (type == "quad") quad(*this, v, path);
    else
        r.fail(JsonReader::key(path, "type"),
               fmt::format("unknown shape type '{}' (expected 'sphere' or 'quad')", type));
}

}  // namespace facet
