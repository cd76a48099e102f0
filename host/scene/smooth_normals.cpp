// Crease-angle smoothing of shading normals (smooth_normals.hpp).
#include "host/scene/smooth_normals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/scene/scene.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

// Above this many corners at one position, the corners are compared with their group's
// mean normal instead of with each other (the pairwise test is quadratic; the apex of a
// finely tessellated cone or a pole of a UV sphere can gather thousands).
constexpr std::size_t kPairwiseLimit = 2048;

using PositionKey = std::array<std::uint32_t, 3>;

PositionKey position_key(glm::vec3 p) {
    PositionKey k{};
    for (int c = 0; c < 3; ++c) {
        const float x = p[c] + 0.0f;  // -0 and +0 are one position
        std::memcpy(&k[std::size_t(c)], &x, sizeof x);
    }
    return k;
}

float* corner_normal(FcTriShading& s, std::size_t corner) { return corner == 0 ? s.n0 : corner == 1 ? s.n1 : s.n2; }

// The interior angle of triangle `tri` at its corner `corner` (radians).
double corner_angle(const std::vector<glm::vec3>& v, std::size_t tri, std::size_t corner) {
    const glm::dvec3 p(v[3 * tri + corner]);
    const glm::dvec3 a = glm::dvec3(v[3 * tri + (corner + 1) % 3]) - p;
    const glm::dvec3 b = glm::dvec3(v[3 * tri + (corner + 2) % 3]) - p;
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The triangles of one list (3 vertices and 1 shading record each), smoothed in place.
void smooth_list(const std::vector<glm::vec3>& v, std::vector<FcTriShading>& shading, double cos_limit,
                 SmoothTally& tally) {
    const std::size_t n = shading.size();
    std::vector<glm::dvec3> face(n);
    std::vector<std::size_t> corners;  // 3 * triangle + corner, of usable triangles
    corners.reserve(3 * n);
    for (std::size_t t = 0; t < n; ++t) {
        const glm::dvec3 c = wide_cross(v[3 * t + 1] - v[3 * t], v[3 * t + 2] - v[3 * t]);
        const double len = glm::length(c);
        if (!(len > 0.0) || !std::isfinite(len)) continue;  // keeps its normals
        face[t] = c / len;
        glm::dvec3 old(0.0);
        for (std::size_t k = 0; k < 3; ++k) {
            const float* o = corner_normal(shading[t], k);
            old += glm::dvec3(o[0], o[1], o[2]);
        }
        if (glm::dot(old, face[t]) < 0.0) face[t] = -face[t];
        for (std::size_t k = 0; k < 3; ++k) corners.push_back(3 * t + k);
    }
    std::vector<PositionKey> keys(3 * n);
    for (std::size_t c : corners) keys[c] = position_key(v[c]);
    std::sort(corners.begin(), corners.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    std::vector<double> weight(3 * n);
    for (std::size_t c : corners) weight[c] = corner_angle(v, c / 3, c % 3);

    auto write = [&](std::size_t c, glm::dvec3 sum, bool shared) {
        const glm::dvec3 own = face[c / 3];
        const glm::vec3 nrm = glm::dot(sum, own) > 0.0 ? unit_or(sum, glm::vec3(own)) : glm::vec3(own);
        float* out = corner_normal(shading[c / 3], c % 3);
        out[0] = nrm.x, out[1] = nrm.y, out[2] = nrm.z;
        ++(shared ? tally.smooth : tally.sharp);
    };
    for (std::size_t begin = 0; begin < corners.size();) {
        std::size_t end = begin + 1;
        while (end < corners.size() && keys[corners[end]] == keys[corners[begin]]) ++end;
        if (end - begin <= kPairwiseLimit) {
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t a = corners[i];
                glm::dvec3 sum(0.0);
                bool shared = false;
                for (std::size_t j = begin; j < end; ++j) {
                    const std::size_t b = corners[j];
                    if (glm::dot(face[a / 3], face[b / 3]) < cos_limit) continue;
                    sum += weight[b] * face[b / 3];
                    shared = shared || b / 3 != a / 3;
                }
                write(a, sum, shared);
            }
        } else {
            glm::dvec3 mean(0.0);
            for (std::size_t i = begin; i < end; ++i) mean += weight[corners[i]] * face[corners[i] / 3];
            const glm::dvec3 axis = glm::length(mean) > 0.0 ? mean / glm::length(mean) : glm::dvec3(0.0);
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t a = corners[i];
                const bool close = glm::dot(face[a / 3], axis) >= cos_limit;
                write(a, close ? mean : face[a / 3], close);
            }
        }
        begin = end;
    }
    tally.triangles += corners.size() / 3;
}

}  // namespace

SmoothTally smooth_normals(Scene& scene, float angle_degrees) {
    const float angle = std::clamp(angle_degrees, 0.0f, 180.0f);
    // A face is always within 0 degrees of itself: at 0 every corner keeps its face normal.
    const double cos_limit = angle >= 180.0f ? -2.0 : std::cos(double(angle) * M_PI / 180.0);
    SmoothTally tally;
    smooth_list(scene.vertices, scene.shading, cos_limit, tally);
    for (SharedMesh& m : scene.meshes) smooth_list(m.vertices, m.shading, cos_limit, tally);
    scene.normal_sources.push_back(
        fmt::format("--smooth-normals {:g}: {} triangles given new normals, {} corners smooth, {} sharp (crease, "
                    "border or lone face)",
                    angle, tally.triangles, tally.smooth, tally.sharp));
    return tally;
}

}  // namespace facet
