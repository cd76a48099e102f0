// GltfResources.*: the files a glTF names (external buffers and images) go through facet's
// input checks, not tinygltf's fopen: a FIFO, also reached through "../", is refused at
// once instead of blocking for ever, a folder is refused instead of "std::bad_alloc";
// and a long acyclic node chain is not mistaken for a cycle.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "host/error.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::TempDir;

// The message load_scene gives for `path`; a load still blocked after 20 s counts as a
// hang: the FIFOs are opened for writing to release it, and the test fails.
std::string load_error(const std::string& path, const std::vector<std::string>& fifos) {
    auto result = std::async(std::launch::async, [&]() -> std::string {
        try {
            load_scene(path);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    });
    if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
        ADD_FAILURE() << path << ": loading blocks on a FIFO";
        for (const std::string& f : fifos) {
            const int fd = ::open(f.c_str(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) ::close(fd);
        }
    }
    return result.get();
}

// A chain of `levels` nodes, each the only child of the one before, the last holding a
// triangle; with an image of that URI when given.
std::string node_chain(const TempDir& d, const std::string& name, int levels, const std::string& image_uri = "") {
    test::GltfBuilder b;
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = b.accessor(p, sizeof p, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    b.m.meshes.emplace_back().primitives.push_back(prim);
    for (int i = 0; i < levels; ++i) {
        tinygltf::Node n;
        if (i + 1 < levels) n.children = {i + 1};
        else n.mesh = 0;
        b.m.nodes.push_back(n);
    }
    b.m.scenes[0].nodes = {0};
    if (!image_uri.empty()) b.m.images.emplace_back().uri = image_uri;
    tinygltf::TinyGLTF writer;
    const std::string path = d.path(name);
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&b.m, path, false, true, true, false)) << path;
    return path;
}

TEST(GltfResources, FifoFolderAndParentPathAreRefused) {
    TempDir d;
    const std::string fifo = d.path("pipe.bin");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::filesystem::create_directories(d.path("dir.bin"));
    std::filesystem::create_directories(d.path("sub"));
    auto gltf = [&](const std::string& name, const std::string& resources) {
        return d.write(name, R"({"asset": {"version": "2.0"}, )" + resources + "}");
    };
    struct Case {
        std::string file, want;
    } cases[] = {
        {gltf("fifo.gltf", R"("buffers": [{"uri": "pipe.bin", "byteLength": 12}])"), "not a regular file"},
        {gltf("sub/up.gltf", R"("buffers": [{"uri": "../pipe.bin", "byteLength": 12}])"), "not a regular file"},
        {gltf("folder.gltf", R"("buffers": [{"uri": "dir.bin", "byteLength": 12}])"), "is a directory"},
    };
    for (const Case& c : cases) {
        const std::string msg = load_error(c.file, {fifo});
        EXPECT_NE(msg.find(c.file), std::string::npos) << msg;
        EXPECT_NE(msg.find(c.want), std::string::npos) << msg;
        EXPECT_NE(msg.find(c.want == "is a directory" ? "dir.bin" : "pipe.bin"), std::string::npos) << msg;
        EXPECT_EQ(msg.find("bad_alloc"), std::string::npos) << msg;
    }
    // An image tinygltf cannot read is its warning (the material's texture is then missing).
    const std::string image = node_chain(d, "image.gltf", 1, "pipe.bin");
    auto loaded = std::async(std::launch::async, [&] { return load_scene(image); });
    if (loaded.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
        ADD_FAILURE() << image << ": loading blocks on a FIFO";
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
    }
    const Scene s = loaded.get();
    std::string warnings;
    for (const std::string& w : s.warnings) warnings += w + "\n";
    EXPECT_NE(warnings.find("pipe.bin': is not a regular file"), std::string::npos) << warnings;
}

// URIs written on Windows ("sub\\tri.bin", ".\\tex.pfm") name the files with '/' in
// their place, as an MTL's texture names do; a missing image is a warning and a checker.
TEST(GltfResources, WindowsUrisAreNormalisedAndMissingImagesWarn) {
    TempDir d;
    std::filesystem::create_directories(d.path("sub"));
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    d.write("sub/tri.bin", std::string(reinterpret_cast<const char*>(p), sizeof p));
    d.write("tex.pfm", std::string("PF\n1 1\n-1.0\n") + std::string(12, '\0'));
    auto gltf = [&](const std::string& name, const std::string& image) {
        std::string text = R"({"asset": {"version": "2.0"},
            "buffers": [{"uri": "sub\\tri.bin", "byteLength": 36}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]}],
            "images": [{"uri": "IMAGE"}], "textures": [{"source": 0}],
            "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
            "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
        return d.write(name, text.replace(text.find("IMAGE"), 5, image));
    };
    const Scene s = load_scene(gltf("win.gltf", ".\\\\tex.pfm"));
    EXPECT_GE(s.triangle_count(), 1u);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].path, d.path("tex.pfm"));
    const Scene missing = load_scene(gltf("missing.gltf", "gone.png"));
    ASSERT_EQ(missing.textures.size(), 1u) << "the checker";
    std::string warnings;
    for (const std::string& w : missing.warnings) warnings += w + "\n";
    EXPECT_NE(warnings.find("gone.png"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("checker"), std::string::npos) << warnings;
}

TEST(GltfResources, LongAcyclicNodeChainIsNotACycle) {
    TempDir d;
    const Scene s = load_scene(node_chain(d, "chain.gltf", 1002));
    EXPECT_GE(s.triangle_count(), 1u);
    test::expect_error([&] { load_scene(node_chain(d, "deep.gltf", 5000)); },
                       {"deep.gltf", "more than 4096 levels deep"});
}

// An image embedded in the glTF (a data URI here; a .glb's bufferView alike) is decoded from
// memory: nothing is written to $TMPDIR, so a signal cannot leave a temporary behind, and a
// missing $TMPDIR is no error (issue 27, item 11: it was "internal error" and left
// facet-texture-* files on Ctrl-C).
TEST(GltfResources, EmbeddedImagesNeedNoTemporaryFiles) {
    const std::string box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf";
    if (!std::filesystem::exists(box)) GTEST_SKIP() << "assimp-testmodels is not installed";
    const char* old = std::getenv("TMPDIR");
    const std::string saved = old ? old : "";
    const std::filesystem::path empty =
        std::filesystem::temp_directory_path() / ("facet-tmpdir-" + std::to_string(getpid()));
    std::filesystem::create_directories(empty);
    setenv("TMPDIR", empty.c_str(), 1);
    Scene scene = load_scene(box);
    EXPECT_EQ(scene.textures.size(), 1u);
    EXPECT_TRUE(std::filesystem::is_empty(empty)) << "a temporary was written";
    setenv("TMPDIR", (empty / "missing").c_str(), 1);
    EXPECT_NO_THROW(scene = load_scene(box));
    if (old) setenv("TMPDIR", saved.c_str(), 1);
    else unsetenv("TMPDIR");
    std::filesystem::remove_all(empty);
}

}  // namespace
}  // namespace facet
