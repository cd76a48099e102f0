// Helpers for the Scene.* tests: a temporary directory to write small scene files
// into, and expectations on facet::Error messages.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "host/error.hpp"
#include "host/scene/scene.hpp"
#include "tests/temp_dir.hpp"

namespace facet::test {

// A JSON "shapes" entry of one unit quad, and a scene file in `d` with `body` as its members.
inline const std::string kQuad =
    R"("shapes": [{"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0]}])";

inline std::string scene(const TempDir& d, const std::string& name, const std::string& body) {
    return d.write(name, "{\n" + body + "\n}\n");
}

// A 20 x 20 quad of `material` at y = 0 seen from above by an orthographic camera
// covering [-2, 2]^2 at n x n pixels, direct light only (max_depth 1): pixel (i, j) sees
// the point x = -2 + 4 (i + 0.5) / n, z likewise.
inline void add_plane_seen_from_above(Scene& scene, int material, int n) {
    add_quad(scene, glm::vec3(-10, 0, 10), glm::vec3(20, 0, 0), glm::vec3(0, 0, -20), material);
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.eye = glm::vec3(0, 5, 0);
    scene.camera.target = glm::vec3(0, 0, 0);
    scene.camera.up = glm::vec3(0, 0, -1);
    scene.camera.ortho_height = 4.0f;
    scene.settings.width = scene.settings.height = n;
    scene.settings.max_depth = 1;
}

// Runs `f`, expecting a facet::Error whose message contains every one of `parts`.
template <typename F>
void expect_error(F f, std::initializer_list<std::string> parts) {
    try {
        f();
        ADD_FAILURE() << "no facet::Error thrown";
    } catch (const Error& e) {
        const std::string msg = e.what();
        for (const std::string& p : parts) {
            EXPECT_NE(msg.find(p), std::string::npos) << "message: " << msg << "\nmissing: " << p;
        }
    }
}

inline glm::vec3 vec(const float v[3]) { return glm::vec3(v[0], v[1], v[2]); }

inline glm::vec3 face_normal(const Scene& s, std::size_t t) {
    const glm::vec3* v = &s.vertices[3 * t];
    return glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
}

inline glm::vec3 centroid(const Scene& s, std::size_t t) {
    const glm::vec3* v = &s.vertices[3 * t];
    return (v[0] + v[1] + v[2]) / 3.0f;
}

inline bool contains(const std::vector<std::string>& list, const std::string& part) {
    for (const std::string& s : list) {
        if (s.find(part) != std::string::npos) return true;
    }
    return false;
}

}  // namespace facet::test
