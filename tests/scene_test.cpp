// Scene.*: the project's scenes, host-made shapes, lights and cameras.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "host/readers/load_scene.hpp"
#include "host/scene/scene.hpp"
#include "tests/scene_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using test::centroid;
using test::face_normal;
using test::vec;

const std::string kScenes = test::scenes_dir();

TEST(Scene, CornellBoxLoads) {
    const Scene s = load_scene(kScenes + "/cornell_box.json");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    ASSERT_EQ(s.triangle_count(), 32u);  // 16 quads: 5 walls, the light, 2 blocks of 5
    ASSERT_EQ(s.vertices.size(), 96u);
    EXPECT_EQ(s.settings.width, 512);
    EXPECT_EQ(s.settings.height, 512);
    EXPECT_EQ(s.settings.spp, 64);
    EXPECT_EQ(s.settings.max_depth, 16);
    EXPECT_NEAR(s.camera.fov_y_degrees, 2.0 * std::atan(12.5 / 35.0) * 180.0 / M_PI, 1e-3);
    EXPECT_EQ(s.camera.eye, glm::vec3(278, 273, -800));

    // Two light triangles, facing down (edges and shading normals agree).
    ASSERT_EQ(s.lights.size(), 2u);
    ASSERT_EQ(s.light_cdf.size(), 3u);
    EXPECT_FLOAT_EQ(s.light_cdf.back(), 1.0f);
    for (const FcLight& l : s.lights) {
        const std::size_t t = static_cast<std::size_t>(l.prim);
        EXPECT_LT(glm::normalize(glm::cross(vec(l.e1), vec(l.e2))).y, -0.999f);
        EXPECT_LT(face_normal(s, t).y, -0.999f);
        EXPECT_LT(vec(s.shading[t].n0).y, -0.999f);
        EXPECT_NEAR(centroid(s, t).y, 548.7f, 1e-3f);
        EXPECT_NEAR(l.pick_pdf, 0.5f, 1e-5f);
    }

    // Every surface faces where light comes from: the shell inward, block tops up,
    // block sides away from their block.
    const glm::vec3 box_center(278.0f, 274.4f, 279.6f);
    const glm::vec3 short_center(185.5f, 82.5f, 169.0f), tall_center(368.5f, 165.0f, 351.25f);
    for (std::size_t t = 0; t < s.triangle_count(); ++t) {
        const glm::vec3 c = centroid(s, t), n = face_normal(s, t);
        const float dist_short = glm::length(glm::vec2(c.x, c.z) - glm::vec2(short_center.x, short_center.z));
        const float dist_tall = glm::length(glm::vec2(c.x, c.z) - glm::vec2(tall_center.x, tall_center.z));
        if (c.y > 1.0f && c.y < 547.0f && (dist_short < 120.0f || dist_tall < 120.0f)) {
            const glm::vec3 block = dist_short < dist_tall ? short_center : tall_center;
            if (std::abs(c.y - 165.0f) < 0.1f || std::abs(c.y - 330.0f) < 0.1f) {
                EXPECT_GT(n.y, 0.999f) << "block top " << t;
            } else {
                EXPECT_GT(glm::dot(n, glm::vec3(c.x - block.x, 0.0f, c.z - block.z)), 0.0f) << t;
            }
        } else {
            EXPECT_GT(glm::dot(n, box_center - c), 0.0f) << "shell triangle " << t;
        }
        // Flat quads: shading normals within a few degrees of the face normal.
        EXPECT_GT(glm::dot(vec(s.shading[t].n0), n), 0.99f) << t;
    }
}

TEST(Scene, CornellObjHasItsOwnLight) {
    const Scene s = load_scene(kScenes + "/cornell_box.obj");
    EXPECT_EQ(s.triangle_count(), 32u);  // no default light added
    EXPECT_EQ(s.lights.size(), 2u);
}

TEST(Scene, FurnaceSphereFacesInward) {
    const Scene s = load_scene(kScenes + "/furnace_sphere.json");
    ASSERT_EQ(s.spheres.size(), 1u);  // analytic
    EXPECT_EQ(s.triangle_count(), 0u);
    EXPECT_EQ(s.spheres[0].flags, FC_SPHERE_INWARD);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, FC_LIGHT_SPHERE);
    EXPECT_EQ(s.lights[0].e1[1], -1.0f) << "emits inward";
}

TEST(Scene, SphereShape) {
    Scene s;
    add_sphere(s, glm::vec3(1, 2, 3), 2.0f, 2, 0, false);
    ASSERT_EQ(s.triangle_count(), 20u * 16u);
    for (const glm::vec3& v : s.vertices) EXPECT_NEAR(glm::length(v - glm::vec3(1, 2, 3)), 2.0f, 1e-5f);
    for (std::size_t t = 0; t < s.triangle_count(); ++t) {
        const glm::vec3 out = centroid(s, t) - glm::vec3(1, 2, 3);
        EXPECT_GT(glm::dot(face_normal(s, t), out), 0.0f);
        EXPECT_NEAR(glm::length(vec(s.shading[t].n2) - face_normal(s, t)), 0.0f, 1e-4f);  // flat
        EXPECT_EQ(s.shading[t].light, -1);
    }
    Scene in;
    add_sphere(in, glm::vec3(0), 1.0f, 0, 0, true);
    ASSERT_EQ(in.triangle_count(), 20u);
    for (std::size_t t = 0; t < 20; ++t) EXPECT_LT(glm::dot(face_normal(in, t), centroid(in, t)), 0.0f);
}

