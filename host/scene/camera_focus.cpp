#include "host/scene/camera_focus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "host/bvh/sah_builder.hpp"

namespace facet {
namespace {

constexpr float kNoHit = std::numeric_limits<float>::infinity();

// A ray o + t d with t > 0; d need not be unit length (t then counts multiples of d).
struct Ray {
    glm::vec3 o, d;
};

// Möller and Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection"; both sides.
float hit_triangle(const Ray& r, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, float t_max) {
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(r.d, e2);
    const float det = glm::dot(e1, p);
    if (!(std::fabs(det) > 0.0f)) return kNoHit;
    const float inv = 1.0f / det;
    const glm::vec3 s = r.o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return kNoHit;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(r.d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return kNoHit;
    const float t = glm::dot(e2, q) * inv;
    return t > 1e-6f * glm::length(r.d) && t < t_max ? t : kNoHit;
}

// The slab test: whether the ray meets the box before t_max.
bool hit_box(const Ray& r, const glm::vec3& inv_d, const float lo[3], const float hi[3], float t_max) {
    float t0 = 0.0f, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        float a = (lo[k] - r.o[k]) * inv_d[k], b = (hi[k] - r.o[k]) * inv_d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

// A binary SAH tree (host/bvh/sah_builder.hpp) over a triangle soup, for a few closest-hit
// queries on the host.
class TriangleTree {
public:
    explicit TriangleTree(const std::vector<glm::vec3>& vertices) : vertices_(vertices) {
        for (std::size_t i = 0; i + 2 < vertices.size(); i += 3) {
            bvh_detail::PrimRef r{};
            bool finite = true;
            for (int k = 0; k < 3; ++k) {
                const float a = vertices[i][k], b = vertices[i + 1][k], c = vertices[i + 2][k];
                finite = finite && std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
                r.lo[k] = std::min({a, b, c});
                r.hi[k] = std::max({a, b, c});
            }
            r.id = std::uint32_t(i / 3);
            if (finite) refs_.push_back(r);
        }
        if (!refs_.empty()) nodes_ = bvh_detail::build_sah(refs_, BvhOptions{}).nodes;
    }

    // The nearest t in (0, t_max) at which the ray meets a triangle, else kNoHit.
    float hit(const Ray& r, float t_max) const {
        if (nodes_.empty()) return kNoHit;
        const glm::vec3 inv_d = 1.0f / r.d;
        float best = kNoHit;
        std::vector<int> stack{0};
        while (!stack.empty()) {
            const bvh_detail::BinaryNode& n = nodes_[std::size_t(stack.back())];
            stack.pop_back();
            visit(r, inv_d, n.a_min, n.a_max, n.a_index, n.a_count, t_max, best, stack);
            visit(r, inv_d, n.b_min, n.b_max, n.b_index, n.b_count, t_max, best, stack);
        }
        return best;
    }

private:
    void visit(const Ray& r, const glm::vec3& inv_d, const float lo[3], const float hi[3], int index, int count,
               float t_max, float& best, std::vector<int>& stack) const {
        if (count == 0 && index == 0) return;  // an empty slot (index 0 is the root, never a child)
        if (!hit_box(r, inv_d, lo, hi, std::min(t_max, best))) return;
        if (count == 0) {
            stack.push_back(index);
            return;
        }
        for (int i = index; i < index + count; ++i) {
            const std::size_t t = refs_[std::size_t(i)].id;
            best = std::min(best, hit_triangle(r, vertices_[3 * t], vertices_[3 * t + 1], vertices_[3 * t + 2],
                                               std::min(t_max, best)));
        }
    }

    const std::vector<glm::vec3>& vertices_;
    std::vector<bvh_detail::PrimRef> refs_;
    std::vector<bvh_detail::BinaryNode> nodes_;
};

// The nearer root of |o + t d - c| = radius, if positive.
float hit_sphere(const Ray& r, const FcSphere& s) {
    const glm::vec3 c(s.center[0], s.center[1], s.center[2]);
    const glm::vec3 oc = r.o - c;
    const float a = glm::dot(r.d, r.d), b = glm::dot(oc, r.d), cc = glm::dot(oc, oc) - s.radius * s.radius;
    const float disc = b * b - a * cc;
    if (!(disc >= 0.0f)) return kNoHit;
    const float root = std::sqrt(disc);
    for (float t : {(-b - root) / a, (-b + root) / a})
        if (t > 0.0f) return t;
    return kNoHit;
}

}  // namespace

ViewDepths probe_view(const Scene& scene, const CameraDesc& camera, float aspect, int grid) {
    // The image plane at distance 1: forward + u right + v up, u, v in [-1, 1]. `forward`
    // is unit and orthogonal to right and up, so t along such a ray is its depth.
    const FcCamera cam = make_camera(camera, aspect);
    const glm::vec3 forward(cam.forward[0], cam.forward[1], cam.forward[2]);
    const glm::vec3 right(cam.right[0], cam.right[1], cam.right[2]), up(cam.up[0], cam.up[1], cam.up[2]);

    const TriangleTree world(scene.vertices);
    std::vector<TriangleTree> meshes;
    meshes.reserve(scene.meshes.size());
    for (const SharedMesh& m : scene.meshes) meshes.emplace_back(m.vertices);
    std::vector<glm::mat4> world_to_object;
    for (const Instance& in : scene.instances) world_to_object.push_back(glm::inverse(in.object_to_world));

    auto depth = [&](float u, float v) {
        const Ray r{camera.eye, forward + u * right + v * up};
        float t = world.hit(r, kNoHit);
        for (const FcSphere& s : scene.spheres) t = std::min(t, hit_sphere(r, s));
        for (std::size_t i = 0; i < scene.instances.size(); ++i) {
            const glm::mat4& m = world_to_object[i];
            const Ray local{glm::vec3(m * glm::vec4(r.o, 1.0f)), glm::vec3(m * glm::vec4(r.d, 0.0f))};
            t = std::min(t, meshes[std::size_t(scene.instances[i].mesh)].hit(local, t));
        }
        return t;
    };

    ViewDepths out;
    const float centre = depth(0.0f, 0.0f);
    if (centre < kNoHit) out.centre = centre;
    float nearest = centre;
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            const float u = grid > 1 ? 2.0f * float(i) / float(grid - 1) - 1.0f : 0.0f;
            const float v = grid > 1 ? 2.0f * float(j) / float(grid - 1) - 1.0f : 0.0f;
            nearest = std::min(nearest, depth(u, v));
        }
    if (nearest < kNoHit) out.nearest = nearest;
    return out;
}

void settle_focus(Scene& scene) {
    CameraDesc& c = scene.camera;
    if (c.projection != FC_PROJECTION_PERSPECTIVE || !(c.aperture > 0.0f)) return;
    // The central square of the image (aspect 1), so that the focus does not depend on the
    // image size: a render resumed at the film's size (--resume) focuses as the first did.
    const ViewDepths view = probe_view(scene, c, 1.0f);
    if (!view.nearest) return;  // nothing in view: no distance is better than another
    const float nearest = *view.nearest;
    if (c.focus_distance > 0.0f) {
        if (c.focus_distance < nearest)
            scene.warnings.push_back(fmt::format(
                "the focus distance {:g} is nearer than anything in view (the nearest surface is {:g} away): with "
                "a lens radius of {:g} the whole image is out of focus",
                c.focus_distance, nearest, c.aperture));
        return;
    }
    const float to_target = glm::length(c.target - c.eye);
    if (to_target >= nearest) return;
    c.focus_distance = view.centre ? *view.centre : nearest;
    scene.warnings.push_back(fmt::format(
        "the camera's target is {:g} from the eye, nearer than anything in view (the nearest surface is {:g} away): "
        "focusing at {:g}, {} (--focus-distance to choose)",
        to_target, nearest, c.focus_distance,
        view.centre ? "the surface at the image centre" : "the nearest surface in view"));
}

}  // namespace facet
