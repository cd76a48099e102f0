// Instancing.*: a glTF mesh used by three nodes (translated; rotated with a non-uniform
// scale; mirrored under a parent) is stored once on the device, and what the kernels see
// of it (closest hits, shadow rays, renders, textures) equals the scene copied into the
// world (GltfLoadOptions::instancing off).
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <random>
#include <span>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include "host/bvh/bvh.hpp"
#include "host/readers/gltf_reader.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"
#include "host/scene/device_scene.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

constexpr int kRings = 6, kSegments = 10;  // the shared mesh: a UV sphere
// Its triangles: two pole fans and two per quad between rings.
constexpr std::size_t kMeshTriangles = 2 * kSegments + 2 * kSegments * (kRings - 2);
constexpr std::size_t kGroundTriangles = 2;

// A model with one buffer that accessors are appended to.
struct Model : test::GltfBuilder {
    int floats(const std::vector<float>& v, int type, std::size_t width) {
        return accessor(v.data(), v.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, type, v.size() / width);
    }
    int mesh(const std::vector<float>& pos, const std::vector<float>& nrm, const std::vector<float>& uv,
             const std::vector<std::uint16_t>& idx) {
        tinygltf::Primitive p;
        p.attributes["POSITION"] = floats(pos, TINYGLTF_TYPE_VEC3, 3);
        p.attributes["NORMAL"] = floats(nrm, TINYGLTF_TYPE_VEC3, 3);
        if (!uv.empty()) p.attributes["TEXCOORD_0"] = floats(uv, TINYGLTF_TYPE_VEC2, 2);
        p.indices = accessor(idx.data(), idx.size() * 2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                             idx.size());
        p.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(p);
        m.meshes.push_back(mesh);
        return int(m.meshes.size() - 1);
    }
    int node(tinygltf::Node n, bool root = true) {
        m.nodes.push_back(std::move(n));
        const int i = int(m.nodes.size() - 1);
        if (root) m.scenes[0].nodes.push_back(i);
        return i;
    }
};

// A UV sphere of radius 1 (poles on y) with its normals and uvs.
int uv_sphere(Model& model) {
    std::vector<float> pos, nrm, uv;
    std::vector<std::uint16_t> idx;
    auto vertex = [&](float theta, float phi, float u, float v) {
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        pos.insert(pos.end(), {n.x, n.y, n.z});
        nrm.insert(nrm.end(), {n.x, n.y, n.z});
        uv.insert(uv.end(), {u, v});
    };
    const float pi = 3.14159265f;
    vertex(0.0f, 0.0f, 0.5f, 0.0f);  // 0: north pole
    vertex(pi, 0.0f, 0.5f, 1.0f);    // 1: south pole
    for (int r = 1; r < kRings; ++r)
        for (int s = 0; s <= kSegments; ++s)  // the seam twice, for its uvs
            vertex(pi * float(r) / kRings, 2.0f * pi * float(s) / kSegments, float(s) / kSegments, float(r) / kRings);
    auto at = [](int r, int s) { return std::uint16_t(2 + (r - 1) * (kSegments + 1) + s); };
    for (int s = 0; s < kSegments; ++s) {
        idx.insert(idx.end(), {0, at(1, s + 1), at(1, s)});
        idx.insert(idx.end(), {1, at(kRings - 1, s), at(kRings - 1, s + 1)});
        for (int r = 1; r + 1 < kRings; ++r) {
            idx.insert(idx.end(), {at(r, s), at(r, s + 1), at(r + 1, s + 1)});
            idx.insert(idx.end(), {at(r, s), at(r + 1, s + 1), at(r + 1, s)});
        }
    }
    return model.mesh(pos, nrm, uv, idx);
}

