// Scene.*: JSON scene files, their schema checks and error messages.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "host/readers/load_scene.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::expect_error;
using test::TempDir;

const std::string kTri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const std::string kQuadShape = R"({"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0]})";

using test::scene;

TEST(SceneJson, JsonFullSceneLoads) {
    TempDir d;
    d.write("m.mtl", "newmtl red\nKd 1 0 0\n");
    d.write("mesh.obj", "mtllib m.mtl\nusemtl red\n" + kTri);
    const auto p = scene(d, "s.json", R"(
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 30,
             "projection": "orthographic", "height": 3},
  "render": {"width": 64, "height": 32, "spp": 4, "max_depth": 5, "rr_depth": 2, "seed": 7, "roulette_gain": 3},
  "materials": {"lamp": {"model": "lambert", "diffuse": [0, 0, 0], "emission": [2, 2, 2],
                         "two_sided_emission": true},
                "blue": {"diffuse": [0, 0, 1], "roughness": 0.3, "ior": 1.4}},
  "meshes": [{"file": "mesh.obj", "transform": {"scale": 2, "rotate": [90, 0, 0, 1],
                                               "translate": [10, 0, 0]}},
             {"file": "mesh.obj", "materials": {"red": "blue"}}],
  "shapes": [{"type": "sphere", "center": [0, 5, 0], "radius": 0.5, "subdivisions": 1, "tessellate": true,
              "material": "lamp"},
             {"type": "quad", "corner": [0, 0, -1], "edge1": [1, 0, 0], "edge2": [0, 1, 0]}])");
    const Scene s = load_scene(p);
    EXPECT_TRUE(s.warnings.empty());
    ASSERT_EQ(s.triangle_count(), 1u + 1u + 80u + 2u);
    EXPECT_EQ(s.camera.projection, FC_PROJECTION_ORTHOGRAPHIC);
    EXPECT_FLOAT_EQ(s.camera.ortho_height, 3.0f);
    EXPECT_FLOAT_EQ(s.camera.fov_y_degrees, 30.0f);
    EXPECT_EQ(s.settings.width, 64);
    EXPECT_EQ(s.settings.height, 32);
    EXPECT_EQ(s.settings.seed, 7u);
    EXPECT_EQ(s.settings.rr_depth, 2);
    EXPECT_EQ(s.settings.roulette_gain, 3.0f);
    // Scale 2, then 90 degrees about z, then +10 in x: (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0).
    EXPECT_NEAR(glm::length(s.vertices[1] - glm::vec3(10, 2, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(s.material_names[static_cast<std::size_t>(s.shading[0].material)], "red");
    EXPECT_EQ(s.material_names[static_cast<std::size_t>(s.shading[1].material)], "blue");
    EXPECT_EQ(s.lights.size(), 80u);
    auto material = [&](const std::string& name) {
        for (std::size_t i = 0; i < s.materials.size(); ++i) {
            if (s.material_names[i] == name) return s.materials[i];
        }
        ADD_FAILURE() << "no material " << name;
        return Material{};
    };
    EXPECT_TRUE(material("lamp").two_sided_emission);
    EXPECT_FLOAT_EQ(material("blue").alpha_y, 0.3f);
    EXPECT_FLOAT_EQ(material("blue").ior, 1.4f);
}

TEST(SceneJson, JsonSyntaxErrorNamesLineAndColumn) {
    TempDir d;
    const auto p = d.write("broken.json", "{\n  \"render\": {\"width\": 64\n  \"spp\": 4}\n}\n");
    expect_error([&] { load_scene(p); }, {"broken.json:3:", "syntax error"});
    const auto q = d.write("trunc.json", "{\"render\": ");
    expect_error([&] { load_scene(q); }, {"trunc.json:1:"});
}

TEST(SceneJson, JsonUnknownKeys) {
    TempDir d;
    expect_error([&] { load_scene(scene(d, "a.json", R"("materails": {})")); },
                 {"a.json", "unknown key 'materails' at top level", "did you mean 'materials'"});
    expect_error([&] { load_scene(scene(d, "b.json", R"("camera": {"fvo": 30}, "shapes": [)" + kQuadShape + "]")); },
                 {"b.json", "'fvo'", "camera", "'fov'"});
    expect_error(
        [&] {
            load_scene(scene(
                d, "c.json",
                R"("shapes": [{"type": "quad", "corner": [0,0,0], "edge1": [1,0,0], "edge2": [0,1,0], "colour": 1}])"));
        },
        {"c.json", "'colour'", "shapes[0]"});
}

TEST(SceneJson, JsonBadTypesAndValues) {
    TempDir d;
    const std::string shapes = R"(, "shapes": [)" + kQuadShape + "]";
    struct Case {
        std::string body, path;
    };
    const Case cases[] = {
        {R"("camera": {"fov": "wide"})", "camera.fov"},
        {R"("camera": {"fov": 200})", "camera.fov"},
        {R"("camera": {"fov": 0})", "camera.fov"},
        {R"("camera": {"eye": [1, 2]})", "camera.eye"},
        {R"("camera": {"projection": "fisheye"})", "camera.projection"},
        {R"("camera": {"eye": [0, 0, 0], "target": [0, 0, 0]})", "camera"},
        {R"("render": {"width": 0})", "render.width"},
        {R"("render": {"height": 20000})", "render.height"},
        {R"("render": {"spp": 0})", "render.spp"},
        {R"("render": {"spp": 2.5})", "render.spp"},
        {R"("render": {"max_depth": 2000})", "render.max_depth"},
        {R"("render": 5)", "render"},
        {R"("materials": {"m": {"diffuse": [0.5, -0.1, 0.5]}})", "materials.m.diffuse"},
        {R"("materials": {"m": {"emission": [1, 1, "x"]}})", "materials.m.emission[2]"},
        {R"("materials": {"m": {"model": "phong"}})", "materials.m.model"},
        {R"("materials": {"m": {"two_sided_emission": 1}})", "materials.m.two_sided_emission"},
        {R"("materials": {"m": {"roughness": 1.5}})", "materials.m.roughness"},
        {R"("meshes": {"file": "x.obj"})", "meshes"},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string name = "bad" + std::to_string(i++) + ".json";
        expect_error([&] { load_scene(scene(d, name, c.body + shapes)); }, {name + ": " + c.path});
    }
    expect_error(
        [&] { load_scene(scene(d, "r.json", R"("shapes": [{"type": "sphere", "center": [0,0,0], "radius": -1}])")); },
        {"r.json: shapes[0].radius"});
    expect_error([&] { load_scene(scene(d, "s.json", R"("shapes": [{"type": "cone"}])")); },
                 {"s.json: shapes[0].type", "cone"});
    expect_error(
        [&] {
            load_scene(scene(d, "t.json",
                             R"("shapes": [{"type": "quad", "corner": [0,0,0], "edge1": [1,0,0], "edge2": [2,0,0]}])"));
        },
        {"t.json: shapes[0]"});
    expect_error([&] { load_scene(scene(d, "u.json", R"("render": {"spp": 4})")); }, {"u.json", "no geometry"});
}

// "clearcoat", "clearcoat_roughness", "sheen" and "sheen_roughness": glTF's layers, alpha =
// roughness^2, each value checked with its path, and refused on a dielectric; "specular_f90" on a
// Schlick microfacet lobe; the layers' textures need their factors.
TEST(SceneJson, ClearcoatAndSheenKeys) {
    TempDir d;
    const std::string shapes = R"(, "shapes": [)" + kQuadShape + "]";
    const Scene s = load_scene(scene(d, "layers.json",
                                     R"("materials": {"m": {"model": "ggx", "metallic": 0.5,
        "clearcoat": 0.8, "clearcoat_roughness": 0.3, "sheen": [0.1, 0.2, 0.3], "sheen_roughness": 0.6,
        "specular_f90": 0.25}})" + shapes));
    ASSERT_FALSE(s.materials.empty());
    const Material& m = s.materials[0];
    EXPECT_FLOAT_EQ(m.clearcoat, 0.8f);
    EXPECT_NEAR(m.clearcoat_alpha, 0.09f, 1e-6f);
    EXPECT_NEAR(glm::length(m.sheen - glm::vec3(0.1f, 0.2f, 0.3f)), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(m.sheen_roughness, 0.6f);
    EXPECT_FLOAT_EQ(m.specular_f90, 0.25f);
    struct Case {
        std::string body, path, problem;
    };
    const Case cases[] = {
        {R"("materials": {"m": {"clearcoat": 1.2}})", "materials.m.clearcoat", "1.2"},
        {R"("materials": {"m": {"clearcoat_roughness": -0.1}})", "materials.m.clearcoat_roughness", "-0.1"},
        {R"("materials": {"m": {"sheen": [0.5, 1.5, 0]}})", "materials.m.sheen", "at most 1"},
        {R"("materials": {"m": {"sheen": 0.5}})", "materials.m.sheen", ""},
        {R"("materials": {"m": {"sheen_roughness": "rough"}})", "materials.m.sheen_roughness", ""},
        {R"("materials": {"m": {"model": "dielectric", "clearcoat": 1}})", "materials.m.clearcoat", "transmit"},
        {R"("materials": {"m": {"model": "ggx", "specular_f90": 1.5}})", "materials.m.specular_f90", "1.5"},
        {R"("materials": {"m": {"model": "lambert", "specular_f90": 0.5}})", "materials.m.specular_f90", "schlick"},
        {R"("materials": {"m": {"model": "ggx", "textures": {"clearcoat": "c.png"}}})",
         "materials.m.textures.clearcoat", "\"clearcoat\" above 0"},
        {R"("materials": {"m": {"model": "ggx", "textures": {"sheen_roughness": "s.png"}}})",
         "materials.m.textures.sheen_roughness", "\"sheen\" above 0"},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string name = "layers" + std::to_string(i++) + ".json";
        expect_error([&] { load_scene(scene(d, name, c.body + shapes)); }, {name + ": " + c.path, c.problem});
    }
}

// "anisotropy" and "anisotropy_rotation" (degrees): glTF's anisotropy strength and rotation
// (radians on the Material), each value checked with its path.
TEST(SceneJson, AnisotropyKeys) {
    TempDir d;
    const std::string shapes = R"(, "shapes": [)" + kQuadShape + "]";
    const Scene s = load_scene(scene(d, "aniso.json",
                                     R"("materials": {"m": {"model": "ggx", "metallic": 1,
        "anisotropy": 0.7, "anisotropy_rotation": 90}})" +
                                         shapes));
    ASSERT_FALSE(s.materials.empty());
    EXPECT_FLOAT_EQ(s.materials[0].anisotropy, 0.7f);
    EXPECT_NEAR(s.materials[0].anisotropy_rotation, 1.5707963f, 1e-6f);
    EXPECT_TRUE(material_is_anisotropic(s.materials[0]));
    struct Case {
        std::string body, path, problem;
    };
    const Case cases[] = {
        {R"("materials": {"m": {"anisotropy": 1.5}})", "materials.m.anisotropy", "1.5"},
        {R"("materials": {"m": {"anisotropy_rotation": "left"}})", "materials.m.anisotropy_rotation", ""},
        {R"("materials": {"m": {"anisotropy_rotation": 720}})", "materials.m.anisotropy_rotation", "720"},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string name = "aniso" + std::to_string(i++) + ".json";
        expect_error([&] { load_scene(scene(d, name, c.body + shapes)); }, {name + ": " + c.path, c.problem});
    }
}

