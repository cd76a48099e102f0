// Scenes at the edge of the documented coordinate range (docs/scene-format.md: vertices
// within +-1e18). Cross products of edges above ~4e9 have a squared length beyond the
// float range: normals, light areas and the ray/triangle test must still be right.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

int emitter(Scene& scene, float radiance) {
    Material m = default_material();
    m.diffuse = glm::vec3(0.0f);
    m.emission = glm::vec3(radiance);
    return add_material(scene, m, "light");
}

TEST(LargeScene, EmitterWithHugeEdgesIsKeptWithItsNormal) {
    for (float edge : {1.0f, 1e10f, 1e18f}) {
        Scene scene;
        // cross(e1, e2) = -z: the +z fallback of an overflowed normal would show.
        add_quad(scene, glm::vec3(0.0f), glm::vec3(0.0f, edge, 0.0f), glm::vec3(edge, 0.0f, 0.0f),
                 emitter(scene, 1.0f));
        build_lights(scene);
        ASSERT_EQ(scene.lights.size(), 2u) << "edge " << edge;
        for (const FcLight& l : scene.lights) {
            EXPECT_NEAR(double(l.area) / (0.5 * double(edge) * double(edge)), 1.0, 1e-6) << "edge " << edge;
            EXPECT_NEAR(double(l.pick_pdf), 0.5, 1e-6);
        }
        for (const FcTriShading& sh : scene.shading) {
            EXPECT_EQ(sh.n0[2], -1.0f) << "edge " << edge;
            EXPECT_EQ(sh.n1[2], -1.0f) << "edge " << edge;
            EXPECT_EQ(sh.n2[2], -1.0f) << "edge " << edge;
        }
    }
}

// A white Lambertian wall (normal +x) lit from above by a one-sided emitter facing down,
// seen by a camera on the +x axis; every length scaled by s. Radiance does not depend
// on the scale (areas and squared distances scale alike), so the images must agree.
std::vector<float> lit_wall(float s) {
    Scene scene;
    Material wall = default_material();
    wall.diffuse = glm::vec3(0.8f);
    const int w = add_material(scene, wall, "wall");
    add_quad(scene, s * glm::vec3(0.0f, -1.0f, -1.0f), s * glm::vec3(0.0f, 2.0f, 0.0f), s * glm::vec3(0.0f, 0.0f, 2.0f),
             w);
    // The emitter faces down: cross(e1, e2) = cross(+x, +z) = -y.
    add_quad(scene, s * glm::vec3(0.0f, 2.0f, -1.0f), s * glm::vec3(2.0f, 0.0f, 0.0f), s * glm::vec3(0.0f, 0.0f, 2.0f),
             emitter(scene, 5.0f));
    build_lights(scene);
    scene.camera.eye = s * glm::vec3(3.0f, 0.0f, 0.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fov_y_degrees = 30.0f;
    scene.settings.width = scene.settings.height = 16;
    scene.settings.max_depth = 2;
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    r.render(16);
    return r.image();
}

TEST(LargeScene, RenderIsScaleInvariantUpToTheDocumentedRange) {
    const std::vector<float> ref = lit_wall(1.0f);
    double ref_mean = 0.0;
    for (float v : ref) ref_mean += double(v);
    ref_mean /= double(ref.size());
    ASSERT_GT(ref_mean, 0.05);
    for (float s : {1e5f, 1e10f, 3e17f}) {
        const std::vector<float> img = lit_wall(s);
        ASSERT_EQ(img.size(), ref.size());
        double mean = 0.0;
        for (float v : img) {
            ASSERT_TRUE(std::isfinite(v)) << "scale " << s;
            mean += double(v);
        }
        mean /= double(img.size());
        EXPECT_NEAR(mean / ref_mean, 1.0, 0.05) << "scale " << s << ": mean " << mean << ", at scale 1 " << ref_mean;
    }
}

}  // namespace
}  // namespace facet
