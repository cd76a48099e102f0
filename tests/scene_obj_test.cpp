// Scene.*: OBJ and MTL loading, normals, and the errors malformed files give.
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/readers/load_scene.hpp"
#include "host/readers/obj_reader.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::expect_error;
using test::TempDir;
using test::vec;

Scene load(const std::string& path) {
    Scene s;
    load_obj(path, s);
    return s;
}

TEST(SceneObj, ObjBadNumberNamesLine) {
    TempDir d;
    const auto p = d.write("bad.obj", "# comment\nv 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(p); }, {"bad.obj:3:", "abc"});
    const auto q = d.write("short.obj", "v 0 0 0\nv 1 0\nf 1 2 1\n");
    expect_error([&] { load(q); }, {"short.obj:2:", "3 numbers"});
    const auto r = d.write("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 x1\nf 1 2 3\n");
    expect_error([&] { load(r); }, {"vn.obj:4:"});
}

TEST(SceneObj, ObjBadIndicesNameLine) {
    TempDir d;
    const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expect_error([&] { load(d.write("a.obj", verts + "f 1 2 4\n")); }, {"a.obj:4:", "out of range"});
    expect_error([&] { load(d.write("b.obj", verts + "f 0 1 2\n")); }, {"b.obj:4:", "index 0"});
    expect_error([&] { load(d.write("c.obj", verts + "f 1 2\n")); }, {"c.obj:4:", "at least 3"});
    expect_error([&] { load(d.write("d.obj", verts + "f -4 -3 -2\n")); }, {"d.obj:4:", "out of range"});
    expect_error([&] { load(d.write("e.obj", verts + "f 1//2 2//2 3//2\n")); }, {"e.obj:4:", "normal"});
    expect_error([&] { load(d.write("f.obj", verts + "f 1/x 2 3\n")); }, {"f.obj:4:", "not an integer"});
    expect_error([&] { load(d.write("g.obj", verts + "f 1/1/1/1 2 3\n")); }, {"g.obj:4:"});
}

TEST(SceneObj, ObjEmptyOrNonFiniteIsError) {
    TempDir d;
    expect_error([&] { load(d.write("empty.obj", "")); }, {"empty.obj", "no faces"});
    expect_error([&] { load(d.write("verts.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")); }, {"verts.obj", "no faces"});
    expect_error([&] { load(d.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")); }, {"nan.obj:2:"});
    expect_error([&] { load(d.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n")); }, {"inf.obj:3:"});
    expect_error([&] { load(d.path("does_not_exist.obj")); }, {"does_not_exist.obj"});
}

TEST(SceneObj, ObjCrlfQuadsNegativeIndices) {
    TempDir d;
    const auto p = d.write("q.obj",
                           "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf -4 -3 -2 -1\r\n"
                           "v 5 0 0\r\nv 6 0 0\r\nv 5 1 0\r\nf 5 -2 -1\r\n");
    const Scene s = load(p);
    ASSERT_EQ(s.triangle_count(), 3u);
    for (std::size_t t = 0; t < 3; ++t) EXPECT_NEAR(test::face_normal(s, t).z, 1.0f, 1e-6f);
    EXPECT_EQ(s.vertices[6], glm::vec3(5, 0, 0));
    EXPECT_EQ(s.vertices[8], glm::vec3(5, 1, 0));
    // Line numbers count CRLF lines correctly.
    expect_error([&] { load(d.write("bad.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 9\r\n")); }, {"bad.obj:4:"});
}

TEST(SceneObj, ObjSmoothNormalsInSmoothingGroup) {
    TempDir d;
    // Triangle A (area 0.5) faces +z, triangle B (area 1) faces +y; they share vertices 1 and 2.
    const auto p = d.write("fold.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 2\ns 1\nf 1 2 3\nf 1 4 2\n");
    const Scene s = load(p);
    ASSERT_EQ(s.triangle_count(), 2u);
    const glm::vec3 shared = glm::normalize(glm::vec3(0, 2, 1));  // area-weighted sum
    EXPECT_NEAR(glm::length(vec(s.shading[0].n0) - shared), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vec(s.shading[0].n1) - shared), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vec(s.shading[0].n2) - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vec(s.shading[1].n1) - glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
}

// Without normals, a face is smoothed only with faces of its own smoothing group; 's off',
// 's 0' or no 's' at all leave it flat (the 8-vertex cube stays a cube).
TEST(SceneObj, ObjSmoothingGroupsAndFlatFaces) {
    TempDir d;
    const std::string fold = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 2\n";
    const glm::vec3 up(0, 0, 1), side(0, 1, 0), shared = glm::normalize(glm::vec3(0, 2, 1));
    auto expect_corner = [](const Scene& s, std::size_t t, const float n[3], glm::vec3 want) {
        EXPECT_NEAR(glm::length(vec(n) - want), 0.0f, 1e-5f) << "triangle " << t;
    };
    for (const char* flat : {"", "s off\n", "s 0\n"}) {
        const Scene s = load(d.write("flat.obj", fold + flat + "f 1 2 3\nf 1 4 2\n"));
        expect_corner(s, 0, s.shading[0].n0, up);
        expect_corner(s, 1, s.shading[1].n0, side);
        ASSERT_EQ(s.normal_sources.size(), 1u);
        EXPECT_NE(s.normal_sources[0].find("6 flat (no normal in the file, smoothing off)"), std::string::npos)
            << s.normal_sources[0];
    }
    // Two groups: no smoothing across the fold.
    const Scene two = load(d.write("two.obj", fold + "s 1\nf 1 2 3\ns 2\nf 1 4 2\n"));
    expect_corner(two, 0, two.shading[0].n0, up);
    expect_corner(two, 1, two.shading[1].n0, side);
    // 's off' after a group ends it.
    const Scene off = load(d.write("off.obj", fold + "s 3\nf 1 2 3\ns off\nf 1 4 2\n"));
    expect_corner(off, 0, off.shading[0].n0, up);
    expect_corner(off, 1, off.shading[1].n0, side);
    // One group across both.
    const Scene one = load(d.write("one.obj", fold + "s 7\nf 1 2 3\nf 1 4 2\n"));
    expect_corner(one, 0, one.shading[0].n0, shared);
    ASSERT_EQ(one.normal_sources.size(), 1u);
    EXPECT_NE(one.normal_sources[0].find("one.obj: normals: 6 smoothed"), std::string::npos) << one.normal_sources[0];
    // The rule forced: smooth ignores 's off', flat ignores the file's normals.
    ObjLoadOptions smooth;
    smooth.normals = NormalRule::Smooth;
    Scene forced;
    load_obj(d.path("flat.obj"), forced, smooth);
    expect_corner(forced, 0, forced.shading[0].n0, shared);
    ObjLoadOptions flat;
    flat.normals = NormalRule::Flat;
    Scene ignored;
    load_obj(d.write("vn.obj", fold + "vn 1 0 0\nf 1//1 2//1 3//1\n"), ignored, flat);
    expect_corner(ignored, 0, ignored.shading[0].n0, up);
    EXPECT_NE(ignored.normal_sources[0].find("3 flat (\"normals\": \"flat\")"), std::string::npos);
}

TEST(SceneObj, ObjBadSmoothingGroupNamesLine) {
    TempDir d;
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (const char* bad : {"s on\n", "s -1\n", "s\n", "s 1 2\n"})
        expect_error([&] { load(d.write("s.obj", tri + bad + "f 1 2 3\n")); }, {"s.obj:4:", "'s' expects"});
}

TEST(SceneObj, ObjNormalsUsedWhenPresent) {
    TempDir d;
    const auto p = d.write("n.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nvn 0 0 0\n"
                           "f 1//1 2//1 3//2\n");
    const Scene s = load(p);
    EXPECT_NEAR(glm::length(vec(s.shading[0].n0) - glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vec(s.shading[0].n1) - glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vec(s.shading[0].n2) - glm::vec3(0, 0, 1)), 0.0f,
                1e-5f);  // zero: face normal
}

TEST(SceneObj, ObjTransformAndMirror) {
    TempDir d;
    const auto p = d.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Scene s;
    load_obj(p, s, glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)));
    EXPECT_EQ(s.vertices[1], glm::vec3(3, 2, 3));
    Scene m;
    load_obj(p, m, glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1)));  // a mirror along z
    const glm::vec3 n = test::face_normal(m, 0);
    EXPECT_NEAR(n.z, -1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(vec(m.shading[0].n0), n), 1.0f, 1e-6f);  // front face kept consistent
}

// A UTF-8 byte-order mark (Windows editors write one) is skipped in the OBJ and its MTL: it glued
// itself to the first keyword, and the OBJ's first vertex was dropped ("position index 3 is out of
// range"). UTF-16 text is refused, naming the file and the encoding.
TEST(SceneObj, Utf8ByteOrderMarkSkippedUtf16Refused) {
    TempDir d;
    const std::string bom = "\xEF\xBB\xBF";
    d.write("m.mtl", bom + "newmtl red\nKd 0.8 0.1 0.1\n");
    const auto p = d.write("bom.obj", bom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib m.mtl\nusemtl red\nf 1 2 3\n");
    const Scene s = load(p);
    EXPECT_TRUE(s.warnings.empty());
    ASSERT_EQ(s.triangle_count(), 1u);
    EXPECT_FLOAT_EQ(s.materials[static_cast<std::size_t>(s.shading[0].material)].diffuse[0], 0.8f);
    std::string utf16 = "\xFF\xFE";
    for (char c : std::string("v 0 0 0\n")) utf16 += std::string{c, '\0'};
    expect_error([&] { load(d.write("wide.obj", utf16)); }, {"wide.obj", "UTF-16"});
    d.write("wide.mtl", std::string("\xFE\xFF\0n", 4));
    expect_error([&] { load(d.write("lib.obj", "mtllib wide.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); },
                 {"wide.mtl", "UTF-16"});
}

TEST(SceneObj, MtlMaterialsMapped) {
    TempDir d;
    d.write("m.mtl",
            "newmtl shiny\nKd 0.1 0.2 0.3\nKs 0.5 0.5 0.5\nNs 98\nNi 1.33\n"
            "newmtl rough\nKd 0.7\nPr 0.25\nKe 1 2 3\nd 0.5\nillum 2\nPm 1\n");
    const auto p = d.write("m.obj",
                           "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n"
                           "usemtl rough\nf 1 2 3\n");
    const Scene s = load(p);
    EXPECT_TRUE(s.warnings.empty());
    ASSERT_EQ(s.triangle_count(), 2u);
    const Material& a = s.materials[static_cast<std::size_t>(s.shading[0].material)];
    const Material& b = s.materials[static_cast<std::size_t>(s.shading[1].material)];
    EXPECT_FLOAT_EQ(a.diffuse[2], 0.3f);
    EXPECT_FLOAT_EQ(a.ks[0], 0.5f);
    EXPECT_FLOAT_EQ(a.ior, 1.33f);
    EXPECT_NEAR(a.alpha_x, std::sqrt(2.0f / 100.0f), 1e-6f);
    EXPECT_FLOAT_EQ(a.alpha_y, a.alpha_x);
    // Ks + Ns: normalized Blinn-Phong. Pr/Pm: GGX, metallic 1 -> no diffuse, F0 = Kd,
    // alpha = Pr^2 (perceptual roughness).
    EXPECT_EQ(a.specular_model, FC_SPECULAR_BLINN_PHONG_NORMALIZED);
    EXPECT_FLOAT_EQ(a.exponent_x, 98.0f);
    EXPECT_EQ(b.specular_model, FC_SPECULAR_MICROFACET);
    EXPECT_EQ(b.ndf, FC_NDF_GGX);
    EXPECT_FLOAT_EQ(b.diffuse[1], 0.0f);
    EXPECT_FLOAT_EQ(b.f0[1], 0.7f);
    EXPECT_FLOAT_EQ(b.alpha_x, 0.0625f);
    EXPECT_FLOAT_EQ(b.emission[2], 3.0f);
    EXPECT_FLOAT_EQ(b.ior, 1.5f);
    // d 0.5: stochastic transparency of alpha 0.5; no d: opaque.
    EXPECT_EQ(a.alpha_mode, FC_ALPHA_OPAQUE);
    EXPECT_EQ(b.alpha_mode, FC_ALPHA_BLEND);
    EXPECT_FLOAT_EQ(b.alpha, 0.5f);
}

// The PBR extension's layers: Pc (clearcoat weight), Pcr (its roughness, alpha = Pcr^2)
// and Ps (a grey sheen of roughness 0.5) map onto glTF's clearcoat and sheen; they make a
// material a PBR one even without Pr or Pm; out of [0, 1] names the line.
TEST(SceneObj, MtlClearcoatAndSheen) {
    TempDir d;
    d.write("m.mtl", "newmtl car\nKd 0.8 0.1 0.1\nPc 1\nPcr 0.3\nnewmtl velvet\nKd 0.2 0.2 0.6\nPr 0.8\nPs 0.5\n");
    const auto p =
        d.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl car\nf 1 2 3\nusemtl velvet\nf 1 2 3\n");
    const Scene s = load(p);
    const Material& car = s.materials[static_cast<std::size_t>(s.shading[0].material)];
    const Material& velvet = s.materials[static_cast<std::size_t>(s.shading[1].material)];
    EXPECT_EQ(car.specular_model, FC_SPECULAR_MICROFACET);
    EXPECT_FLOAT_EQ(car.clearcoat, 1.0f);
    EXPECT_FLOAT_EQ(car.clearcoat_alpha, 0.09f);
    EXPECT_EQ(car.sheen, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(velvet.clearcoat, 0.0f);
    EXPECT_EQ(velvet.sheen, glm::vec3(0.5f));
    EXPECT_FLOAT_EQ(velvet.sheen_roughness, 0.5f);
    d.write("bad.mtl", "newmtl a\nPc 2\n");
    const auto q = d.write("x.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(q); }, {"bad.mtl:2:"});
}

// The PBR extension's aniso (strength) and anisor (rotation, a fraction of a turn) map onto
// glTF's anisotropy and make the material a PBR (GGX) one; out of [0, 1] names the line.
TEST(SceneObj, MtlAnisotropy) {
    TempDir d;
    d.write("m.mtl",
            "newmtl brushed\nKd 0.9 0.9 0.9\nPm 1\nPr 0.3\naniso 0.8\nanisor 0.25\n"
            "newmtl plain\nKd 0.5 0.5 0.5\naniso 0.5\n");
    const auto p =
        d.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl brushed\nf 1 2 3\nusemtl plain\nf 1 2 3\n");
    const Scene s = load(p);
    const Material& brushed = s.materials[static_cast<std::size_t>(s.shading[0].material)];
    const Material& plain = s.materials[static_cast<std::size_t>(s.shading[1].material)];
    EXPECT_FLOAT_EQ(brushed.anisotropy, 0.8f);
    EXPECT_NEAR(brushed.anisotropy_rotation, 1.5707963f, 1e-6f);
    EXPECT_FLOAT_EQ(brushed.alpha_x, 0.09f);
    EXPECT_EQ(plain.specular_model, FC_SPECULAR_MICROFACET);
    EXPECT_FLOAT_EQ(plain.anisotropy, 0.5f);
    d.write("bad.mtl", "newmtl a\nanisor 1.5\n");
    const auto q = d.write("x.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(q); }, {"bad.mtl:2:"});
}

TEST(SceneObj, MtlBadNumberNamesLine) {
    TempDir d;
    d.write("bad.mtl", "newmtl a\nKd 0.5 abc 0.5\n");
    const auto p = d.write("x.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(p); }, {"bad.mtl:2:", "abc"});
    d.write("neg.mtl", "newmtl a\n\nKe 1 -1 1\n");
    const auto q = d.write("y.obj", "mtllib neg.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(q); }, {"neg.mtl:3:", "negative"});
    d.write("orphan.mtl", "Kd 1 1 1\n");
    const auto r = d.write("z.obj", "mtllib orphan.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load(r); }, {"orphan.mtl:1:", "newmtl"});
}

TEST(SceneObj, MissingMtlIsWarning) {
    TempDir d;
    const auto p = d.write("lonely.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
    const Scene s = load(p);
    ASSERT_EQ(s.triangle_count(), 1u);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("lonely.obj"), std::string::npos);
    EXPECT_NE(s.warnings[0].find("gone.mtl"), std::string::npos);
    EXPECT_FLOAT_EQ(s.materials[static_cast<std::size_t>(s.shading[0].material)].diffuse[0], 0.8f);
}

// A texture facet reads must exist (docs/textures.md); one it does not read is a warning.
// A missing texture is a warning and a checker (docs/textures.md), an error with --strict.
TEST(SceneObj, MissingTextureIsWarningOrStrictError) {
    TempDir d;
    d.write("t.mtl", "newmtl a\nKd 1 1 1\nmap_Kd -bm 1 textures/wood.png\n");
    const auto p = d.write("t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    const Scene checker = load(p);
    EXPECT_EQ(checker.textures.size(), 1u) << "the checker";
    for (const char* part : {"t.mtl:3", "wood.png", "material 'a'", "checker"})
        EXPECT_TRUE(test::contains(checker.warnings, part)) << part;
    expect_error([&] { load_scene(p, "", true); }, {"t.mtl:3", "wood.png", "material 'a'", "--strict"});
    d.write("t.mtl", "newmtl a\nKd 1 1 1\ndecal textures/wood.png\n");
    const Scene s = load(p);
    ASSERT_EQ(s.triangle_count(), 1u);
    EXPECT_TRUE(test::contains(s.warnings, "t.mtl:3:"));
    EXPECT_TRUE(test::contains(s.warnings, "wood.png"));
    EXPECT_TRUE(test::contains(s.warnings, "missing"));
}

TEST(SceneObj, MaterialOverrides) {
    TempDir d;
    d.write("o.mtl", "newmtl a\nKd 0.1 0.1 0.1\nnewmtl b\nKd 0.2 0.2 0.2\n");
    const auto p = d.write("o.obj",
                           "mtllib o.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"
                           "usemtl b\nf 1 2 3\n");
    Scene s;
    const int mine = add_material(s, default_material(), "mine");
    ObjLoadOptions opt;
    opt.material_map["b"] = mine;
    load_obj(p, s, opt);
    EXPECT_NE(s.shading[0].material, mine);
    EXPECT_EQ(s.shading[1].material, mine);
    Scene all;
    load_obj(p, all, glm::mat4(1.0f), 0);
    EXPECT_EQ(all.shading[0].material, 0);
    EXPECT_EQ(all.shading[1].material, 0);
    opt.material_map["nope"] = mine;
    expect_error(
        [&] {
            Scene t;
            load_obj(p, t, opt);
        },
        {"o.obj", "'nope'"});
}

// Mangled files load or give facet::Error, never another exception or a crash.
TEST(SceneObj, MangledObjNeverCrashes) {
    const std::string base =
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
        "usemtl a\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf -1 -2 -3\n";
    const std::string mtl = "newmtl a\nKd 0.5 0.5 0.5\nNs 10\nmap_Kd x.png\n";
    const std::string noise = "/-0 .e#\n\rv f9x";
    std::mt19937 rng(1234);
    TempDir d;
    for (int i = 0; i < 300; ++i) {
        std::string obj = base, m = mtl;
        std::string& target = (i % 3 == 0) ? m : obj;
        for (int k = 0; k < 3; ++k) {
            const std::size_t at = rng() % target.size();
            target[at] = noise[rng() % noise.size()];
        }
        d.write("m.mtl", m);
        const auto p = d.write("mangled.obj", obj);
        try {
            load(p);
        } catch (const Error&) {
        }
    }
}

}  // namespace
}  // namespace facet