TEST(SceneJson, JsonUnknownMaterial) {
    TempDir d;
    d.write("tri.obj", kTri);
    expect_error(
        [&] {
            load_scene(scene(d, "a.json",
                             R"("materials": {"white": {}}, "meshes": [{"file": "tri.obj", "material": "whte"}])"));
        },
        {"a.json: meshes[0].material", "'whte'", "'white'"});
    expect_error(
        [&] {
            load_scene(scene(d, "b.json",
                             R"("shapes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "x"}])"));
        },
        {"b.json: shapes[0].material", "'x'"});
}

TEST(SceneJson, JsonMissingMeshFile) {
    TempDir d;
    expect_error([&] { load_scene(scene(d, "a.json", R"("meshes": [{"file": "models/gone.obj"}])")); },
                 {"a.json", "meshes[0].file", "models/gone.obj"});
    d.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    expect_error([&] { load_scene(scene(d, "b.json", R"("meshes": [{"file": "bad.obj"}])")); },
                 {"b.json", "meshes[0]", "bad.obj:4:"});
}

TEST(SceneJson, JsonMeshNormalRule) {
    TempDir d;
    d.write("fold.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 2\nf 1 2 3\nf 1 4 2\n");
    const Scene flat = load_scene(scene(d, "a.json", R"("meshes": [{"file": "fold.obj"}])"));
    EXPECT_NEAR(flat.shading[0].n0[2], 1.0f, 1e-6f);
    const Scene smooth = load_scene(scene(d, "b.json", R"("meshes": [{"file": "fold.obj", "normals": "smooth"}])"));
    EXPECT_NEAR(smooth.shading[0].n0[2], glm::normalize(glm::vec3(0, 2, 1)).z, 1e-6f);
    expect_error([&] { load_scene(scene(d, "c.json", R"("meshes": [{"file": "fold.obj", "normals": "soft"}])")); },
                 {"c.json: meshes[0].normals", "unknown normal rule 'soft'"});
}

TEST(SceneJson, JsonWithoutCameraFramesTheScene) {
    TempDir d;
    const Scene s = load_scene(scene(d, "a.json", R"("shapes": [)" + kQuadShape + "]"));
    EXPECT_EQ(s.camera.target, glm::vec3(0.5f, 0.5f, 0.0f));
    EXPECT_TRUE(test::contains(s.warnings, "no emitters"));
}

TEST(SceneJson, UnknownExtensionIsError) {
    TempDir d;
    expect_error([&] { load_scene(d.write("scene.xml", "<scene/>")); }, {"scene.xml", ".xml"});
}

}  // namespace
}  // namespace facet
