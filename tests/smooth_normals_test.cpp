// `--smooth-normals [ANGLE]` (host/scene/smooth_normals.hpp): crease-angle smoothing of
// shading normals on meshes whose right answer is known: a sphere's normals are radial, a
// cube's edges stay sharp below 90 degrees, a mesh wound against its normals keeps its side.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "host/scene/scene.hpp"
#include "host/scene/smooth_normals.hpp"

namespace facet {
namespace {

glm::vec3 corner(const FcTriShading& s, int c) {
    const float* n = c == 0 ? s.n0 : c == 1 ? s.n1 : s.n2;
    return glm::vec3(n[0], n[1], n[2]);
}

double degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)));
}

// The largest angle between a corner's shading normal and the radial direction.
double worst_radial_error(const Scene& scene) {
    double worst = 0.0;
    for (std::size_t t = 0; t < scene.shading.size(); ++t)
        for (int c = 0; c < 3; ++c)
            worst =
                std::max(worst, degrees_between(corner(scene.shading[t], c), scene.vertices[3 * t + std::size_t(c)]));
    return worst;
}

// A flat-shaded icosphere (faces about 10 degrees apart) gets radial normals: each
// corner's normal is within a degree of its position's direction, where the face normals
// it had were up to ~7 degrees off.
TEST(SmoothNormals, SphereBecomesRadial) {
    Scene scene;
    scene.materials.push_back(default_material());
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 2, 0, false);
    for (FcTriShading& s : scene.shading) {  // flat, as an OBJ without normals reads
        const std::size_t t = std::size_t(&s - scene.shading.data());
        const glm::vec3 f = glm::normalize(glm::cross(scene.vertices[3 * t + 1] - scene.vertices[3 * t],
                                                      scene.vertices[3 * t + 2] - scene.vertices[3 * t]));
        for (float* n : {s.n0, s.n1, s.n2}) n[0] = f.x, n[1] = f.y, n[2] = f.z;
    }
    EXPECT_GT(worst_radial_error(scene), 5.0);
    const SmoothTally tally = smooth_normals(scene, 30.0f);
    EXPECT_EQ(tally.triangles, scene.shading.size());
    EXPECT_EQ(tally.smooth, 3 * scene.shading.size());
    EXPECT_LT(worst_radial_error(scene), 1.0);
    ASSERT_FALSE(scene.normal_sources.empty());
    EXPECT_NE(scene.normal_sources.back().find("--smooth-normals 30"), std::string::npos);
}

// A cube's faces meet at 90 degrees: under 90 every corner keeps its face's normal (the
// edges stay sharp); above it the corners are averaged across the three faces.
TEST(SmoothNormals, CreaseAngleKeepsCubeEdges) {
    Scene scene;
    scene.materials.push_back(default_material());
    const glm::vec3 e[3] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    for (int a = 0; a < 3; ++a) {  // six faces of [-1, 1]^3, wound outward
        const glm::vec3 u = e[(a + 1) % 3], v = e[(a + 2) % 3], w = e[a];
        const glm::vec3 lo(-1.0f);
        add_quad(scene, lo, v, u, 0);      // the face at -w, facing -w
        add_quad(scene, lo + w, u, v, 0);  // the face at +w, facing +w
    }
    Scene sharp = scene;
    const SmoothTally kept = smooth_normals(sharp, 60.0f);
    EXPECT_EQ(kept.smooth, 24u);  // the corners on a face's diagonal, shared by its two coplanar triangles
    EXPECT_EQ(kept.sharp, 12u);
    for (std::size_t t = 0; t < sharp.shading.size(); ++t)
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(degrees_between(corner(sharp.shading[t], c), corner(scene.shading[t], c)), 1e-3);
    const SmoothTally rounded = smooth_normals(scene, 120.0f);
    EXPECT_EQ(rounded.sharp, 0u);
    for (std::size_t t = 0; t < scene.shading.size(); ++t)
        for (int c = 0; c < 3; ++c) {  // every cube corner's normal points along its diagonal
            const glm::vec3 p = scene.vertices[3 * t + std::size_t(c)];
            EXPECT_LT(degrees_between(corner(scene.shading[t], c), p), 1e-3) << "triangle " << t << " corner " << c;
        }
}

// A triangle pair wound one way with normals pointing the other way (a file whose
// winding disagrees with its normals) keeps the side of its normals; 0 degrees leaves
// every corner with its own face's normal.
TEST(SmoothNormals, KeepsTheSideTheFileMeant) {
    Scene scene;
    scene.materials.push_back(default_material());
    const glm::vec3 down(0.0f, 0.0f, -1.0f);
    add_triangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, down, down, down, 0);  // wound towards +z
    add_triangle(scene, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, down, down, down, 0);
    const SmoothTally tally = smooth_normals(scene, 0.0f);
    EXPECT_EQ(tally.triangles, 2u);
    for (const FcTriShading& s : scene.shading)
        for (int c = 0; c < 3; ++c) EXPECT_LT(degrees_between(corner(s, c), down), 1e-3);
}

}  // namespace
}  // namespace facet
