#include "host/scene/scene.hpp"

#include "host/scene/material.hpp"
#include "host/util/vec3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace facet {

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
    return b;
}

CameraDesc frame_camera(const Scene& scene) {
    constexpr float fov = 40.0f;
    CameraDesc cam;
    cam.fov_y_degrees = fov;
    if (scene.vertices.empty() && scene.spheres.empty()) return cam;
    const Bounds bounds = scene_bounds(scene);
    const glm::vec3 center = bounds.center();
    float radius = bounds.radius();
    if (!(radius > 0.0f)) radius = 1.0f;
    // The bounding sphere fits the vertical fov at this distance.
    const float distance = radius / std::sin(0.5f * glm::radians(fov));
    cam.target = center;
    cam.eye = center + distance * glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return cam;
}

}  // namespace facet
