// The camera and key light a bare model gets (host/scene/scene.hpp frame_camera,
// host/readers/default_lighting.hpp): a format with no front is seen from its longer side,
// glTF from +z (its front), and the key light stands on the camera's side.
#include <gtest/gtest.h>

#include <string>

#include <glm/geometric.hpp>

#include "host/readers/load_scene.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

// A box [-x, x] x [-1, 1] x [-z, z] as an OBJ.
std::string box_obj(float x, float z) {
    std::string s;
    for (int i = 0; i < 8; ++i)
        s += "v " + std::to_string(i & 1 ? x : -x) + (i & 2 ? " 1 " : " -1 ") + std::to_string(i & 4 ? z : -z) + "\n";
    return s + "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
}

// The unit horizontal direction from the target to the eye.
glm::vec3 view_side(const Scene& scene) {
    glm::vec3 d = scene.camera.eye - scene.camera.target;
    d.y = 0.0f;
    return glm::normalize(d);
}

// The centre of the key light (the triangles of material "default_light").
glm::vec3 key_light_centre(const Scene& scene) {
    glm::vec3 sum(0.0f);
    int n = 0;
    for (std::size_t t = 0; t < scene.shading.size(); ++t)
        if (scene.material_names[std::size_t(scene.shading[t].material)] == "default_light")
            for (int c = 0; c < 3; ++c, ++n) sum += scene.vertices[3 * t + std::size_t(c)];
    return n > 0 ? sum / float(n) : sum;
}

// A model longer along z than x (spot.obj's cow) is seen from +x, its side; the key light
// follows the camera.
TEST(Framing, LongAlongZIsSeenFromTheSide) {
    test::TempDir d;
    const Scene scene = load_scene(d.write("long_z.obj", box_obj(0.5f, 3.0f)));
    EXPECT_GT(view_side(scene).x, 0.99f);
    EXPECT_NE(scene.camera_note.find("seen from +x"), std::string::npos) << scene.camera_note;
    EXPECT_GT(key_light_centre(scene).x, 1.0f);
    EXPECT_NEAR(key_light_centre(scene).z, 0.0f, 1e-3f);
}

// A model longer along x keeps the view from +z, with the key light on +z.
TEST(Framing, LongAlongXIsSeenFromFront) {
    test::TempDir d;
    const Scene scene = load_scene(d.write("long_x.obj", box_obj(3.0f, 0.5f)));
    EXPECT_GT(view_side(scene).z, 0.99f);
    EXPECT_NE(scene.camera_note.find("seen from +z"), std::string::npos) << scene.camera_note;
    EXPECT_GT(key_light_centre(scene).z, 1.0f);
}

// A box about as deep as wide (McGuire's Cornell boxes: 2.02 wide, 2.03 deep, open towards
// +z) keeps the +z view: from +x the camera saw a closed wall and a black image.
TEST(Framing, RoomAboutAsDeepAsWideKeepsTheFront) {
    test::TempDir d;
    const Scene scene = load_scene(d.write("room.obj", box_obj(1.01f, 1.015f)));
    EXPECT_GT(view_side(scene).z, 0.99f);
}

}  // namespace
}  // namespace facet
