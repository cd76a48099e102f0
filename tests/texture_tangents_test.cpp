// Tangent frames of normal maps (host/scene/texture_tangents.hpp, docs/textures.md):
// glTF TANGENT attributes are read; without them, MikkTSpace-style vertex tangents are
// computed, and on a uv sphere they match the analytic ones a file gives; a mirrored uv
// seam keeps each side's handedness. Read back through the kernels' own decoding
// (kernels/test/texture_kernels.cl, tangent_batch).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "host/readers/gltf_reader.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

// Corner c of every triangle's tangent (xyz) and handedness (w; 0: none), read by the kernels.
std::vector<cl_float4> corner_tangents(const std::vector<FcTriTexcoords>& tc) {
    std::vector<cl_float4> query;
    for (std::size_t t = 0; t < tc.size(); ++t)
        for (int c = 0; c < 3; ++c) query.push_back({{float(t), c == 1 ? 1.0f : 0.0f, c == 2 ? 1.0f : 0.0f, 0.0f}});
    ClContext& ctx = test::context();
    cl::Kernel k(test::program("kernels/test/texture_kernels.cl"), "tangent_batch");
    cl::Buffer in_tc(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tc.size() * sizeof(FcTriTexcoords),
                     const_cast<FcTriTexcoords*>(tc.data()));
    cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, query.size() * sizeof(cl_float4),
                  query.data());
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, query.size() * sizeof(cl_float4));
    k.setArg(0, in_tc);
    k.setArg(1, in);
    k.setArg(2, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(query.size()));
    std::vector<cl_float4> result(query.size());
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, result.size() * sizeof(cl_float4), result.data());
    return result;
}

glm::vec3 xyz(const cl_float4& v) { return glm::vec3(v.s[0], v.s[1], v.s[2]); }

double angle_degrees(glm::vec3 a, glm::vec3 b) {
    return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)) * 180.0 / M_PI;
}

// A unit uv sphere of nu x nv quads as glTF (seam vertices doubled, as exporters write
// it): p = (sin th cos ph, cos th, -sin th sin ph), u = ph / 2pi, v = th / pi (v = 0 at
// the top of the image: the north pole), normals p, and with `tangents` the analytic
// TANGENT: t = dp/du normalised, w = +1 where cross(n, t) points to the image's top
// (-dp/dv), as glTF's bitangent rule reads it.
std::string write_uv_sphere(const test::TempDir& d, const std::string& name, bool tangents) {
    const int nu = 32, nv = 16;
    std::vector<float> pos, nrm, uv, tan;
    for (int i = 0; i <= nv; ++i)
        for (int j = 0; j <= nu; ++j) {
            const double th = M_PI * i / nv, ph = 2.0 * M_PI * j / nu;
            const glm::dvec3 p(std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph));
            const glm::dvec3 t(-std::sin(ph), 0.0, -std::cos(ph));  // dp/du / |dp/du|
            const glm::dvec3 dpdv(std::cos(th) * std::cos(ph), -std::sin(th), -std::cos(th) * std::sin(ph));
            const double w = glm::dot(glm::cross(p, t), -dpdv) >= 0.0 ? 1.0 : -1.0;
            pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
            nrm.insert(nrm.end(), {float(p.x), float(p.y), float(p.z)});
            uv.insert(uv.end(), {float(j) / nu, float(i) / nv});
            tan.insert(tan.end(), {float(t.x), float(t.y), float(t.z), float(w)});
        }
    std::vector<std::uint32_t> idx;
    for (int i = 0; i < nv; ++i)
        for (int j = 0; j < nu; ++j) {
            const std::uint32_t a = std::uint32_t(i * (nu + 1) + j), b = a + 1, c = a + nu + 1, e = c + 1;
            idx.insert(idx.end(), {a, c, e, a, e, b});  // counter-clockwise seen from outside
        }
    test::GltfBuilder g;
    tinygltf::Model& m = g.m;
    const int f = TINYGLTF_COMPONENT_TYPE_FLOAT;
    tinygltf::Primitive p;
    p.attributes["POSITION"] = g.accessor(pos.data(), pos.size() * 4, f, TINYGLTF_TYPE_VEC3, pos.size() / 3);
    p.attributes["NORMAL"] = g.accessor(nrm.data(), nrm.size() * 4, f, TINYGLTF_TYPE_VEC3, nrm.size() / 3);
    p.attributes["TEXCOORD_0"] = g.accessor(uv.data(), uv.size() * 4, f, TINYGLTF_TYPE_VEC2, uv.size() / 2);
    if (tangents)
        p.attributes["TANGENT"] = g.accessor(tan.data(), tan.size() * 4, f, TINYGLTF_TYPE_VEC4, tan.size() / 4);
    p.indices =
        g.accessor(idx.data(), idx.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, idx.size());
    p.mode = TINYGLTF_MODE_TRIANGLES;
    m.meshes.emplace_back().primitives.push_back(p);
    tinygltf::Node n;
    n.mesh = 0;
    m.nodes.push_back(n);
    m.scenes[0].nodes.push_back(0);
    tinygltf::TinyGLTF writer;
    const std::string path = d.path(name);
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&m, path, false, true, true, true)) << path;
    return path;
}

// The scene's device uvs and tangents after giving every material a normal map.
std::vector<FcTriTexcoords> normal_mapped_texcoords(Scene& scene) {
    std::vector<float> tilted;
    for (int i = 0; i < 4; ++i) tilted.insert(tilted.end(), {0.7f, 0.5f, 0.8f, 1.0f});
    scene.textures.push_back(make_texture(2, 2, tilted));
    for (Material& m : scene.materials) m.textures.normal = int(scene.textures.size() - 1);
    return compile_textures(scene).texcoords;
}

