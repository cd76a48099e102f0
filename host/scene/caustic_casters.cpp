#include "host/scene/caustic_casters.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "kernels/shared/render_layout.h"

namespace facet {
namespace {

struct Bound {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
    float lens = 0.0f;  // the relative index of a smooth glass ball, else 0
};

bool is_glass(const Scene& scene, int material) {
    return material >= 0 && std::size_t(material) < scene.materials.size() &&
           scene.materials[std::size_t(material)].specular_model == FC_SPECULAR_DIELECTRIC;
}

// The sphere about the box of the points' centre that holds them all (not the smallest, but
// within a factor of sqrt(3) of it), computed in double.
Bound bound_of(std::span<const glm::vec3> points) {
    glm::dvec3 lo(points[0]), hi(points[0]);
    for (const glm::vec3& v : points) {
        lo = glm::min(lo, glm::dvec3(v));
        hi = glm::max(hi, glm::dvec3(v));
    }
    const glm::dvec3 c = 0.5 * (lo + hi);
    double r2 = 0.0;
    for (const glm::vec3& v : points) {
        const glm::dvec3 e = glm::dvec3(v) - c;
        r2 = std::max(r2, glm::dot(e, e));
    }
    // a float radius at least the double one, so that every point stays inside
    return Bound{glm::vec3(c), std::nextafter(float(std::sqrt(r2)), INFINITY)};
}

// Runs of consecutive triangles of one dielectric material: their bounds.
void triangle_runs(const Scene& scene, std::span<const glm::vec3> vertices, std::span<const FcTriShading> shading,
                   std::vector<Bound>& out) {
    std::size_t i = 0;
    while (i < shading.size()) {
        const int material = shading[i].material;
        std::size_t end = i + 1;
        while (end < shading.size() && shading[end].material == material) ++end;
        if (is_glass(scene, material)) out.push_back(bound_of(vertices.subspan(3 * i, 3 * (end - i))));
        i = end;
    }
}

}  // namespace

std::vector<float> caustic_casters(const Scene& scene) {
    if (!(scene.settings.caustic_guide > 0.0f)) return {};
    // the receivers (caustic_guide_receiver): Lambertian materials, and rough microfacet ones
    // (the kernels tell which of these are plain bases)
    const bool receiver = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return (m.diffuse_model == FC_DIFFUSE_LAMBERT && m.specular_model == FC_SPECULAR_NONE) ||
               (m.specular_model == FC_SPECULAR_MICROFACET && std::max(m.alpha_x, m.alpha_y) >= FC_ALPHA_MIRROR);
    });
    if (!receiver) return {};
    std::vector<Bound> bounds;
    for (const FcSphere& s : scene.spheres) {
        if (!is_glass(scene, s.material)) continue;
        const Material& m = scene.materials[std::size_t(s.material)];
        const bool lens = !(s.flags & FC_SPHERE_INWARD) && m.ior > 1.0f + 1e-3f && !m.textures.any() &&
                          m.anisotropy == 0.0f && !(std::max(m.alpha_x, m.alpha_y) >= FC_ALPHA_MIRROR);
        bounds.push_back(Bound{glm::vec3(s.center[0], s.center[1], s.center[2]), s.radius, lens ? m.ior : 0.0f});
    }
    triangle_runs(scene, scene.vertices, scene.shading, bounds);
    for (const Instance& in : scene.instances) {
        const SharedMesh& mesh = scene.meshes[std::size_t(in.mesh)];
        std::vector<Bound> own;
        triangle_runs(scene, mesh.vertices, mesh.shading, own);
        const glm::mat4& m = in.object_to_world;
        // the placement's linear part stretches no length by more than its Frobenius norm
        const glm::vec3 c0(m[0]), c1(m[1]), c2(m[2]);
        const float stretch = std::sqrt(glm::dot(c0, c0) + glm::dot(c1, c1) + glm::dot(c2, c2));
        for (const Bound& b : own)
            bounds.push_back(Bound{glm::vec3(m * glm::vec4(b.centre, 1.0f)), b.radius * stretch * 1.0001f});
    }
    std::erase_if(bounds, [](const Bound& b) { return !(b.radius > 0.0f) || !std::isfinite(b.radius); });
    if (bounds.size() > FC_MAX_CASTERS) {
        std::stable_sort(bounds.begin(), bounds.end(),
                         [](const Bound& a, const Bound& b) { return a.radius > b.radius; });
        bounds.resize(FC_MAX_CASTERS);
    }
    std::vector<float> out;
    out.reserve(8 * bounds.size());
    for (const Bound& b : bounds)
        out.insert(out.end(), {b.centre.x, b.centre.y, b.centre.z, b.radius, b.lens, 0, 0, 0});
    return out;
}

}  // namespace facet
