// Vertex tangents for normal maps, MikkTSpace-style (Mikkelsen 2008; the reference
// implementation's steps: per-face tangents from uv derivatives, vertices welded by
// position, normal and uv, split where the handedness differs, angle-weighted sums,
// Gram-Schmidt to the vertex normal), written from the algorithm's description.
#include "host/scene/texture_tangents.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "host/scene/scene.hpp"

namespace facet {
namespace {

// A welded vertex: bit-exact position, normal and uv (as MikkTSpace compares them),
// and the handedness of the faces around it.
struct VertexKey {
    float v[8];
    int sign;
    bool operator==(const VertexKey& o) const { return std::memcmp(this, &o, sizeof o) == 0; }
};

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the key's bytes
        const auto* b = reinterpret_cast<const unsigned char*>(&k);
        for (std::size_t i = 0; i < sizeof k; ++i) h = (h ^ b[i]) * 1099511628211ull;
        return std::size_t(h);
    }
};

glm::dvec3 load(const float (&v)[3]) { return {v[0], v[1], v[2]}; }

// One triangle's corners as the tangent computation needs them.
struct Corners {
    glm::dvec3 p[3], n[3];
    glm::dvec2 uv[3];
};

Corners corners(const Scene& scene, const std::vector<FcTriTexcoords>& tc, std::size_t t) {
    Corners c;
    const FcTriShading& s = scene.shading[t];
    const float(*normals[3])[3] = {&s.n0, &s.n1, &s.n2};
    for (int k = 0; k < 3; ++k) {
        c.p[k] = glm::dvec3(scene.vertices[3 * t + std::size_t(k)]);
        const glm::dvec3 n = load(*normals[k]);
        c.n[k] = glm::length(n) > 0.0 ? glm::normalize(n) : n;
        c.uv[k] = glm::dvec2(tc[t].uv[k][0], tc[t].uv[k][1]);
    }
    return c;
}

VertexKey vertex_key(const Corners& c, int k, int sign) {
    VertexKey out;
    std::memset(&out, 0, sizeof out);
    const double v[8] = {c.p[k].x, c.p[k].y, c.p[k].z, c.n[k].x, c.n[k].y, c.n[k].z, c.uv[k].x, c.uv[k].y};
    for (int i = 0; i < 8; ++i) out.v[i] = float(v[i]) + 0.0f;  // -0 and +0 weld
    out.sign = sign;
    return out;
}

// v made orthogonal to the unit n.
glm::dvec3 orthogonal(glm::dvec3 v, glm::dvec3 n) { return v - n * glm::dot(n, v); }

// The angle at corner k.
double corner_angle(const Corners& c, int k) {
    const glm::dvec3 a = c.p[(k + 1) % 3] - c.p[k], b = c.p[(k + 2) % 3] - c.p[k];
    const double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0 && lb > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

// The face's dp/du and the handedness of its uv winding (+1: the bitangent cross(n, t)
// points along -dp/dv, toward the image's top); false where the uvs are degenerate.
bool face_tangent(const Corners& c, glm::dvec3* dpdu, int* sign) {
    const glm::dvec3 e1 = c.p[1] - c.p[0], e2 = c.p[2] - c.p[0];
    const glm::dvec2 d1 = c.uv[1] - c.uv[0], d2 = c.uv[2] - c.uv[0];
    const double det = d1.x * d2.y - d1.y * d2.x;
    if (!(det != 0.0) || !std::isfinite(det)) return false;
    *dpdu = (d2.y * e1 - d1.y * e2) / det;
    const glm::dvec3 dpdv = (d1.x * e2 - d2.x * e1) / det;
    glm::dvec3 n = glm::cross(e1, e2);
    if (glm::dot(n, c.n[0] + c.n[1] + c.n[2]) < 0.0) n = -n;  // the side the shading normals face
    *sign = glm::dot(glm::cross(n, *dpdu), dpdv) > 0.0 ? -1 : 1;
    return std::isfinite(glm::length(*dpdu)) && glm::length(*dpdu) > 0.0;
}

bool wants_tangents(const Scene& scene, const std::vector<FcTriTexcoords>& tc, std::size_t t) {
    const int m = scene.shading[t].material;
    if ((tc[t].tangent_flags & FC_TANGENTS_SET) != 0 || m < 0 || std::size_t(m) >= scene.materials.size()) return false;
    const Material& mat = scene.materials[std::size_t(m)];
    return mat.textures.normal >= 0 || mat.textures.clearcoat_normal >= 0 || material_is_anisotropic(mat);
}

}  // namespace

