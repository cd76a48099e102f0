// InputLimits.*: what facet reads can neither make it read without end, allocate what a
// header claims, nor overflow the image; and its messages say what is wrong (issue 14).
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "host/bvh/bvh.hpp"
#include "host/image/image_io.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::contains;
using test::expect_error;
using test::TempDir;

namespace fs = std::filesystem;

using test::kQuad;
using test::scene;

// --- Radiance that would overflow the float accumulation ---------------------------

TEST(InputLimits, RadianceBeyondTheLimitIsRefused) {
    TempDir d;
    expect_error(
        [&] {
            load_scene(scene(d, "e.json", R"("materials": {"lamp": {"emission": [3e38, 1, 1]}},
        "shapes": [{"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], "material": "lamp"}])"));
        },
        {"e.json", "lamp", "emission", "1e+30"});
    expect_error(
        [&] {
            load_scene(
                scene(d, "p.json",
                      R"("lights": [{"type": "point", "position": [0, 1, 0], "color": [1e37, 1e37, 1e37]}],)" + kQuad));
        },
        {"p.json", "lights[0].color", "1e+30"});
    expect_error(
        [&] { load_scene(scene(d, "c.json", R"("environment": {"constant": [1e20, 1, 1], "scale": 1e20},)" + kQuad)); },
        {"c.json", "environment.constant", "1e+30"});
    d.write("m.mtl", "newmtl hot\nKe 3e38 3e38 3e38\n");
    expect_error(
        [&] { load_scene(d.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl hot\nf 1 2 3\n")); },
        {"m.obj", "hot", "emission"});
}

// Built in code (past the reader's limits): an emitter of 3e38 and a point light of 1e37
// seen over many samples. Every pixel stays finite, and no sample is rejected.
TEST(InputLimits, HugeRadianceStaysFiniteInTheImage) {
    Scene scene;
    Material lamp = default_material();
    lamp.diffuse = glm::vec3(0.0f);
    lamp.emission = glm::vec3(3e38f);
    const int hot = add_material(scene, lamp, "lamp");
    Material wall = default_material();
    const int grey = add_material(scene, wall, "wall");
    add_quad(scene, glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), hot);
    add_quad(scene, glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), grey);
    PunctualLight point;
    point.position = glm::vec3(0.5f, 0.0f, 0.5f);
    point.color = glm::vec3(1e37f);
    scene.punctual_lights.push_back(point);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 3.0f);
    scene.settings.width = scene.settings.height = 8;
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    for (int pass = 0; pass < 4; ++pass) r.render(16);
    double rejected = -1.0;
    const std::vector<float> img = r.image(&rejected);
    float largest = 0.0f;
    for (float v : img) {
        ASSERT_TRUE(std::isfinite(v));
        largest = std::max(largest, v);
    }
    EXPECT_EQ(rejected, 0.0);
    EXPECT_GT(largest, 1e29f) << "the emitter's pixels hold the clamped radiance";
}

// --- Headers that claim more than the file holds -----------------------------------

TEST(InputLimits, HeaderClaimingHugeImageIsRefusedBeforeAllocating) {
    TempDir d;
    // A 117-byte Radiance file declaring 16000x16000 (3 GB as float RGB).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16000 +X 16000\n";
    hdr.resize(117, '\x02');
    const std::string hdr_path = d.write("huge.hdr", hdr);
    expect_error([&] { read_image(hdr_path); }, {hdr_path, "16000x16000", "117 bytes"});
    expect_error([&] { load_scene(scene(d, "env.json", R"("environment": {"file": "huge.hdr"},)" + kQuad)); },
                 {hdr_path});

    // A small tiled EXR (1x1 tiles) whose data window is then patched to 16000x16000:
    // OpenEXR would allocate a 2 GB tile offset table when opening it.
    const std::string exr_path = d.path("tiled.exr");
    {
        OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::HALF);
        spec.tile_width = spec.tile_height = 1;
        auto out = OIIO::ImageOutput::create(exr_path);
        ASSERT_TRUE(out && out->open(exr_path, spec));
        std::vector<float> px(4 * 4 * 3, 0.5f);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        ASSERT_TRUE(out->close());
    }
    std::string bytes;
    {
        std::ifstream in(exr_path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string tag = std::string("dataWindow\0box2i\0", 17);
    for (std::size_t at = bytes.find(tag); at != std::string::npos; at = bytes.find(tag, at + 1)) {
        const std::size_t value = at + tag.size() + 4;
        for (std::size_t i : {value + 8, value + 12}) {  // xMax, yMax = 15999
            const std::uint32_t v = 15999;
            for (int b = 0; b < 4; ++b) bytes[i + std::size_t(b)] = char((v >> (8 * b)) & 0xff);
        }
    }
    const std::string patched = d.write("patched.exr", bytes);
    expect_error([&] { read_image(patched); }, {patched, "16000x16000"});
}

// --- Files that are not regular files ------------------------------------------------

TEST(InputLimits, DevicesAndPipesAreRefused) {
    TempDir d;
    auto link = [&](const std::string& name, const char* target) {
        fs::create_symlink(target, d.path(name));
        return d.path(name);
    };
    const std::string zero_json = link("zero.json", "/dev/zero");
    expect_error([&] { load_scene(zero_json); }, {zero_json, "not a regular file"});
    const std::string random_obj = link("random.obj", "/dev/urandom");
    expect_error([&] { load_scene(random_obj); }, {random_obj, "not a regular file"});
    link("zero.mtl", "/dev/zero");
    const std::string obj = d.write("m.obj", "mtllib zero.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error([&] { load_scene(obj); }, {"zero.mtl", "not a regular file"});
    const std::string zero_hdr = link("zero.hdr", "/dev/zero");
    expect_error([&] { read_image(zero_hdr); }, {zero_hdr, "not a regular file"});
    expect_error([&] { load_scene(scene(d, "env.json", R"("environment": {"file": "zero.hdr"},)" + kQuad)); },
                 {zero_hdr, "not a regular file"});
    const std::string fifo = d.path("pipe.json");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expect_error([&] { load_scene(fifo); }, {fifo, "not a regular file"});
}

// --- Messages ------------------------------------------------------------------------

TEST(InputLimits, UnreadableFilesSayWhy) {
    TempDir d;
    const std::string file = d.write("plain", "x");
    expect_error([&] { load_scene(file + "/scene.json"); }, {"scene.json", "Not a directory"});
    expect_error([&] { load_scene(d.path("missing.json")); }, {"missing.json", "no such file"});
    expect_error([&] { read_image(d.path("missing.exr")); }, {"missing.exr", "no such file"});
    if (::geteuid() != 0) {  // root reads anything
        const std::string locked = scene(d, "locked.json", kQuad);
        ::chmod(locked.c_str(), 0);
        expect_error([&] { load_scene(locked); }, {locked, "Permission denied"});
    }
}

TEST(InputLimits, OutOfRangeNumbersAreCalledSo) {
    TempDir d;
    expect_error([&] { load_scene(d.write("r.obj", "v 0 0 1e39\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); },
                 {"r.obj:1", "1e39", "out of range"});
    d.write("r.mtl", "newmtl a\nKd 1e-50 0 0\n");
    expect_error([&] { load_scene(d.write("m.obj", "mtllib r.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")); },
                 {"r.mtl:2", "out of range"});
    expect_error([&] { load_scene(d.write("g.obj", "v 0 0 1x\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); },
                 {"g.obj:1", "not a valid number"});
}

TEST(InputLimits, DuplicatesAndEmptyLibrariesWarn) {
    TempDir d;
    const Scene a = load_scene(scene(d, "dup.json", R"("render": {"spp": 4, "spp": 8},)" + kQuad));
    EXPECT_TRUE(contains(a.warnings, "key 'spp' is given twice")) << "warnings: " << a.warnings.size();
    EXPECT_EQ(a.settings.spp, 8);

    d.write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl red\nKd 0 1 0\n");
    const Scene b = load_scene(d.write("two.obj", "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n"));
    EXPECT_TRUE(contains(b.warnings, "two.mtl:3: material 'red' is defined again"));

    for (const char* body : {"", "this is not an MTL file\n\x01\x02\n"}) {
        d.write("bad.mtl", body);
        const Scene c =
            load_scene(d.write("bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n"));
        EXPECT_TRUE(contains(c.warnings, "defines no material")) << "body '" << body << "'";
        EXPECT_TRUE(contains(c.warnings, "'usemtl red' names no material")) << "body '" << body << "'";
    }
}

}  // namespace
}  // namespace facet
