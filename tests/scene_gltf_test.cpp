// SceneGltf.*: glTF 2.0 files written by the tests themselves (through tinygltf's writer)
// in every container (.gltf + .bin, data URIs, .glb), and the malformed glTF files of
// Debian's assimp-testmodels (skipped when the package is absent).
#include <cmath>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "host/readers/gltf_reader.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/scene_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using test::expect_error;
using test::TempDir;

// A model built in memory: one buffer that accessors are appended to.
struct ModelBuilder : test::GltfBuilder {
    int vec3s(const std::vector<float>& v) {
        return accessor(v.data(), v.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v.size() / 3);
    }
    int indices(const std::vector<std::uint16_t>& v) {
        return accessor(v.data(), v.size() * 2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, v.size());
    }

    // The unit square in z = 0 facing +z: indexed (4 vertices) or not (6).
    int square(bool indexed, bool normals, int material = -1) {
        tinygltf::Primitive p;
        if (indexed) {
            p.attributes["POSITION"] = vec3s({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
            p.indices = indices({0, 1, 2, 0, 2, 3});
        } else {
            p.attributes["POSITION"] = vec3s({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0});
        }
        if (normals) {
            const std::size_t n = indexed ? 4 : 6;
            std::vector<float> x;
            for (std::size_t i = 0; i < n; ++i) x.insert(x.end(), {1, 0, 0});
            p.attributes["NORMAL"] = vec3s(x);
        }
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.material = material;
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
    int mesh_node(int mesh, std::vector<double> translation = {}) {
        tinygltf::Node n;
        n.mesh = mesh;
        n.translation = std::move(translation);
        return node(n);
    }

    // Writes the model as name (.gltf with a .bin beside it, or data URIs, or .glb).
    std::string write(const TempDir& d, const std::string& name, bool embed = false) {
        const bool glb = name.size() > 4 && name.substr(name.size() - 4) == ".glb";
        if (!embed && !glb) m.buffers[0].uri = std::filesystem::path(name).stem().string() + ".bin";
        tinygltf::TinyGLTF writer;
        const std::string path = d.path(name);
        EXPECT_TRUE(writer.WriteGltfSceneToFile(&m, path, false, embed || glb, true, glb)) << path;
        return path;
    }
};

glm::vec3 v3(const float n[3]) { return glm::vec3(n[0], n[1], n[2]); }

TEST(SceneGltf, TrianglesInEveryContainer) {
    TempDir d;
    for (const std::string name : {"sep.gltf", "uri.gltf", "bin.glb"}) {
        for (bool indexed : {true, false}) {
            SCOPED_TRACE(name + (indexed ? " indexed" : " not indexed"));
            ModelBuilder b;
            b.mesh_node(b.square(indexed, false));
            const std::string path = b.write(d, name, name == "uri.gltf");
            if (name == "sep.gltf") {
                EXPECT_TRUE(std::filesystem::exists(d.path("sep.bin")));
            }
            if (name == "uri.gltf") {
                EXPECT_FALSE(std::filesystem::exists(d.path("uri.bin")));
            }
            Scene s;
            EXPECT_FALSE(load_gltf(path, s));
            ASSERT_EQ(s.triangle_count(), 2u);
            EXPECT_EQ(s.vertices[1], glm::vec3(1, 0, 0));
            EXPECT_EQ(s.vertices[5], glm::vec3(0, 1, 0));
            // No NORMAL: flat (glTF's rule), and `facet info` says so.
            EXPECT_EQ(v3(s.shading[0].n0), glm::vec3(0, 0, 1));
            ASSERT_EQ(s.normal_sources.size(), 1u);
            EXPECT_NE(s.normal_sources[0].find("6 flat (no NORMAL attribute"), std::string::npos);
            ASSERT_EQ(s.materials.size(), 1u);  // glTF's default material
            EXPECT_EQ(s.material_names[0], "gltf_default");
        }
    }
}

TEST(SceneGltf, NormalsNodeHierarchyAndInstancing) {
    TempDir d;
    ModelBuilder b;
    const int mesh = b.square(true, true);
    // parent: translate (10, 0, 0); child: rotate 90 degrees about +y, scale 2; the mesh
    // is used by the child and by a second root node (translated (0, 5, 0)).
    tinygltf::Node child;
    child.mesh = mesh;
    const double h = std::sqrt(0.5);
    child.rotation = {0, h, 0, h};
    child.scale = {2, 2, 2};
    const int c = b.node(child, false);
    tinygltf::Node parent;
    parent.translation = {10, 0, 0};
    parent.children = {c};
    b.node(parent);
    tinygltf::Node matrix;
    matrix.mesh = mesh;
    matrix.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1};
    b.node(matrix);
    const std::string path = b.write(d, "tree.gltf");
    Scene shared;  // the mesh stored once, two instances (tests/instancing_test.cpp traces them)
    load_gltf(path, shared);
    EXPECT_EQ(shared.triangle_count(), 0u);
    ASSERT_EQ(shared.meshes.size(), 1u);
    EXPECT_EQ(shared.meshes[0].triangle_count(), 2u);
    EXPECT_EQ(shared.instances.size(), 2u);
    Scene s;
    GltfLoadOptions copied;
    copied.instancing = false;
    load_gltf(path, s, copied);
    ASSERT_EQ(s.triangle_count(), 4u);  // copied: two copies of the two triangles
    // (1, 0, 0) -> scale (2, 0, 0) -> rotate about y: (0, 0, -2) -> translate (10, 0, -2).
    EXPECT_NEAR(glm::length(s.vertices[1] - glm::vec3(10, 0, -2)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(v3(s.shading[0].n0) - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);  // +x rotated
    EXPECT_EQ(s.vertices[7], glm::vec3(1, 5, 0));
    EXPECT_EQ(v3(s.shading[2].n0), glm::vec3(1, 0, 0));  // the file's normals
    EXPECT_NE(s.normal_sources[0].find("12 corners from the file"), std::string::npos);
    EXPECT_EQ(s.materials.size(), 1u);  // one material for every copy
}

TEST(SceneGltf, CameraAndPunctualLights) {
    TempDir d;
    ModelBuilder b;
    b.mesh_node(b.square(true, false));
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.perspective.yfov = M_PI / 4;
    cam.perspective.znear = 0.1;
    cam.perspective.aspectRatio = 2.0;
    b.m.cameras.push_back(cam);
    tinygltf::Node cn;
    cn.camera = 0;
    cn.translation = {0.5, 0.5, 5};
    b.node(cn);
    const char* types[] = {"point", "spot", "directional"};
    for (int i = 0; i < 3; ++i) {
        tinygltf::Light l;
        l.type = types[i];
        l.color = {1, 0.5, 0.25};
        l.intensity = M_PI;
        l.spot.innerConeAngle = 0.1;
        l.spot.outerConeAngle = 0.5;
        b.m.lights.push_back(l);
        tinygltf::Node ln;
        ln.translation = {double(i), 2, 0};
        ln.rotation = {-std::sqrt(0.5), 0, 0, std::sqrt(0.5)};  // -90 degrees about x: -z -> -y
        tinygltf::Value::Object o;
        o["light"] = tinygltf::Value(i);
        ln.extensions["KHR_lights_punctual"] = tinygltf::Value(o);
        b.node(ln);
    }
    b.m.extensionsUsed.push_back("KHR_lights_punctual");
    const Scene s = load_scene(b.write(d, "lit.glb"));
    EXPECT_EQ(s.camera.eye, glm::vec3(0.5f, 0.5f, 5.0f));
    EXPECT_NEAR(glm::length(s.camera.target - glm::vec3(0.5f, 0.5f, 4.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(s.camera.fov_y_degrees, 45.0f, 1e-4f);
    EXPECT_EQ(s.settings.height, s.settings.width / 2);
    ASSERT_EQ(s.punctual_lights.size(), 3u);
    EXPECT_EQ(s.triangle_count(), 2u);  // lights of its own: no default light
    for (int i = 0; i < 3; ++i) {
        const PunctualLight& l = s.punctual_lights[std::size_t(i)];
        EXPECT_NEAR(glm::length(l.color - glm::vec3(1, 0.5f, 0.25f)), 0.0f, 1e-6f);  // intensity pi -> c_light 1
        EXPECT_NEAR(glm::length(l.position - glm::vec3(float(i), 2, 0)), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(l.direction - glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
    }
    EXPECT_EQ(s.punctual_lights[0].type, FC_LIGHT_POINT);
    EXPECT_EQ(s.punctual_lights[1].type, FC_LIGHT_SPOT);
    EXPECT_NEAR(s.punctual_lights[1].outer_degrees, 0.5f * 180.0f / float(M_PI), 1e-4f);
    EXPECT_EQ(s.punctual_lights[2].type, FC_LIGHT_DIRECTIONAL);
    EXPECT_EQ(s.lights.size(), 3u);
}

TEST(SceneGltf, CameraChosenByName) {
    TempDir d;
    ModelBuilder b;
    b.mesh_node(b.square(true, false));
    for (int i = 0; i < 2; ++i) {
        tinygltf::Camera cam;
        cam.type = "perspective";
        cam.name = i == 0 ? "front" : "side";
        cam.perspective.yfov = i == 0 ? M_PI / 4 : M_PI / 3;
        cam.perspective.znear = 0.1;
        b.m.cameras.push_back(cam);
        tinygltf::Node cn;
        cn.camera = i;
        cn.translation = {double(i), 0.5, 5};
        b.node(cn);
    }
    const std::string file = b.write(d, "two_cameras.gltf");
    EXPECT_EQ(load_scene(file).camera.eye, glm::vec3(0.0f, 0.5f, 5.0f));  // the first by default
    const Scene side = load_scene(file, "side");
    EXPECT_EQ(side.camera.eye, glm::vec3(1.0f, 0.5f, 5.0f));
    EXPECT_NEAR(side.camera.fov_y_degrees, 60.0f, 1e-4f);
    for (const std::string& w : side.warnings) EXPECT_EQ(w.find("every camera but the first"), std::string::npos) << w;
    expect_error([&] { load_scene(file, "top"); }, {"two_cameras.gltf", "--camera top", "'front', 'side'"});
    expect_error([&] { load_scene(test::scenes_dir() + "/cornell_box.json", "front"); },
                 {"cornell_box.json", "only glTF files name their cameras"});
}

TEST(SceneGltf, MaterialsMappedOntoFacetModels) {
    TempDir d;
    ModelBuilder b;
    auto material = [&](const char* name, std::vector<double> base, double metallic, double roughness) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = std::move(base);
        m.pbrMetallicRoughness.metallicFactor = metallic;
        m.pbrMetallicRoughness.roughnessFactor = roughness;
        b.m.materials.push_back(m);
        b.mesh_node(b.square(true, false, int(b.m.materials.size() - 1)));
        return &b.m.materials.back();
    };
    material("gold", {1, 0.7, 0.3, 1}, 1, 0.2);
    material("plastic", {0.8, 0.1, 0.1, 0.4}, 0, 0.5)->alphaMode = "BLEND";
    tinygltf::Value::Object ior, transmission, strength, iridescence;
    ior["ior"] = tinygltf::Value(1.33);
    transmission["transmissionFactor"] = tinygltf::Value(1.0);
    strength["emissiveStrength"] = tinygltf::Value(10.0);
    iridescence["iridescenceFactor"] = tinygltf::Value(1.0);
    tinygltf::Material* glass = material("water", {0.9, 1, 1, 1}, 0, 0.1);
    glass->extensions["KHR_materials_ior"] = tinygltf::Value(ior);
    glass->extensions["KHR_materials_transmission"] = tinygltf::Value(transmission);
    tinygltf::Material* lamp = material("lamp", {1, 1, 1, 1}, 0, 1);
    lamp->emissiveFactor = {1, 0.5, 0};
    lamp->extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strength);
    lamp->extensions["KHR_materials_iridescence"] = tinygltf::Value(iridescence);
    lamp->occlusionTexture.index = 0;
    lamp->alphaMode = "MASK";
    lamp->alphaCutoff = 0.25;
    b.m.extensionsUsed = {"KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_emissive_strength",
                          "KHR_materials_iridescence"};
    Scene s;
    load_gltf(b.write(d, "mat.gltf"), s);
    ASSERT_EQ(s.materials.size(), 4u);
    const Material& gold = s.materials[0];
    EXPECT_EQ(gold.diffuse_model, FC_DIFFUSE_NONE);
    EXPECT_EQ(gold.specular_model, FC_SPECULAR_MICROFACET);
    EXPECT_EQ(gold.ndf, FC_NDF_GGX);
    EXPECT_NEAR(glm::length(gold.f0 - glm::vec3(1, 0.7f, 0.3f)), 0.0f, 1e-6f);
    EXPECT_NEAR(gold.alpha_x, 0.04f, 1e-6f);  // roughness^2
    const Material& plastic = s.materials[1];
    EXPECT_EQ(plastic.diffuse_model, FC_DIFFUSE_LAMBERT_1MF0);
    EXPECT_NEAR(glm::length(plastic.diffuse - glm::vec3(0.8f, 0.1f, 0.1f)), 0.0f, 1e-6f);
    EXPECT_NEAR(plastic.f0.x, 0.04f, 1e-6f);  // ((1.5 - 1) / (1.5 + 1))^2
    EXPECT_NEAR(plastic.alpha_y, 0.25f, 1e-6f);
    const Material& water = s.materials[2];
    EXPECT_EQ(water.specular_model, FC_SPECULAR_DIELECTRIC);
    EXPECT_NEAR(water.ior, 1.33f, 1e-6f);
    EXPECT_NEAR(water.alpha_x, 0.01f, 1e-6f);
    EXPECT_NEAR(glm::length(water.transmittance - glm::vec3(0.9f, 1, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(s.materials[3].emission - glm::vec3(10, 5, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(s.material_names[3], "lamp");
    // alphaMode: OPAQUE ignores the base colour's alpha, MASK cuts at alphaCutoff, BLEND is
    // stochastic transparency of the base colour's alpha.
    EXPECT_EQ(gold.alpha_mode, FC_ALPHA_OPAQUE);
    EXPECT_EQ(plastic.alpha_mode, FC_ALPHA_BLEND);
    EXPECT_NEAR(plastic.alpha, 0.4f, 1e-6f);
    EXPECT_EQ(s.materials[3].alpha_mode, FC_ALPHA_MASK);
    EXPECT_NEAR(s.materials[3].alpha_cutoff, 0.25f, 1e-6f);
    // What is not read is named.
    for (const char* ignored : {"occlusionTexture", "materials[3] 'lamp'",
                                "material extension KHR_materials_iridescence", "extension KHR_materials_iridescence"})
        EXPECT_TRUE(test::contains(s.warnings, ignored)) << ignored;
    EXPECT_FALSE(test::contains(s.warnings, "alphaMode")) << "MASK and BLEND are read";
    // An extension the file requires and facet does not read is an error.
    b.m.extensionsRequired = {"KHR_materials_iridescence"};
    expect_error([&] { load_scene(b.write(d, "req.gltf")); },
                 {"req.gltf", "requires the extension KHR_materials_iridescence"});
}

// KHR_materials_clearcoat and KHR_materials_sheen onto the layers: alpha = roughness^2, the
// sheen colour as written, the layers left off a transmissive material, and a factor out of
// range or a texture that does not exist named by its JSON path.
TEST(SceneGltf, ClearcoatAndSheenLayers) {
    TempDir d;
    auto build = [](double clearcoat, std::vector<double> sheen, bool normal_texture = false) {
        ModelBuilder b;
        tinygltf::Value::Object cc, sh, tex;
        cc["clearcoatFactor"] = tinygltf::Value(clearcoat);
        cc["clearcoatRoughnessFactor"] = tinygltf::Value(0.5);
        tex["index"] = tinygltf::Value(0);
        if (normal_texture) cc["clearcoatNormalTexture"] = tinygltf::Value(tex);  // no texture 0
        tinygltf::Value::Array colour;
        for (double c : sheen) colour.push_back(tinygltf::Value(c));
        sh["sheenColorFactor"] = tinygltf::Value(colour);
        sh["sheenRoughnessFactor"] = tinygltf::Value(0.25);
        for (bool glass : {false, true}) {
            tinygltf::Material m;
            m.name = glass ? "glass" : "coated";
            m.pbrMetallicRoughness.baseColorFactor = {0.5, 0.5, 0.5, 1};
            m.pbrMetallicRoughness.metallicFactor = 0.0;
            m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(cc);
            m.extensions["KHR_materials_sheen"] = tinygltf::Value(sh);
            if (glass) {
                tinygltf::Value::Object t;
                t["transmissionFactor"] = tinygltf::Value(1.0);
                m.extensions["KHR_materials_transmission"] = tinygltf::Value(t);
            }
            b.m.materials.push_back(m);
            b.mesh_node(b.square(true, false, int(b.m.materials.size() - 1)));
        }
        b.m.extensionsUsed = {"KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_transmission"};
        b.m.extensionsRequired = {"KHR_materials_clearcoat", "KHR_materials_sheen"};
        return b;
    };
    Scene s;
    load_gltf(build(0.75, {0.2, 0.4, 0.6}).write(d, "layers.gltf"), s);
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& coated = s.materials[0];
    EXPECT_FLOAT_EQ(coated.clearcoat, 0.75f);
    EXPECT_FLOAT_EQ(coated.clearcoat_alpha, 0.25f);  // roughness^2
    EXPECT_NEAR(glm::length(coated.sheen - glm::vec3(0.2f, 0.4f, 0.6f)), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(coated.sheen_roughness, 0.25f);
    EXPECT_EQ(s.materials[1].clearcoat, 0.0f);
    EXPECT_EQ(s.materials[1].sheen, glm::vec3(0.0f));
    for (const char* warning : {"KHR_materials_sheen on a transmissive material", "materials[1] 'glass'"})
        EXPECT_TRUE(test::contains(s.warnings, warning)) << warning;
    EXPECT_FALSE(test::contains(s.warnings, "material extension KHR_materials_clearcoat"));
    expect_error(
        [&] {
            load_scene(build(0.75, {0.2, 0.4, 0.6}, true).write(d, "normal.gltf"));
        },
        {"normal.gltf", "extensions.KHR_materials_clearcoat.clearcoatNormalTexture names texture 0"});
    expect_error(
        [&] {
            load_scene(build(1.5, {0, 0, 0}).write(d, "coat.gltf"));
        },
        {"coat.gltf", "materials[0].extensions.KHR_materials_clearcoat.clearcoatFactor", "[0, 1]", "1.5"});
    expect_error(
        [&] {
            load_scene(build(1, {0, 2, 0}).write(d, "sheen.gltf"));
        },
        {"sheen.gltf", "materials[0].extensions.KHR_materials_sheen.sheenColorFactor[1]", "[0, 1]"});
}

TEST(SceneGltf, InJsonScene) {
    TempDir d;
    ModelBuilder b;
    b.mesh_node(b.square(true, false));
    b.write(d, "m.glb");
    const Scene s = load_scene(test::scene(d, "s.json", R"("materials": {"red": {"diffuse": [0.8, 0, 0]}},
        "meshes": [{"file": "m.glb", "material": "red", "transform": {"translate": [0, 0, 2]}}])"));
    ASSERT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.vertices[0], glm::vec3(0, 0, 2));
    EXPECT_EQ(s.shading[0].material, 0);
}

TEST(SceneGltf, MalformedFilesNameTheProblem) {
    TempDir d;
    {
        ModelBuilder b;
        b.mesh_node(b.square(true, false));
        b.m.accessors[1].count = 7;  // 7 indices in a 12-byte view
        expect_error([&] { load_scene(b.write(d, "overrun.gltf")); },
                     {"overrun.gltf", "meshes[0].primitives[0].indices: accessor 1", "overrun"});
    }
    {
        ModelBuilder b;
        b.mesh_node(b.square(true, false));
        std::uint16_t bad = 9;
        std::memcpy(b.m.buffers[0].data.data() + b.m.bufferViews[1].byteOffset + 2, &bad, 2);
        expect_error([&] { load_scene(b.write(d, "index.glb")); }, {"index.glb", "index 1 is 9", "4 vertices"});
    }
    {
        ModelBuilder b;
        b.mesh_node(b.square(true, false));
        const float inf = INFINITY;
        std::memcpy(b.m.buffers[0].data.data() + 4, &inf, 4);
        expect_error([&] { load_scene(b.write(d, "inf.gltf")); }, {"inf.gltf", "POSITION", "not finite"});
    }
    {
        ModelBuilder b;
        const int n = b.mesh_node(b.square(true, false));
        b.m.nodes[std::size_t(n)].children = {n};
        expect_error([&] { load_scene(b.write(d, "cycle.gltf")); }, {"cycle.gltf", "nodes[0]", "cycle"});
    }
    {
        ModelBuilder b;
        b.mesh_node(b.square(true, false));
        b.write(d, "gone.gltf");
        std::filesystem::remove(d.path("gone.bin"));
        expect_error([&] { load_scene(d.path("gone.gltf")); }, {"gone.gltf", "not a valid glTF"});
    }
    expect_error([&] { load_scene(d.write("text.gltf", "{\"asset\": ")); }, {"text.gltf", "not a valid glTF"});
    expect_error([&] { load_scene(d.write("text.glb", "glTF but not really")); }, {"text.glb", "not a valid glTF"});
}

TEST(SceneGltf, DemoSceneLoads) {
    const Scene s = load_scene(test::scenes_dir() + "/gltf_materials.gltf");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_EQ(s.triangle_count(), 2u + 3u * 12u + 2u);  // floor, three cubes, the panel
    ASSERT_EQ(s.materials.size(), 5u);
    EXPECT_EQ(s.material_names[3], "glass");
    EXPECT_EQ(s.materials[3].specular_model, FC_SPECULAR_DIELECTRIC);
    EXPECT_EQ(s.materials[1].diffuse_model, FC_DIFFUSE_NONE);  // gold: a conductor
    EXPECT_EQ(s.punctual_lights.size(), 1u);
    EXPECT_EQ(s.camera.eye, glm::vec3(0.0f, 2.0f, 5.0f));
    EXPECT_EQ(s.settings.height, 341);  // 512 / 1.5
    EXPECT_EQ(s.lights.size(), 3u);     // the panel's two triangles and the point light
}

// Debian's assimp-testmodels: the malformed files give an error naming the file, the
// others load (with their textures, or an error naming the file when an image cannot be
// read); none crashes.
TEST(SceneGltf, AssimpTestModels) {
    const std::filesystem::path root = "/usr/share/assimp/models/glTF2";
    if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
    const std::vector<std::string> malformed = {"IndexOutOfRange/IndexOutOfRange.gltf",
                                                "IndexOutOfRange/AllIndicesOutOfRange.gltf",
                                                "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
                                                "MissingBin/BoxTextured.gltf",
                                                "RecursiveNodes/RecursiveNodes.gltf",
                                                "SchemaFailures/sceneWrongType.gltf",
                                                "wrongTypes/badArray.gltf",
                                                "wrongTypes/badNumber.gltf"};
    for (const std::string& rel : malformed) {
        SCOPED_TRACE(rel);
        expect_error([&] { load_scene((root / rel).string()); }, {(root / rel).string()});
    }
    int loaded = 0, refused = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        try {
            const Scene s = load_scene(entry.path().string());
            EXPECT_GT(s.triangle_count(), 0u);
            ++loaded;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(entry.path().string()), std::string::npos) << e.what();
            ++refused;
        }
    }
    EXPECT_GT(loaded, 10);
    std::printf("assimp-testmodels glTF2: %d loaded, %d refused with an error\n", loaded, refused);
}

}  // namespace
}  // namespace facet