// The ground (used once: copied into the world) and the sphere used by three nodes.
std::string write_scene(const test::TempDir& dir) {
    Model model;
    const int ground = model.mesh({-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5}, {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}, {},
                                  {0, 2, 1, 0, 3, 2});
    const int sphere = uv_sphere(model);
    tinygltf::Node g;
    g.mesh = ground;
    model.node(g);
    tinygltf::Node a;  // translated
    a.mesh = sphere;
    a.translation = {-2.2, 1.0, 0.0};
    model.node(a);
    tinygltf::Node b;  // rotated 40 degrees about (1, 1, 0), scaled non-uniformly
    b.mesh = sphere;
    const glm::quat qb = glm::angleAxis(glm::radians(40.0f), glm::normalize(glm::vec3(1, 1, 0)));
    b.rotation = {qb.x, qb.y, qb.z, qb.w};
    b.scale = {1.5, 0.6, 1.0};
    b.translation = {0.0, 1.0, 0.0};
    model.node(b);
    tinygltf::Node c;  // mirrored (negative determinant), under a translated parent
    c.mesh = sphere;
    const glm::quat qc = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));
    c.rotation = {qc.x, qc.y, qc.z, qc.w};
    c.scale = {-0.8, 0.8, 0.9};
    c.translation = {0.0, 1.0, 0.3};
    const int child = model.node(c, false);
    tinygltf::Node parent;
    parent.translation = {2.2, 0.0, 0.0};
    parent.children = {child};
    model.node(parent);
    const std::string path = dir.path("instanced.gltf");
    model.m.buffers[0].uri = "instanced.bin";
    tinygltf::TinyGLTF writer;
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&model.m, path, false, false, true, false)) << path;
    return path;
}

struct Pair {
    Scene instanced, flat;
};

Pair load_pair() {
    static const test::TempDir dir;
    static const std::string path = write_scene(dir);
    Pair p;
    GltfLoadOptions flat;
    flat.instancing = false;
    load_gltf(path, p.instanced);
    load_gltf(path, p.flat, flat);
    for (Scene* s : {&p.instanced, &p.flat}) {
        s->camera.eye = glm::vec3(0.5f, 3.5f, 8.0f);
        s->camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
        s->settings.width = s->settings.height = 40;
        s->settings.max_depth = 3;
        s->environment = constant_environment(glm::vec3(0.6f, 0.7f, 0.8f));
        PunctualLight sun;
        sun.type = FC_LIGHT_DIRECTIONAL;
        sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
        sun.color = glm::vec3(2.0f);
        s->punctual_lights = {sun};
        build_lights(*s);
    }
    return p;
}

TEST(Instancing, MeshUsedByThreeNodesIsStoredOnce) {
    const Pair p = load_pair();
    const Scene& s = p.instanced;
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 3u);
    EXPECT_EQ(s.triangle_count(), kGroundTriangles) << "a mesh used once stays in the world";
    EXPECT_EQ(s.meshes[0].triangle_count(), kMeshTriangles);
    EXPECT_EQ(s.stored_triangle_count(), kGroundTriangles + kMeshTriangles);
    EXPECT_EQ(s.placed_triangle_count(), kGroundTriangles + 3 * kMeshTriangles);
    EXPECT_TRUE(p.flat.instances.empty());
    EXPECT_EQ(p.flat.triangle_count(), kGroundTriangles + 3 * kMeshTriangles);

    // The device holds one copy; each instance's inverse is its inverse, its box holds it.
    const Bvh bvh = build_bvh(s.vertices);
    const DeviceScene dev = compile(s, bvh);
    EXPECT_EQ(dev.tris.size(), kGroundTriangles + kMeshTriangles);
    EXPECT_EQ(dev.shading.size(), kGroundTriangles + kMeshTriangles);
    ASSERT_EQ(dev.instancing.instances.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        const FcInstance& in = dev.instancing.instances[k];
        const glm::mat4& m = s.instances[std::size_t(dev.instancing.order[k])].object_to_world;
        for (const glm::vec3& v : s.meshes[0].vertices) {
            const glm::vec3 w(m * glm::vec4(v, 1.0f));
            glm::vec3 back;
            for (int r = 0; r < 3; ++r) {
                back[r] = in.world_to_object[r][0] * w.x + in.world_to_object[r][1] * w.y +
                          in.world_to_object[r][2] * w.z + in.world_to_object[r][3];
                EXPECT_LE(in.lo[r], w[r]);
                EXPECT_GE(in.hi[r], w[r]);
            }
            EXPECT_LT(glm::length(back - v), 1e-5f);
        }
    }
    const DeviceScene flat = compile(p.flat, build_bvh(p.flat.vertices));
    EXPECT_EQ(flat.tris.size(), kGroundTriangles + 3 * kMeshTriangles);
    EXPECT_TRUE(flat.instancing.instances.empty());
    EXPECT_LT(dev.nodes.size_bytes() + dev.tris.size_bytes(), flat.nodes.size_bytes() + flat.tris.size_bytes());
}