std::uint32_t encode_octahedral(glm::vec3 unit) {
    glm::vec3 v = unit / (std::fabs(unit.x) + std::fabs(unit.y) + std::fabs(unit.z));
    if (!std::isfinite(v.x + v.y + v.z)) v = glm::vec3(1.0f, 0.0f, 0.0f);
    float x = v.x, y = v.y;
    if (v.z < 0.0f) {  // the lower half folded over the diagonals
        x = (1.0f - std::fabs(v.y)) * (v.x >= 0.0f ? 1.0f : -1.0f);
        y = (1.0f - std::fabs(v.x)) * (v.y >= 0.0f ? 1.0f : -1.0f);
    }
    auto snorm16 = [](float f) {
        const long q = std::lround(std::clamp(f, -1.0f, 1.0f) * 32767.0f);
        return std::uint32_t(std::uint16_t(std::int16_t(q)));
    };
    return snorm16(x) | (snorm16(y) << 16);
}

void set_triangle_tangents(Scene& scene, std::size_t tri, const glm::vec4 (&tangent)[3]) {
    if (scene.texcoords.size() < scene.shading.size()) scene.texcoords.resize(scene.shading.size(), FcTriTexcoords{});
    FcTriTexcoords& t = scene.texcoords.at(tri);
    for (int c = 0; c < 3; ++c) {
        const float len = glm::length(glm::vec3(tangent[c]));
        if (!(len > 0.0f) || !std::isfinite(len)) return;  // computed instead (compute_tangents)
    }
    t.tangent_flags = FC_TANGENTS_SET;
    for (int c = 0; c < 3; ++c) {
        t.tangent[c] = encode_octahedral(glm::normalize(glm::vec3(tangent[c])));
        if (tangent[c].w < 0.0f) t.tangent_flags |= 1u << c;
    }
}

void compute_tangents(const Scene& scene, std::vector<FcTriTexcoords>& tc) {
    std::unordered_map<VertexKey, glm::dvec3, VertexKeyHash> sums;
    // Per face: dp/du made orthogonal to each corner's normal, weighted by the corner's angle.
    for (std::size_t t = 0; t < scene.shading.size(); ++t) {
        if (!wants_tangents(scene, tc, t)) continue;
        const Corners c = corners(scene, tc, t);
        glm::dvec3 dpdu;
        int sign;
        if (!face_tangent(c, &dpdu, &sign)) continue;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 o = orthogonal(dpdu, c.n[k]);
            const double len = glm::length(o);
            if (len > 0.0) sums.try_emplace(vertex_key(c, k, sign), 0.0).first->second += corner_angle(c, k) * o / len;
        }
    }
    // Per corner: the welded vertex's sum, orthogonal to the corner's normal.
    for (std::size_t t = 0; t < scene.shading.size(); ++t) {
        if (!wants_tangents(scene, tc, t)) continue;
        const Corners c = corners(scene, tc, t);
        glm::dvec3 dpdu;
        int sign;
        if (!face_tangent(c, &dpdu, &sign)) continue;  // no uv frame: the kernel keeps the normal
        FcTriTexcoords& out = tc[t];
        out.tangent_flags = FC_TANGENTS_SET | (sign < 0 ? 7u : 0u);
        for (int k = 0; k < 3; ++k) {
            const auto it = sums.find(vertex_key(c, k, sign));
            glm::dvec3 v = orthogonal(it != sums.end() ? it->second : dpdu, c.n[k]);
            if (!(glm::length(v) > 0.0) || !std::isfinite(glm::length(v))) v = orthogonal(dpdu, c.n[k]);
            if (!(glm::length(v) > 0.0) || !std::isfinite(glm::length(v))) v = dpdu;
            out.tangent[k] = encode_octahedral(glm::vec3(glm::normalize(v)));
        }
    }
}

}  // namespace facet
