// Shapes built on the host: triangles, parallelograms, icospheres and analytic spheres.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "host/scene/scene.hpp"
#include "host/util/vec3.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

// Unit normal, or +z for a degenerate direction (such triangles are never hit).
glm::vec3 safe_normalize(glm::vec3 v) { return unit_or(glm::dvec3(v), glm::vec3(0.0f, 0.0f, 1.0f)); }

using Tri = std::array<int, 3>;

// The icosahedron, faces counter-clockwise seen from outside.
void icosahedron(std::vector<glm::vec3>& verts, std::vector<Tri>& faces) {
    const float t = 0.5f * (1.0f + std::sqrt(5.0f));
    verts = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& v : verts) v = glm::normalize(v);
    faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

// Splits every triangle into four, the new vertices pushed onto the unit sphere.
void subdivide(std::vector<glm::vec3>& verts, std::vector<Tri>& faces) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        auto it = midpoints.find(key);
        if (it != midpoints.end()) return it->second;
        verts.push_back(glm::normalize(verts[static_cast<std::size_t>(a)] + verts[static_cast<std::size_t>(b)]));
        const int index = static_cast<int>(verts.size() - 1);
        midpoints.emplace(key, index);
        return index;
    };
    std::vector<Tri> out;
    out.reserve(faces.size() * 4);
    for (const Tri& f : faces) {
        const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
        out.push_back({f[0], ab, ca});
        out.push_back({f[1], bc, ab});
        out.push_back({f[2], ca, bc});
        out.push_back({ab, bc, ca});
    }
    faces = std::move(out);
}

}  // namespace

void add_triangle(Scene& scene, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 n0, glm::vec3 n1, glm::vec3 n2,
                  int material) {
    scene.vertices.push_back(p0);
    scene.vertices.push_back(p1);
    scene.vertices.push_back(p2);
    FcTriShading sh{};
    store(sh.n0, safe_normalize(n0));
    store(sh.n1, safe_normalize(n1));
    store(sh.n2, safe_normalize(n2));
    sh.material = material;
    sh.light = -1;
    scene.shading.push_back(sh);
}

void add_quad(Scene& scene, glm::vec3 corner, glm::vec3 e1, glm::vec3 e2, int material) {
    const glm::vec3 n = unit_or(wide_cross(e1, e2), glm::vec3(0.0f, 0.0f, 1.0f));
    add_triangle(scene, corner, corner + e1, corner + e1 + e2, n, n, n, material);
    add_triangle(scene, corner, corner + e1 + e2, corner + e2, n, n, n, material);
    // uv: e1 along u, e2 up the image (v = 0 at its top row)
    const std::size_t t = scene.shading.size() - 2;
    set_triangle_texcoords(scene, t, {0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f});
    set_triangle_texcoords(scene, t + 1, {0.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f});
}

void add_sphere(Scene& scene, glm::vec3 center, float radius, int subdivisions, int material, bool inward) {
    std::vector<glm::vec3> verts;
    std::vector<Tri> faces;
    icosahedron(verts, faces);
    for (int i = 0; i < subdivisions; ++i) subdivide(verts, faces);
    for (const Tri& f : faces) {
        glm::vec3 p0 = center + radius * verts[static_cast<std::size_t>(f[0])];
        glm::vec3 p1 = center + radius * verts[static_cast<std::size_t>(f[1])];
        glm::vec3 p2 = center + radius * verts[static_cast<std::size_t>(f[2])];
        if (inward) std::swap(p1, p2);
        const glm::vec3 n = triangle_normal(p0, p1, p2);
        add_triangle(scene, p0, p1, p2, n, n, n, material);
    }
}

void add_analytic_sphere(Scene& scene, glm::vec3 center, float radius, int material, bool inward) {
    FcSphere s{};
    store(s.center, center);
    s.radius = radius;
    s.material = material;
    s.light = -1;
    s.flags = inward ? FC_SPHERE_INWARD : 0;
    s.prim = static_cast<fc_int>(scene.spheres.size());
    scene.spheres.push_back(s);
}

}  // namespace facet
