// AssimpReader.*: the formats read through Assimp (host/readers/assimp_reader.cpp), on the
// models of Debian's assimp-testmodels (skipped without the package) and on malformed files.
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <assimp/IOStream.hpp>

#include "host/readers/assimp_io.hpp"
#include "host/readers/assimp_reader.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::expect_error;
using test::TempDir;

const std::string kModels = "/usr/share/assimp/models/";

#define REQUIRE_MODEL(path) \
    if (!fs::exists(path)) GTEST_SKIP() << (path) << " is missing (Debian's assimp-testmodels)"

std::string all_warnings(const Scene& s) {
    std::string out;
    for (const std::string& w : s.warnings) out += w + "\n";
    return out;
}

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

TEST(AssimpReader, StlBinaryAndAsciiGiveTheSameSpider) {
    const std::string binary = kModels + "STL/Spider_binary.stl", ascii = kModels + "STL/Spider_ascii.stl";
    REQUIRE_MODEL(binary);
    const Scene b = load_scene(binary), a = load_scene(ascii);
    EXPECT_GT(b.triangle_count(), 1000u);
    EXPECT_EQ(b.triangle_count(), a.triangle_count());
    EXPECT_FALSE(b.lights.empty()) << "a bare model is lit by default";
}

TEST(AssimpReader, FbxSpiderWithItsMaterials) {
    const std::string spider = kModels + "FBX/spider.fbx";
    REQUIRE_MODEL(spider);
    const Scene s = load_scene(spider);
    EXPECT_GT(s.triangle_count(), 1000u);
    EXPECT_GT(s.materials.size(), 1u) << "the spider's materials, not one default";
}

// FBX's embedded images (aiTexture) become textures.
TEST(AssimpReader, FbxEmbeddedTextureIsRead) {
    const std::string box = kModels + "FBX/embedded_ascii/box.FBX";
    REQUIRE_MODEL(box);
    const Scene s = load_scene(box);
    ASSERT_EQ(s.textures.size(), 1u) << all_warnings(s);
    EXPECT_NE(s.textures[0].path.find("box.FBX#"), std::string::npos) << s.textures[0].path;
    EXPECT_GT(s.textures[0].width, 1);
}

TEST(AssimpReader, ColladaAnd3dsWithTexturesBesideThem) {
    const std::string duck = kModels + "Collada/duck.dae", cube = kModels + "3DS/cube_with_diffuse_texture.3DS";
    REQUIRE_MODEL(duck);
    const Scene d = load_scene(duck);
    EXPECT_GT(d.triangle_count(), 1000u);
    ASSERT_EQ(d.textures.size(), 1u) << all_warnings(d);
    EXPECT_NE(d.textures[0].path.find("duckCM.tga"), std::string::npos);
    Scene c;
    load_assimp(cube, c);  // without the default light's triangles
    EXPECT_EQ(c.triangle_count(), 12u);
    EXPECT_EQ(c.textures.size(), 1u) << all_warnings(c);
}

// What facet does not read is named, once per kind.
TEST(AssimpReader, IgnoredKindsAreOneWarningEach) {
    const std::string fbx = kModels + "FBX/animation_with_skeleton.fbx";
    REQUIRE_MODEL(fbx);
    const std::string w = all_warnings(load_scene(fbx));
    EXPECT_EQ(count(w, "animations"), 1u) << w;
    EXPECT_EQ(count(w, "skins"), 1u) << w;
}

TEST(AssimpReader, InJsonSceneWithTransform) {
    const std::string stl = kModels + "STL/Spider_binary.stl";
    REQUIRE_MODEL(stl);
    TempDir d;
    Scene plain;
    load_assimp(stl, plain);
    const Scene s =
        load_scene(test::scene(d, "s.json", R"("meshes": [{"file": ")" + stl + R"(", "transform": {"scale": 2}}])"));
    ASSERT_EQ(s.triangle_count(), plain.triangle_count());
    EXPECT_FLOAT_EQ(s.vertices[0].x, 2.0f * plain.vertices[0].x);
}

// Every malformed file is a facet::Error naming it, never a crash.
TEST(AssimpReader, MalformedFilesAreErrorsNamingTheFile) {
    for (const char* name : {"empty.3ds", "empty.x", "empty.lwo", "empty.ase", "empty.off"}) {
        const std::string p = kModels + "invalid/" + name;
        if (!fs::exists(p)) continue;
        expect_error([&] { load_scene(p); }, {p});
    }
    TempDir d;
    expect_error([&] { load_scene(d.write("noise.stl", "solid x\nfacet normal nonsense\n")); }, {"noise.stl"});
    std::string truncated(80, ' ');  // a binary STL header promising 1000 triangles, holding none
    truncated += std::string("\xe8\x03\x00\x00", 4) + std::string(20, '\0');
    expect_error([&] { load_scene(d.write("short.stl", truncated)); }, {"short.stl"});
    expect_error([&] { load_scene(d.write("empty.fbx", "")); }, {"empty.fbx"});
    expect_error([&] { load_scene(d.path("absent.dae")); }, {"absent.dae", "no such file"});
    ASSERT_EQ(::mkfifo(d.path("pipe.stl").c_str(), 0600), 0);
    expect_error([&] { load_scene(d.path("pipe.stl")); }, {"pipe.stl", "not a regular file"});
}

// The files Assimp opens itself: regular files inside the model's folder only, read-only.
TEST(AssimpReader, FilesAssimpOpensPassTheInputChecks) {
    TempDir d;
    fs::create_directories(d.path("model"));
    d.write("model/part.bin", "abcdef");
    d.write("secret.txt", "outside");
    ASSERT_EQ(::mkfifo(d.path("model/pipe.bin").c_str(), 0600), 0);
    AssimpFiles files(d.path("model"));
    EXPECT_TRUE(files.Exists(d.path("model/part.bin").c_str()));
    EXPECT_FALSE(files.Exists(d.path("model/../secret.txt").c_str())) << "outside the model's folder";
    EXPECT_FALSE(files.Exists(d.path("model/pipe.bin").c_str()));
    Assimp::IOStream* in = files.Open(d.path("model/part.bin").c_str());
    ASSERT_NE(in, nullptr);
    char buf[4] = {};
    EXPECT_EQ(in->FileSize(), 6u);
    EXPECT_EQ(in->Read(buf, 1, 4), 4u);
    EXPECT_EQ(std::string(buf, 4), "abcd");
    EXPECT_EQ(in->Read(buf, 4, 1), 0u) << "2 bytes left: no whole item of 4";
    files.Close(in);
    EXPECT_EQ(files.Open(d.path("model/../secret.txt").c_str()), nullptr);
    EXPECT_NE(files.refusal().find("outside the model's folder"), std::string::npos) << files.refusal();
    EXPECT_EQ(files.Open(d.path("model/pipe.bin").c_str()), nullptr);
    EXPECT_NE(files.refusal().find("not a regular file"), std::string::npos) << files.refusal();
    EXPECT_EQ(files.Open(d.path("model/part.bin").c_str(), "wb"), nullptr) << "never written";
}

TEST(AssimpReader, FormatsAreListedOnce) {
    EXPECT_TRUE(is_assimp_format(".stl"));
    EXPECT_TRUE(is_assimp_format(".fbx"));
    EXPECT_FALSE(is_assimp_format(".obj")) << "OBJ, PLY and glTF have their own readers";
    EXPECT_FALSE(is_assimp_format(".ply"));
    EXPECT_FALSE(is_assimp_format(".gltf"));
}

}  // namespace
}  // namespace facet