// What trace_scene_batch returns for each ray.
struct Traced {
    std::vector<cl_float4> hit, ng, ns;
    std::vector<int> any;
};

template <typename T>
cl::Buffer buffer(std::span<const T> v) {
    const T zero{};
    const std::span<const T> data = v.empty() ? std::span<const T>(&zero, 1) : v;
    return cl::Buffer(test::context().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size_bytes(),
                      const_cast<T*>(data.data()));
}

// The node layouts the renderer builds: 4-wide, 8-wide with float boxes, 8-wide quantised.
struct NodeLayout {
    int width;
    int quantised;
    const char* kernels;
};
constexpr NodeLayout kNodeLayouts[] = {{4, 0, "kernels/test/instance_kernels.cl"},
                                       {8, 0, "kernels/test/instance_kernels8.cl"},
                                       {8, 1, "kernels/test/instance_kernels8q.cl"}};

Traced trace(const Scene& scene, const NodeLayout& layout, const std::vector<cl_float4>& origins,
             const std::vector<cl_float4>& dirs) {
    BvhOptions options;
    options.width = layout.width;
    options.quantised = layout.quantised;
    const Bvh bvh = build_bvh(scene.vertices, options);
    const DeviceScene dev = compile(scene, bvh);
    ClContext& ctx = test::context();
    const std::size_t n = origins.size();
    cl::Kernel k(test::program(layout.kernels), "trace_scene_batch");
    const cl::Buffer args[] = {buffer(dev.nodes),
                               buffer(dev.tris),
                               buffer(dev.shading),
                               buffer(dev.face_normals),
                               buffer(dev.spheres),
                               buffer(dev.sphere_nodes),
                               buffer(dev.instances),
                               buffer(dev.instance_nodes),
                               buffer(std::span<const cl_float4>(origins)),
                               buffer(std::span<const cl_float4>(dirs))};
    cl_uint a = 0;
    for (const cl::Buffer& b : args) k.setArg(a++, b);
    cl::Buffer hit(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer ng(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer ns(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer any(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(int));
    for (const cl::Buffer* b : {&hit, &ng, &ns, &any}) k.setArg(a++, *b);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    Traced t;
    t.hit.resize(n), t.ng.resize(n), t.ns.resize(n), t.any.resize(n);
    ctx.queue().enqueueReadBuffer(hit, CL_TRUE, 0, n * sizeof(cl_float4), t.hit.data());
    ctx.queue().enqueueReadBuffer(ng, CL_TRUE, 0, n * sizeof(cl_float4), t.ng.data());
    ctx.queue().enqueueReadBuffer(ns, CL_TRUE, 0, n * sizeof(cl_float4), t.ns.data());
    ctx.queue().enqueueReadBuffer(any, CL_TRUE, 0, n * sizeof(int), t.any.data());
    return t;
}

glm::vec3 xyz(const cl_float4& v) { return glm::vec3(v.s[0], v.s[1], v.s[2]); }
glm::vec3 yzw(const cl_float4& v) { return glm::vec3(v.s[1], v.s[2], v.s[3]); }
int int_w(const cl_float4& v) {
    int i;
    std::memcpy(&i, &v.s[3], sizeof i);
    return i;
}

// Rays from a sphere of radius 9 about the scene toward points around the three spheres.
void camera_rays(std::vector<cl_float4>& origins, std::vector<cl_float4>& dirs, std::size_t n) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 o;
        do o = glm::vec3(2.0f * u(rng) - 1.0f, u(rng), 2.0f * u(rng) - 1.0f);
        while (!(glm::length(o) > 0.2f && glm::length(o) <= 1.0f));
        o = glm::vec3(0.0f, 1.0f, 0.0f) + 9.0f * glm::normalize(o);
        const glm::vec3 target(7.0f * u(rng) - 3.5f, 2.6f * u(rng) - 0.1f, 3.0f * u(rng) - 1.5f);
        const glm::vec3 d = glm::normalize(target - o);
        origins.push_back(cl_float4{{o.x, o.y, o.z, 0.0f}});
        dirs.push_back(cl_float4{{d.x, d.y, d.z, INFINITY}});
    }
}

TEST(Instancing, ClosestHitsMatchFlattened) {
    const Pair p = load_pair();
    std::vector<cl_float4> origins, dirs;
    camera_rays(origins, dirs, 4096);
    for (const NodeLayout& layout : kNodeLayouts) {
        SCOPED_TRACE(layout.kernels);
        const Traced a = trace(p.instanced, layout, origins, dirs), b = trace(p.flat, layout, origins, dirs);
        const Bvh bvh = build_bvh(p.instanced.vertices);
        const std::vector<std::int32_t> order = compile(p.instanced, bvh).instancing.order;
        std::size_t both = 0, on_instances = 0, differ = 0, far = 0;
        for (std::size_t i = 0; i < origins.size(); ++i) {
            const bool ha = a.hit[i].s[0] >= 0.0f, hb = b.hit[i].s[0] >= 0.0f;
            // The flattened scene's triangle for an instanced one: copies follow the ground in node order.
            int prim = int_w(a.ng[i]);
            const int inst = int_w(a.ns[i]);
            if (ha && inst >= 0) {
                prim += order[std::size_t(inst)] * int(kMeshTriangles);
                ++on_instances;
            }
            if (ha != hb || (ha && prim != int_w(b.ng[i]))) {
                ++differ;  // a ray through an edge may meet either neighbour
                continue;
            }
            if (!ha) continue;
            ++both;
            const float t = b.hit[i].s[0];
            const bool close = std::fabs(a.hit[i].s[0] - t) <= 1e-4f * t &&
                               glm::length(yzw(a.hit[i]) - yzw(b.hit[i])) <= 1e-4f * glm::length(yzw(b.hit[i])) &&
                               glm::length(xyz(a.ng[i]) - xyz(b.ng[i])) <= 1e-4f &&
                               glm::length(xyz(a.ns[i]) - xyz(b.ns[i])) <= 1e-4f;
            if (!close && far++ < 5)
                ADD_FAILURE() << "ray " << i << ": t " << a.hit[i].s[0] << " vs " << t << ", ns (" << a.ns[i].s[0]
                              << ", " << a.ns[i].s[1] << ", " << a.ns[i].s[2] << ") vs (" << b.ns[i].s[0] << ", "
                              << b.ns[i].s[1] << ", " << b.ns[i].s[2] << ")";
        }
        EXPECT_EQ(far, 0u) << "hits that differ from the flattened scene's beyond 1e-4";
        EXPECT_LE(differ, origins.size() / 1000) << "rays meeting another triangle (or none)";
        EXPECT_GT(on_instances, origins.size() / 4) << "rays that meet an instance";
        EXPECT_GT(both, origins.size() / 2);
    }
}

TEST(Instancing, ShadowRaysMatchFlattened) {
    const Pair p = load_pair();
    // Segments between random points of the scene's box, as shadow rays are.
    std::mt19937 rng(16);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<cl_float4> origins, dirs;
    for (int i = 0; i < 4096; ++i) {
        const glm::vec3 a(8.0f * u(rng) - 4.0f, 2.8f * u(rng) + 0.05f, 5.0f * u(rng) - 2.5f);
        const glm::vec3 b(8.0f * u(rng) - 4.0f, 2.8f * u(rng) + 0.05f, 5.0f * u(rng) - 2.5f);
        const float len = glm::length(b - a);
        const glm::vec3 d = (b - a) / len;
        origins.push_back(cl_float4{{a.x, a.y, a.z, 0.0f}});
        dirs.push_back(cl_float4{{d.x, d.y, d.z, len}});
    }
    for (const NodeLayout& layout : kNodeLayouts) {
        SCOPED_TRACE(layout.kernels);
        const Traced a = trace(p.instanced, layout, origins, dirs), b = trace(p.flat, layout, origins, dirs);
        std::size_t blocked = 0, differ = 0, closest_disagrees = 0;
        for (std::size_t i = 0; i < origins.size(); ++i) {
            blocked += std::size_t(b.any[i]);
            differ += a.any[i] != b.any[i] ? 1u : 0u;
            closest_disagrees += (a.any[i] != 0) != (a.hit[i].s[0] >= 0.0f) ? 1u : 0u;
        }
        EXPECT_LE(differ, origins.size() / 1000) << "shadow rays answered differently";
        EXPECT_EQ(closest_disagrees, 0u) << "any-hit and closest-hit disagree in the instanced scene";
        EXPECT_GT(blocked, origins.size() / 10) << "segments blocked";
        EXPECT_LT(blocked, origins.size() * 9 / 10);
    }
}

// The two renders with the same seeds: the same image in mean (a z-test on the image's mean
// per channel, its variance summed from each pixel's two half-images) and nearly pixel for
// pixel (the paths use the same numbers; a few part where the geometry rounds differently).
void expect_same_render(const Scene& instanced, const Scene& flat, std::uint32_t spp, bool per_pixel = true) {
    Renderer ri(test::context(), instanced, build_bvh(instanced.vertices));
    Renderer rf(test::context(), flat, build_bvh(flat.vertices));
    EXPECT_NE(ri.build().source.text.find("#define FC_HAS_INSTANCES 1\n"), std::string::npos);
    EXPECT_NE(rf.build().source.text.find("#define FC_HAS_INSTANCES 0\n"), std::string::npos);
    render_fixed(ri, spp);
    render_fixed(rf, spp);
    const Renderer::Halves a = ri.halves(), b = rf.halves();
    const std::size_t n = a.rgb[0].size(), pixels = n / 3;
    std::size_t differ = 0;
    double mean[2][3] = {}, var[3] = {};
    for (std::size_t i = 0; i < n; ++i) {
        const float va = 0.5f * (a.rgb[0][i] + a.rgb[1][i]), vb = 0.5f * (b.rgb[0][i] + b.rgb[1][i]);
        if (std::fabs(va - vb) > 1e-3f * (1.0f + std::fabs(vb))) ++differ;
        mean[0][i % 3] += double(va) / double(pixels);
        mean[1][i % 3] += double(vb) / double(pixels);
        const double da = double(a.rgb[0][i]) - double(a.rgb[1][i]), db = double(b.rgb[0][i]) - double(b.rgb[1][i]);
        var[i % 3] += 0.25 * (da * da + db * db) / (double(pixels) * double(pixels));
    }
    for (int c = 0; c < 3; ++c) {
        const double z = std::fabs(mean[0][c] - mean[1][c]) / std::sqrt(var[c] + 1e-18);
        EXPECT_LT(z, 4.0) << "channel " << c << ": means " << mean[0][c] << " and " << mean[1][c];
        EXPECT_GT(mean[1][c], 0.05) << "the image is lit";
    }
    if (per_pixel) {
        EXPECT_LE(differ, n / 50) << "pixel channels that differ by more than 1e-3, of " << n;
    }
    EXPECT_EQ(a.rejected, 0.0);
}

TEST(Instancing, RenderMatchesFlattened) {
    const Pair p = load_pair();
    expect_same_render(p.instanced, p.flat, 16);
}

// Textures on the shared mesh: the instances read the mesh's uvs, which equal those of the
// copies (corners 1 and 2 swapped in the mirrored copy, as its vertices are), and their
// texture frames are the copies'.
TEST(Instancing, TexturedMeshKeepsItsUvs) {
    Pair p = load_pair();
    const SharedMesh& mesh = p.instanced.meshes[0];
    ASSERT_EQ(mesh.texcoords.size(), kMeshTriangles);
    for (std::size_t copy = 0; copy < 3; ++copy)
        for (std::size_t t = 0; t < kMeshTriangles; ++t) {
            const FcTriTexcoords& f = p.flat.texcoords[kGroundTriangles + copy * kMeshTriangles + t];
            const FcTriTexcoords& s = mesh.texcoords[t];
            const bool mirrored = copy == 2;
            for (int c = 0; c < 3; ++c) {
                const int fc = mirrored && c > 0 ? 3 - c : c;
                EXPECT_EQ(f.uv[fc][0], s.uv[c][0]) << "copy " << copy << " triangle " << t;
                EXPECT_EQ(f.uv[fc][1], s.uv[c][1]) << "copy " << copy << " triangle " << t;
            }
        }
    // A 64 x 64 checker (its mip level follows the world-space area of the triangle) and a
    // tilted normal map (its tangent frame follows dp/du in world space).
    std::vector<float> rgba, tilted;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float v = (x / 4 + y / 4) % 2 ? 0.9f : 0.1f;
            rgba.insert(rgba.end(), {v, 0.5f * v + 0.2f, 1.0f - v, 1.0f});
        }
    for (int i = 0; i < 16; ++i) tilted.insert(tilted.end(), {0.85f, 0.6f, 0.9f, 1.0f});
    for (Scene* s : {&p.instanced, &p.flat}) {
        s->textures.push_back(make_texture(64, 64, rgba));
        s->textures.push_back(make_texture(4, 4, tilted));
        ASSERT_EQ(s->materials.size(), 1u);
        s->materials[0].textures.base_color = 0;
    }
    expect_same_render(p.instanced, p.flat, 16);
    // The normal map: the instances' vertex tangents are computed in object space (glTF's
    // convention) and placed by the instance's linear part, the copies' after their transform;
    // under the non-uniform scale of the second node the two differ by the angle weights and
    // the Gram-Schmidt step, so the images agree in mean (z-test), not pixel for pixel.
    for (Scene* s : {&p.instanced, &p.flat}) s->materials[0].textures.normal = 1;
    expect_same_render(p.instanced, p.flat, 16, false);
}