TEST(Scene, QuadShape) {
    Scene s;
    add_quad(s, glm::vec3(0), glm::vec3(2, 0, 0), glm::vec3(0, 0, -3), 0);
    ASSERT_EQ(s.triangle_count(), 2u);
    for (std::size_t t = 0; t < 2; ++t) {
        EXPECT_NEAR(face_normal(s, t).y, 1.0f, 1e-6f);  // cross(x, -z) = +y
        EXPECT_NEAR(vec(s.shading[t].n0).y, 1.0f, 1e-6f);
    }
}

TEST(Scene, LightPickPdfsFollowPower) {
    Scene s;
    Material dim = default_material(), bright = default_material(), twin = default_material();
    for (int c = 0; c < 3; ++c) {
        dim.emission[c] = 1.0f;
        bright.emission[c] = 3.0f;
        twin.emission[c] = 1.0f;
    }
    twin.two_sided_emission = true;
    const int m_plain = add_material(s, default_material(), "plain");
    const int m_dim = add_material(s, dim, "dim");
    const int m_bright = add_material(s, bright, "bright");
    const int m_twin = add_material(s, twin, "twin");
    add_quad(s, glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), m_plain);
    add_quad(s, glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), m_dim);     // area 0.5 each
    add_quad(s, glm::vec3(0), glm::vec3(2, 0, 0), glm::vec3(0, 1, 0), m_bright);  // area 1 each
    add_quad(s, glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), m_twin);
    build_lights(s);
    ASSERT_EQ(s.lights.size(), 6u);
    ASSERT_EQ(s.light_cdf.size(), 7u);
    // Powers: dim 0.5, bright 3, twin 1 (per triangle); total 2 * 4.5 = 9.
    const float expected[6] = {0.5f / 9, 0.5f / 9, 3.0f / 9, 3.0f / 9, 1.0f / 9, 1.0f / 9};
    float sum = 0.0f;
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_NEAR(s.lights[i].pick_pdf, expected[i], 1e-6f) << i;
        EXPECT_NEAR(s.light_cdf[i + 1] - s.light_cdf[i], expected[i], 1e-6f);
        EXPECT_EQ(s.shading[static_cast<std::size_t>(s.lights[i].prim)].light, static_cast<int>(i));
        sum += s.lights[i].pick_pdf;
    }
    EXPECT_NEAR(sum, 1.0f, 1e-6f);
    EXPECT_EQ(s.light_cdf.front(), 0.0f);
    EXPECT_EQ(s.light_cdf.back(), 1.0f);
    EXPECT_EQ(s.shading[0].light, -1);
    EXPECT_EQ(s.shading[1].light, -1);
    EXPECT_NEAR(s.lights[2].area, 1.0f, 1e-6f);

    Scene dark;
    add_quad(dark, glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), add_material(dark, default_material(), "d"));
    build_lights(dark);
    EXPECT_TRUE(dark.lights.empty());
    EXPECT_EQ(dark.light_cdf, std::vector<float>{0.0f});
}

TEST(Scene, LightEdgesFaceTheShadingNormal) {
    Scene s;
    Material m = default_material();
    m.emission[0] = 1.0f;
    const int mat = add_material(s, m, "e");
    // Wound clockwise seen from +z, but shading normals say +z.
    add_triangle(s, glm::vec3(0), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1),
                 glm::vec3(0, 0, 1), mat);
    build_lights(s);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_GT(glm::cross(vec(s.lights[0].e1), vec(s.lights[0].e2)).z, 0.0f);
    EXPECT_EQ(vec(s.lights[0].p0), glm::vec3(0));
}

TEST(Scene, MakeCamera) {
    CameraDesc d;
    d.eye = glm::vec3(0, 0, 5);
    d.target = glm::vec3(0);
    d.fov_y_degrees = 90.0f;
    const FcCamera c = make_camera(d, 2.0f);
    EXPECT_EQ(c.projection, FC_PROJECTION_PERSPECTIVE);
    EXPECT_NEAR(vec(c.forward).z, -1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(vec(c.up)), 1.0f, 1e-5f);  // tan(45 deg)
    EXPECT_NEAR(vec(c.up).y, 1.0f, 1e-5f);
    EXPECT_NEAR(vec(c.right).x, 2.0f, 1e-5f);  // aspect 2, +x to the right
    d.projection = FC_PROJECTION_ORTHOGRAPHIC;
    d.ortho_height = 4.0f;
    const FcCamera o = make_camera(d, 1.5f);
    EXPECT_NEAR(vec(o.up).y, 2.0f, 1e-5f);
    EXPECT_NEAR(vec(o.right).x, 3.0f, 1e-5f);
}

TEST(Scene, ObjWithoutEmittersGetsDefaultLightAndCamera) {
    test::TempDir dir;
    const std::string obj = dir.write("tri.obj", "v -1 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n");
    const Scene s = load_scene(obj);
    EXPECT_EQ(s.triangle_count(), 3u);  // the mesh and the two-sided light quad
    EXPECT_EQ(s.lights.size(), 3u);     // the quad's two triangles and the white environment
    EXPECT_TRUE(s.materials.back().two_sided_emission);
    EXPECT_EQ(s.camera.target, glm::vec3(0, 1, 0));
    EXPECT_GT(s.camera.eye.z, 2.0f);
    EXPECT_GT(s.camera.eye.y, 1.0f);
    // The light points at the mesh.
    EXPECT_LT(glm::dot(face_normal(s, 1), centroid(s, 1) - glm::vec3(0, 1, 0)), 0.0f);
}

}  // namespace
}  // namespace facet
