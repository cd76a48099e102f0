#include "host/scene/scene.hpp"

#include "host/error.hpp"
#include "host/scene/material.hpp"
#include "host/util/vec3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace facet {

void asset_warning(Scene& scene, const std::string& message) {
    if (scene.strict_assets) throw Error(message + " (--strict: a missing asset is an error)");
    scene.warnings.push_back(message);
}

Material default_material() {
    Material m = make_material("lambert");
    m.diffuse = glm::vec3(0.8f);
    return m;
}

FcCamera make_camera(const CameraDesc& desc, float aspect) {
    const glm::vec3 forward = glm::normalize(desc.target - desc.eye);
    const glm::vec3 right_unit = glm::normalize(glm::cross(forward, desc.up));
    const glm::vec3 up_unit = glm::cross(right_unit, forward);
    // Half the image plane: at distance 1 (perspective) or in world units (orthographic).
    const float half_height = desc.projection == FC_PROJECTION_ORTHOGRAPHIC
                                  ? 0.5f * desc.ortho_height
                                  : std::tan(0.5f * glm::radians(desc.fov_y_degrees));
    FcCamera cam{};
    store(cam.eye, desc.eye);
    store(cam.forward, forward);
    store(cam.right, right_unit * (half_height * aspect));
    store(cam.up, up_unit * half_height);
    cam.projection = desc.projection;
    cam.lens_radius = desc.projection == FC_PROJECTION_PERSPECTIVE ? desc.aperture : 0.0f;
    cam.focus_distance = desc.focus_distance > 0.0f ? desc.focus_distance : glm::length(desc.target - desc.eye);
    return cam;
}

int add_material(Scene& scene, const Material& material, const std::string& name) {
    scene.materials.push_back(material);
    scene.material_names.push_back(name);
    return static_cast<int>(scene.materials.size() - 1);
}

float Bounds::radius() const { return 0.5f * glm::length(hi - lo); }

Bounds scene_bounds(const Scene& scene) {
    Bounds b{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    for (const glm::vec3& v : scene.vertices) {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    for (const FcSphere& sp : scene.spheres) {
        const glm::vec3 c(sp.center[0], sp.center[1], sp.center[2]);
        b.lo = glm::min(b.lo, c - glm::vec3(sp.radius));
        b.hi = glm::max(b.hi, c + glm::vec3(sp.radius));
    }
    for (const Instance& in : scene.instances) {
        const Bounds ib = transformed_bounds(scene.meshes[std::size_t(in.mesh)].vertices, in.object_to_world);
        if (ib.empty()) continue;
        b.lo = glm::min(b.lo, ib.lo);
        b.hi = glm::max(b.hi, ib.hi);
    }
    return b;
}

Bounds transformed_bounds(const std::vector<glm::vec3>& points, const glm::mat4& transform) {
    constexpr float big = std::numeric_limits<float>::max();
    Bounds box{glm::vec3(big), glm::vec3(-big)}, out = box;
    for (const glm::vec3& p : points) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    if (box.empty()) return out;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                               (k & 4) ? box.hi.z : box.lo.z);
        const glm::vec3 p(transform * glm::vec4(corner, 1.0f));
        out.lo = glm::min(out.lo, p);
        out.hi = glm::max(out.hi, p);
    }
    return out;
}

bool instance_transform_ok(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) return false;
    const double det = glm::determinant(glm::dmat3(glm::mat3(m)));
    return det != 0.0 && std::isfinite(det);
}

int add_shared_mesh(Scene& scene, SharedMesh mesh) {
    scene.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene.meshes.size() - 1);
}

void add_instance(Scene& scene, int mesh, const glm::mat4& object_to_world) {
    if (mesh < 0 || std::size_t(mesh) >= scene.meshes.size())
        throw Error(fmt::format("add_instance: mesh {} does not exist ({} shared meshes)", mesh, scene.meshes.size()));
    if (!instance_transform_ok(object_to_world))
        throw Error(
            fmt::format("add_instance: the transform of an instance of mesh '{}' is not an invertible "
                        "affine transform",
                        scene.meshes[std::size_t(mesh)].name));
    scene.instances.push_back(Instance{mesh, object_to_world});
}

void mark_triangle_materials(const Scene& scene, std::vector<bool>& used) {
    auto mark = [&](const std::vector<FcTriShading>& shading) {
        for (const FcTriShading& s : shading)
            if (s.material >= 0 && std::size_t(s.material) < used.size()) used[std::size_t(s.material)] = true;
    };
    mark(scene.shading);
    for (const SharedMesh& m : scene.meshes) mark(m.shading);
}

std::size_t Scene::stored_triangle_count() const {
    std::size_t n = shading.size();
    for (const SharedMesh& m : meshes) n += m.triangle_count();
    return n;
}

std::size_t Scene::placed_triangle_count() const {
    std::size_t n = shading.size();
    for (const Instance& in : instances) n += meshes[std::size_t(in.mesh)].triangle_count();
    return n;
}

namespace {

// Whether a broadside framing looks from +x: the model is clearly longer along z than along
// x (by a quarter; a room about as deep as wide, such as a Cornell box open towards +z,
// keeps the +z view its author meant).
bool broadside_from_x(const Scene& scene, Framing framing) {
    if (framing != Framing::Broadside) return false;
    const Bounds b = scene_bounds(scene);
    return !b.empty() && b.hi.z - b.lo.z > 1.25f * (b.hi.x - b.lo.x);
}

}  // namespace

std::string framing_note(const Scene& scene, Framing framing) {
    if (framing == Framing::Front) return "framed to fit the model, seen from +z (glTF's front)";
    return broadside_from_x(scene, framing) ? "framed to fit the model, seen from +x (its longer side)"
                                            : "framed to fit the model, seen from +z (its longer side)";
}

CameraDesc frame_camera(const Scene& scene, Framing framing) {
    constexpr float fov = 40.0f;
    CameraDesc cam;
    cam.fov_y_degrees = fov;
    if (scene.vertices.empty() && scene.spheres.empty() && scene.instances.empty()) return cam;
    const Bounds bounds = scene_bounds(scene);
    const glm::vec3 center = bounds.center();
    float radius = bounds.radius();
    if (!(radius > 0.0f)) radius = 1.0f;
    // The bounding sphere fits the vertical fov at this distance.
    const float distance = radius / std::sin(0.5f * glm::radians(fov));
    cam.target = center;
    const glm::vec3 view =
        broadside_from_x(scene, framing) ? glm::vec3(1.0f, 0.25f, 0.0f) : glm::vec3(0.0f, 0.25f, 1.0f);
    cam.eye = center + distance * glm::normalize(view);
    cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return cam;
}

}  // namespace facet