// Alpha on the shared mesh (kernels/trace/alpha_test.cl): the instances' triangles are
// tested with their place in the whole triangle array (the instance's offset), so their
// cut-outs fall where the copies' do: a MASK checker of alpha 0 / 1 matches per pixel, and
// BLEND (whose random numbers are the triangle's own, so not the copies') matches in mean.
TEST(Instancing, AlphaCutOutMatchesFlattened) {
    Pair p = load_pair();
    std::vector<float> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) rgba.insert(rgba.end(), {0.8f, 0.8f, 0.8f, (x + y) % 2 ? 1.0f : 0.0f});
    for (Scene* s : {&p.instanced, &p.flat}) {
        s->textures.push_back(make_texture(8, 8, rgba, FC_WRAP_CLAMP, FC_WRAP_CLAMP));
        ASSERT_EQ(s->materials.size(), 1u);
        s->materials[0].alpha_mode = FC_ALPHA_MASK;
        s->materials[0].textures.alpha = 0;
    }
    expect_same_render(p.instanced, p.flat, 16);
    for (Scene* s : {&p.instanced, &p.flat}) {
        s->materials[0].alpha_mode = FC_ALPHA_BLEND;
        s->materials[0].textures.alpha = -1;
        s->materials[0].alpha = 0.5f;
    }
    expect_same_render(p.instanced, p.flat, 16, false);
}

TEST(Instancing, FeatureBitOnlyWithInstances) {
    const Pair p = load_pair();
    const FeatureMask bit = 1u << 11;
    EXPECT_EQ(scene_features(p.instanced) & bit, bit);
    EXPECT_EQ(scene_features(p.flat) & bit, 0u);
    EXPECT_NE(describe_features(scene_features(p.instanced)).find("instances"), std::string::npos);
    for (const char* file : {"cornell_box.json", "material_grid.json", "spheres_sky.json", "glass_metal_sky.json"})
        EXPECT_EQ(scene_features(load_scene(test::scenes_dir() + "/" + file)) & bit, 0u) << file;
}

}  // namespace
}  // namespace facet
