// The light a bare model gets when its file brings none, and `--env`'s choices
// (host/readers/default_lighting.hpp): a closed cube read from an OBJ is rendered from
// the front (the key light's side) and from behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "host/bvh/bvh.hpp"
#include "host/error.hpp"
#include "host/readers/default_lighting.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

// A closed cube [-1, 1]^3, faces wound outward.
const char* kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

// The mean of the image's centre quarter (all of it on the cube's face towards the
// camera), seen from (0, 0, z_eye) towards the origin.
double face_brightness(Scene scene, float z_eye) {
    scene.camera.eye = glm::vec3(0.0f, 0.0f, z_eye);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.camera.fov_y_degrees = 40.0f;
    const int size = 32;
    scene.settings.width = size;
    scene.settings.height = size;
    scene.settings.max_depth = 4;
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, 32, 8);
    const std::vector<float> img = r.image();
    const std::size_t channels = img.size() / std::size_t(size * size);
    double sum = 0.0;
    int n = 0;
    for (int y = size / 4; y < 3 * size / 4; ++y)
        for (int x = size / 4; x < 3 * size / 4; ++x, ++n)
            for (int c = 0; c < 3; ++c)
                sum += double(img[(std::size_t(y) * size + std::size_t(x)) * channels + std::size_t(c)]);
    return sum / double(3 * n);
}

TEST(DefaultLighting, CubeReadsFromFrontAndBehind) {
    test::TempDir dir;
    const Scene scene = load_scene(dir.write("cube.obj", kCube));
    EXPECT_NE(scene.lighting_note.find("white environment"), std::string::npos) << scene.lighting_note;
    const double front = face_brightness(scene, 4.0f);
    const double behind = face_brightness(scene, -4.0f);
    EXPECT_GT(behind, 0.25) << "front " << front;
    EXPECT_LT(front / behind, 2.0) << "front " << front << ", behind " << behind;
}

TEST(DefaultLighting, EnvNoneLeavesTheBackDark) {
    test::TempDir dir;
    Scene scene = load_scene(dir.write("cube.obj", kCube));
    apply_environment_choice({"none", std::nullopt, std::nullopt}, scene);
    EXPECT_EQ(scene.environment_light, -1);
    EXPECT_NE(scene.lighting_note.find("none"), std::string::npos) << scene.lighting_note;
    EXPECT_LT(face_brightness(scene, -4.0f), 0.1) << "only the key light, in front";
}

TEST(DefaultLighting, EnvWhiteStrengthScalesTheBack) {
    test::TempDir dir;
    Scene scene = load_scene(dir.write("cube.obj", kCube));
    const double one = face_brightness(scene, -4.0f);
    apply_environment_choice({"white", 90.0f, 2.0f}, scene);
    const double two = face_brightness(scene, -4.0f);
    EXPECT_NEAR(two / one, 2.0 / double(kDefaultEnvironmentRadiance), 0.3) << one << " then " << two;
}

TEST(DefaultLighting, EmissiveOnlyFileIsNotedNotChanged) {
    test::TempDir dir;
    dir.write("glow.mtl", "newmtl glow\nKe 1 1 1\n");
    const Scene scene = load_scene(dir.write("glow.obj", std::string("mtllib glow.mtl\nusemtl glow\n") + kCube));
    EXPECT_EQ(scene.environment_light, -1);
    EXPECT_EQ(std::count(scene.material_names.begin(), scene.material_names.end(), "default_light"), 0);
    EXPECT_NE(scene.lighting_note.find("--env sky"), std::string::npos) << scene.lighting_note;
}

TEST(DefaultLighting, EnvRefusesOtherNames) {
    test::TempDir dir;
    Scene scene = load_scene(dir.write("cube.obj", kCube));
    EXPECT_THROW(apply_environment_choice({"skye", std::nullopt, std::nullopt}, scene), Error);
    EXPECT_THROW(apply_environment_choice({dir.path("missing.exr"), std::nullopt, std::nullopt}, scene), Error);
}

}  // namespace
}  // namespace facet
