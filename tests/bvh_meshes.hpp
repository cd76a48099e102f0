// Meshes for tests/bvh_test.cpp, made procedurally so the tests need no files: closed
// indexed meshes (shared vertices are bit-identical, for the watertightness tests), a
// degenerate-heavy triangle soup, and a minimal OBJ reader (v and f lines only).
#pragma once

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace facet::test {

struct IndexedMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::ivec3> faces;

    std::vector<glm::vec3> soup() const {
        std::vector<glm::vec3> out;
        out.reserve(faces.size() * 3);
        for (const glm::ivec3& f : faces)
            for (int k = 0; k < 3; ++k) out.push_back(positions[f[k]]);
        return out;
    }
};

// Torus around +z with radii R > r, nu x nv quads split in two: 2*nu*nv triangles.
inline IndexedMesh make_torus(int nu, int nv, float R, float r) {
    IndexedMesh m;
    const float two_pi = 6.28318530717958647692f;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            float a = two_pi * static_cast<float>(i) / static_cast<float>(nu);
            float b = two_pi * static_cast<float>(j) / static_cast<float>(nv);
            m.positions.emplace_back((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                                     r * std::sin(b));
        }
    auto at = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.faces.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            m.faces.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    return m;
}

// The surface of the cube [0, n]^3 as a grid of unit squares, two triangles each, all
// vertices on integer coordinates (so rays can be aimed exactly at edges and vertices).
inline IndexedMesh make_grid_cube(int n) {
    IndexedMesh m;
    auto vertex = [&](glm::vec3 p) {
        m.positions.push_back(p);
        return static_cast<int>(m.positions.size()) - 1;
    };
    // Vertices are duplicated per face but bit-identical, which is all the test needs.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    int idx[4];
                    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                    for (int k = 0; k < 4; ++k) {
                        glm::vec3 p(0.0f);
                        p[axis] = static_cast<float>(side * n);
                        p[u] = static_cast<float>(i + di[k]);
                        p[v] = static_cast<float>(j + dj[k]);
                        idx[k] = vertex(p);
                    }
                    m.faces.emplace_back(idx[0], idx[1], idx[2]);
                    m.faces.emplace_back(idx[0], idx[2], idx[3]);
                }
        }
    return m;
}

// A soup built to trouble a BVH: duplicates, slivers, zero-area and non-finite
// triangles, coplanar overlapping ones, huge and tiny ones. `unusable` counts the
// triangles build_bvh must skip.
inline std::vector<glm::vec3> make_degenerate_soup(int count, std::size_t& unusable) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    auto rnd = [&](float lo, float hi) {
        return glm::vec3(lo + (hi - lo) * u01(rng), lo + (hi - lo) * u01(rng), lo + (hi - lo) * u01(rng));
    };
    std::vector<glm::vec3> v;
    unusable = 0;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < count; ++i) {
        glm::vec3 c = rnd(-1.0f, 1.0f);
        glm::vec3 a, b, d;
        switch (i % 10) {
            case 0:  // ordinary
                a = c + rnd(-0.1f, 0.1f), b = c + rnd(-0.1f, 0.1f), d = c + rnd(-0.1f, 0.1f);
                break;
            case 1:  // exact duplicate of the previous triangle
                if (i > 0) {
                    a = v[v.size() - 3], b = v[v.size() - 2], d = v[v.size() - 1];
                    break;
                }
                [[fallthrough]];
            case 2:  // sliver: the third vertex a hair off the first edge
                a = c, b = c + rnd(-0.3f, 0.3f);
                d = 0.5f * (a + b) + glm::vec3(0.0f, 1e-6f, 0.0f);
                break;
            case 3:  // zero area: repeated vertex, or three on an axis-parallel line
                a = c, b = (i % 20 == 3) ? c : c + glm::vec3(0.25f, 0.0f, 0.0f);
                d = c + glm::vec3(0.5f, 0.0f, 0.0f);
                ++unusable;
                break;
            case 4:  // coplanar and overlapping, on z = 0.25
                a = glm::vec3(c.x, c.y, 0.25f), b = a + glm::vec3(0.3f, 0.0f, 0.0f),
                d = a + glm::vec3(0.0f, 0.3f, 0.0f);
                break;
            case 5:  // huge
                a = rnd(-1e3f, 1e3f), b = rnd(-1e3f, 1e3f), d = rnd(-1e3f, 1e3f);
                if (i % 30 != 5) a.z = b.z = d.z = -2.0f;  // mostly a floor below the rest
                break;
            case 6:  // tiny
                a = c, b = c + rnd(-1e-5f, 1e-5f), d = c + rnd(-1e-5f, 1e-5f);
                break;
            case 7:  // non-finite vertex
                a = c, b = c + glm::vec3(0.1f, 0.0f, 0.0f), d = glm::vec3(nan, 0.0f, inf);
                ++unusable;
                break;
            default:  // axis-aligned (flat boxes) sharing an edge with a neighbour
                a = c, b = c + glm::vec3(0.2f, 0.0f, 0.0f), d = c + glm::vec3(0.0f, 0.2f, 0.0f);
                v.push_back(b), v.push_back(d), v.push_back(c + glm::vec3(0.2f, 0.2f, 0.0f));
                break;
        }
        v.push_back(a), v.push_back(b), v.push_back(d);
    }
    return v;
}

// Triangle soup from an OBJ file's v and f lines (polygons fanned); empty if unreadable.
inline std::vector<glm::vec3> load_obj_soup(const std::string& path) {
    std::ifstream in(path);
    std::vector<glm::vec3> pos, out;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            glm::vec3 p;
            s >> p.x >> p.y >> p.z;
            pos.push_back(p);
        } else if (tag == "f") {
            std::vector<int> idx;
            std::string tok;
            while (s >> tok) {
                int k = std::stoi(tok.substr(0, tok.find('/')));
                idx.push_back(k < 0 ? static_cast<int>(pos.size()) + k : k - 1);
            }
            for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
                out.push_back(pos.at(idx[0]));
                out.push_back(pos.at(idx[k]));
                out.push_back(pos.at(idx[k + 1]));
            }
        }
    }
    return out;
}

}  // namespace facet::test
