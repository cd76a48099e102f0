// host/scene/camera_focus: the depths a camera sees, found on the host, and the focus
// distance chosen when the target is nearer than anything in view.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/camera_focus.hpp"

namespace facet {
namespace {

// A 2x2 quad in the plane z = z0, facing +z, centred on the axis.
void add_wall(Scene& scene, float z0) {
    add_quad(scene, glm::vec3(-1.0f, -1.0f, z0), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), 0);
}

Scene scene_with_camera(glm::vec3 eye, glm::vec3 target) {
    Scene scene;
    scene.materials.push_back(default_material());
    scene.material_names.push_back("grey");
    scene.camera.eye = eye;
    scene.camera.target = target;
    return scene;
}

TEST(CameraFocus, DepthsAlongTheViewDirection) {
    // A wall 4 ahead and, off-centre, a nearer small one 2 ahead: the centre sees the far
    // wall, the grid finds the near one; depths, not ray lengths.
    Scene scene = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 0.0f));
    add_wall(scene, 1.0f);
    add_quad(scene, glm::vec3(0.3f, 0.3f, 3.0f), glm::vec3(0.2f, 0.0f, 0.0f), glm::vec3(0.0f, 0.2f, 0.0f), 0);
    const ViewDepths d = probe_view(scene, scene.camera, 1.0f, 33);
    ASSERT_TRUE(d.centre.has_value());
    ASSERT_TRUE(d.nearest.has_value());
    EXPECT_NEAR(*d.centre, 4.0f, 1e-4f);
    EXPECT_NEAR(*d.nearest, 2.0f, 1e-4f);
}

TEST(CameraFocus, SpheresAndInstancesAreSeen) {
    Scene scene = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 0.0f));
    add_analytic_sphere(scene, glm::vec3(0.0f), 1.0f, 0, false);
    EXPECT_NEAR(probe_view(scene, scene.camera, 1.0f).centre.value_or(0.0f), 4.0f, 1e-4f);
    // A wall stored at z = 0 in its mesh, placed at z = 3 by its instance: 2 ahead.
    SharedMesh wall;
    for (glm::vec3 p : {glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(1, 1, 0), glm::vec3(-1, -1, 0),
                        glm::vec3(1, 1, 0), glm::vec3(-1, 1, 0)})
        wall.vertices.push_back(p);
    wall.shading.resize(2);
    scene.meshes.push_back(wall);
    scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 3.0f))});
    EXPECT_NEAR(probe_view(scene, scene.camera, 1.0f).centre.value_or(0.0f), 2.0f, 1e-4f);
}

TEST(CameraFocus, TargetNearerThanTheSceneFocusesAtTheCentre) {
    // The Cornell box's trap: the target a step ahead of the eye.
    Scene scene = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 4.999f));
    add_wall(scene, 0.0f);
    scene.camera.aperture = 0.1f;
    settle_focus(scene);
    EXPECT_NEAR(scene.camera.focus_distance, 5.0f, 1e-4f);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("focusing at 5, the surface at the image centre"), std::string::npos)
        << scene.warnings[0];
}

TEST(CameraFocus, GivenDistanceNearerThanTheSceneIsWarnedAndKept) {
    Scene scene = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 0.0f));
    add_wall(scene, 0.0f);
    scene.camera.aperture = 0.1f;
    scene.camera.focus_distance = 1.0f;
    settle_focus(scene);
    EXPECT_EQ(scene.camera.focus_distance, 1.0f);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("focus distance 1 is nearer than anything in view"), std::string::npos);
}

TEST(CameraFocus, SaneFocusPinholeAndEmptyViewsAreLeftAlone) {
    Scene scene = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 0.0f));
    add_wall(scene, 0.0f);
    scene.camera.aperture = 0.1f;
    settle_focus(scene);  // the target lies on the wall
    EXPECT_EQ(scene.camera.focus_distance, 0.0f);
    scene.camera.aperture = 0.0f;  // a pinhole: no focus at all
    scene.camera.target = glm::vec3(0.0f, 0.0f, 4.999f);
    settle_focus(scene);
    EXPECT_EQ(scene.camera.focus_distance, 0.0f);
    Scene empty = scene_with_camera(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 4.999f));
    empty.camera.aperture = 0.1f;
    settle_focus(empty);
    EXPECT_EQ(empty.camera.focus_distance, 0.0f);
    EXPECT_TRUE(scene.warnings.empty());
    EXPECT_TRUE(empty.warnings.empty());
}

}  // namespace
}  // namespace facet