TEST(TextureTangents, ComputedMatchTheFileOnAUvSphere) {
    test::TempDir d;
    Scene given, computed;
    load_gltf(write_uv_sphere(d, "given.glb", true), given);
    load_gltf(write_uv_sphere(d, "computed.glb", false), computed);
    ASSERT_EQ(given.shading.size(), computed.shading.size());
    ASSERT_GT(given.texcoords.size(), 0u);
    EXPECT_TRUE(given.texcoords[0].tangent_flags & FC_TANGENTS_SET) << "TANGENT read from the file";
    EXPECT_FALSE(computed.texcoords[0].tangent_flags & FC_TANGENTS_SET);
    const std::vector<cl_float4> a = corner_tangents(normal_mapped_texcoords(given));
    const std::vector<cl_float4> b = corner_tangents(normal_mapped_texcoords(computed));
    double worst_inside = 0.0, worst = 0.0;
    std::size_t compared = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const std::size_t t = k / 3;
        const glm::vec3 p = computed.vertices[k];
        ASSERT_NE(b[k].s[3], 0.0f) << "triangle " << t << " has computed tangents";
        EXPECT_EQ(a[k].s[3], b[k].s[3]) << "handedness of corner " << k;
        if (std::fabs(p.y) > 0.999f) continue;  // the poles: one face a vertex, no average to compare
        const double angle = angle_degrees(xyz(a[k]), xyz(b[k]));
        const float u = computed.texcoords[t].uv[k % 3][0];
        // On the uv seam a vertex's faces lie on one side only: off by half a segment (5.6 degrees).
        const bool seam = !(u > 0.0f && u < 1.0f);
        worst = std::max(worst, angle);
        if (!seam) worst_inside = std::max(worst_inside, angle);
        ++compared;
    }
    EXPECT_GT(compared, a.size() / 2);
    EXPECT_LT(worst_inside, 0.1) << "degrees between the file's and the computed tangents";
    EXPECT_LT(worst, 6.0) << "degrees between the file's and the computed tangents on the seam";
}

// A flat strip in z = 0 (normal +z) mirrored at x = 0: u = |x|, v = 1 - y (the image
// upright). Its seam vertices are shared (same position, normal and uv) but the two
// sides have opposite handedness: tangent -x, w = -1 on the left, +x, w = +1 on the
// right, also at the seam.
TEST(TextureTangents, MirroredSeamKeepsEachSidesHandedness) {
    Scene scene;
    add_material(scene, default_material(), "mirrored");
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (float side : {-1.0f, 1.0f}) {
        const glm::vec3 a(0, 0, 0), b(side, 0, 0), c(side, 1, 0), e(0, 1, 0);
        const glm::vec2 ua(0, 1), ub(1, 1), uc(1, 0), ue(0, 0);
        // counter-clockwise from +z on both sides
        if (side > 0) {
            add_triangle(scene, a, b, c, n, n, n, 0);
            set_triangle_texcoords(scene, scene.shading.size() - 1, ua, ub, uc);
            add_triangle(scene, a, c, e, n, n, n, 0);
            set_triangle_texcoords(scene, scene.shading.size() - 1, ua, uc, ue);
        } else {
            add_triangle(scene, a, c, b, n, n, n, 0);
            set_triangle_texcoords(scene, scene.shading.size() - 1, ua, uc, ub);
            add_triangle(scene, a, e, c, n, n, n, 0);
            set_triangle_texcoords(scene, scene.shading.size() - 1, ua, ue, uc);
        }
    }
    const std::vector<cl_float4> t = corner_tangents(normal_mapped_texcoords(scene));
    for (std::size_t k = 0; k < t.size(); ++k) {
        const float side = k < 6 ? -1.0f : 1.0f;
        SCOPED_TRACE("corner " + std::to_string(k));
        EXPECT_NEAR(t[k].s[0], side, 1e-4f);
        EXPECT_NEAR(t[k].s[1], 0.0f, 1e-4f);
        EXPECT_NEAR(t[k].s[2], 0.0f, 1e-4f);
        EXPECT_EQ(t[k].s[3], side) << "handedness";
    }
}

// The file's tangents follow the node's transform; a mirroring one flips the handedness.
TEST(TextureTangents, FileTangentsFollowAMirroringTransform) {
    test::TempDir d;
    const std::string path = write_uv_sphere(d, "s.glb", true);
    Scene plain, mirrored;
    load_gltf(path, plain);
    GltfLoadOptions options;
    options.mesh.transform =
        glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1));
    load_gltf(path, mirrored, options);
    ASSERT_EQ(plain.shading.size(), mirrored.shading.size());
    const std::vector<cl_float4> a = corner_tangents(normal_mapped_texcoords(plain));
    const std::vector<cl_float4> b = corner_tangents(normal_mapped_texcoords(mirrored));
    for (std::size_t k = 0; k < a.size(); k += 3) {
        ASSERT_NE(a[k].s[3], 0.0f) << "the file's tangents, triangle " << k / 3;
        EXPECT_EQ(a[k].s[3], -b[k].s[3]) << "triangle " << k / 3;
        EXPECT_NEAR(a[k].s[0], -b[k].s[0], 1e-4f);  // corner 0 stays corner 0 when b and c swap
        EXPECT_NEAR(a[k].s[1], b[k].s[1], 1e-4f);
    }
}

}  // namespace
}  // namespace facet
