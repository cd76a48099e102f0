#include "host/scene/scene.hpp"

#include "host/scene/material.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace facet {

FcMaterial default_material() {
    FcMaterial m = make_material("lambert");
    for (int c = 0; c < 3; ++c) m.diffuse[c] = 0.8f;
    return m;
}

static void store(float out[3], glm::vec3 v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
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
    return cam;
}

int add_material(Scene& scene, const FcMaterial& material, const std::string& name) {
    scene.materials.push_back(material);
    scene.material_names.push_back(name);
    return static_cast<int>(scene.materials.size() - 1);
}

CameraDesc frame_camera(const Scene& scene) {
    constexpr float fov = 40.0f;
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& v : scene.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    CameraDesc cam;
    cam.fov_y_degrees = fov;
    if (scene.vertices.empty()) return cam;
    const glm::vec3 center = 0.5f * (lo + hi);
    float radius = 0.5f * glm::length(hi - lo);
    if (!(radius > 0.0f)) radius = 1.0f;
    // The bounding sphere fits the vertical fov at this distance.
    const float distance = radius / std::sin(0.5f * glm::radians(fov));
    cam.target = center;
    cam.eye = center + distance * glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return cam;
}

}  // namespace facet
