// load_scene: a JSON scene file, or a bare OBJ, PLY, glTF or Assimp model (STL, FBX, ...)
// framed by a default camera (glTF: its own first camera, if it has one) and lit by default
// when it brings no light of its own (default_lighting.hpp).
#include "host/readers/load_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/error.hpp"
#include "host/readers/assimp_reader.hpp"
#include "host/readers/default_lighting.hpp"
#include "host/readers/foreign_scene.hpp"
#include "host/readers/gltf_reader.hpp"
#include "host/readers/gzip_file.hpp"
#include "host/readers/json_scene.hpp"
#include "host/readers/obj_reader.hpp"
#include "host/readers/ply_reader.hpp"
#include "host/scene/texture_validate.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

// Every vertex finite and within +-kMaxCoordinate, so that edges, cross products
// (areas, normals) and the bounding box stay finite in float arithmetic; transforms and
// shape sizes can push a finite file past that.
constexpr float kMaxCoordinate = 1e18f;

void check_geometry(const Scene& scene, const std::string& path) {
    for (std::size_t i = 0; i < scene.vertices.size(); ++i) {
        const glm::vec3& v = scene.vertices[i];
        for (int c = 0; c < 3; ++c) {
            if (std::isfinite(v[c]) && std::fabs(v[c]) <= kMaxCoordinate) continue;
            throw Error(
                fmt::format("{}: triangle {} has a vertex at ({:g}, {:g}, {:g}): coordinates must be finite and "
                            "within +-{:g} (check the transforms and the shapes' sizes)",
                            path, i / 3, v.x, v.y, v.z, kMaxCoordinate));
        }
    }
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const FcSphere& s = scene.spheres[i];
        bool ok = std::isfinite(s.radius) && s.radius <= kMaxCoordinate;
        for (int c = 0; c < 3; ++c)
            ok = ok && std::isfinite(s.center[c]) && std::fabs(s.center[c]) + s.radius <= kMaxCoordinate;
        if (!ok)
            throw Error(
                fmt::format("{}: sphere {} at ({:g}, {:g}, {:g}) of radius {:g}: it must lie within +-{:g} "
                            "(check the transforms and the shapes' sizes)",
                            path, i, s.center[0], s.center[1], s.center[2], s.radius, kMaxCoordinate));
    }
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const SharedMesh& m = scene.meshes[std::size_t(scene.instances[i].mesh)];
        const Bounds b = transformed_bounds(m.vertices, scene.instances[i].object_to_world);
        bool ok = true;
        for (const glm::vec3& v : m.vertices) ok = ok && std::isfinite(v.x + v.y + v.z);
        for (int c = 0; c < 3; ++c)
            ok = ok && std::fabs(b.lo[c]) <= kMaxCoordinate && std::fabs(b.hi[c]) <= kMaxCoordinate;
        if (!ok)
            throw Error(
                fmt::format("{}: instance {} of mesh '{}' reaches ({:g}, {:g}, {:g}) to ({:g}, {:g}, {:g}): "
                            "coordinates must be finite and within +-{:g} (check the transforms)",
                            path, i, m.name, b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z, kMaxCoordinate));
    }
}

// The first bytes of a file ("" when it cannot be read: the caller's error names it).
std::string file_head(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return head;
}

// ".obj, .ply, .stl (STL), ...": the model formats read, for the messages.
std::string model_formats() {
    std::string list = ".obj, .ply";
    for (const AssimpFormat& f : assimp_formats()) list += fmt::format(", {} ({})", f.extension, f.name);
    return list;
}

}  // namespace

Scene load_scene(const std::string& path, const std::string& camera_name, bool strict_assets) {
    Scene scene;
    scene.strict_assets = strict_assets;
    scene.source_path = path;
    if (std::error_code ec; std::filesystem::is_directory(path, ec))
        throw Error(
            fmt::format("{}: is a folder, not a scene file (give a .json scene, a model ({}) or a .gltf or "
                        ".glb file)",
                        path, model_formats()));
    const std::string ext = extension_under_gz(path);
    if (!camera_name.empty() && ext != ".gltf" && ext != ".glb")
        throw Error(
            fmt::format("{}: --camera {}: only glTF files name their cameras (use --eye, --target, --up "
                        "and --fov to place the camera)",
                        path, camera_name));
    if (ext == ".obj" || ext == ".ply" || is_assimp_format(ext)) {
        if (ext == ".obj") load_obj(path, scene);
        else if (ext == ".ply") load_ply(path, scene);
        else load_assimp(path, scene);
        check_geometry(scene, path);
        scene.camera = frame_camera(scene, Framing::Broadside);
        scene.camera_note = framing_note(scene, Framing::Broadside);
        add_default_lighting(scene);  // default_lighting.hpp
    } else if (ext == ".gltf" || ext == ".glb") {
        GltfLoadOptions options;
        options.camera_name = camera_name;
        const bool has_camera = load_gltf(path, scene, options);
        check_geometry(scene, path);
        if (!has_camera) {
            scene.camera = frame_camera(scene);
            scene.camera_note = framing_note(scene, Framing::Front);
        }
        add_default_lighting(scene);
    } else if (ext == ".json") {
        const bool has_camera = load_json_scene(path, scene);
        check_geometry(scene, path);
        if (!has_camera) scene.camera = frame_camera(scene);
    } else {
        if (std::string kind = foreign_scene_kind(ext, file_head(path)); !kind.empty())
            refuse_foreign_scene(path, kind);
        throw Error(fmt::format(
            "{}: unknown scene format '{}' (facet reads a .json scene, a .gltf or .glb file, or a model: {})", path,
            ext, model_formats()));
    }
    sanitise_textures(scene);  // texels clamped to what the materials read them as (texture_validate.hpp)
    build_lights(scene);
    if (scene.lights.empty()) {
        scene.warnings.push_back(fmt::format("{}: the scene has no emitters; the image will be black", path));
    }
    // Spheres have no uvs: their materials' alpha (docs/textures.md) is not applied to them.
    for (const FcSphere& sp : scene.spheres) {
        const std::size_t m = std::size_t(sp.material);
        if (m < scene.materials.size() && scene.materials[m].alpha_mode != FC_ALPHA_OPAQUE) {
            scene.warnings.push_back(
                fmt::format("{}: material '{}' has an alpha mode, which spheres do not read: its spheres are opaque",
                            path, m < scene.material_names.size() ? scene.material_names[m] : std::to_string(m)));
            break;
        }
    }
    return scene;
}

}  // namespace facet
