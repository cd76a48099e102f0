// Limits.*: absurd or broken parameters in scene files, meshes, materials and images are
// rejected with a message naming the file and key (or line), or sanitised with a
// warning; device errors say their cause (docs/robustness.md lists what is checked).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "host/cl/runtime.hpp"
#include "tests/cl_test_env.hpp"
#include "host/image/image_io.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/environment_map.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/scene_test_util.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

using test::contains;
using test::expect_error;
using test::TempDir;

using test::kQuad;
using test::scene;

// Render settings: zero, negative, fractional and huge values, each named by its key.
TEST(Limits, RenderSettingsOutOfRange) {
    TempDir d;
    const char* cases[][2] = {
        {R"("render": {"width": -5})", "render.width"},
        {R"("render": {"width": 1e9})", "render.width"},
        {R"("render": {"height": 0})", "render.height"},
        {R"("render": {"spp": -1})", "render.spp"},
        {R"("render": {"spp": 1e9})", "render.spp"},
        {R"("render": {"max_depth": 0})", "render.max_depth"},
        {R"("render": {"max_depth": -3})", "render.max_depth"},
        {R"("render": {"rr_depth": -1})", "render.rr_depth"},
        {R"("render": {"roulette_gain": 0})", "render.roulette_gain"},
        {R"("render": {"roulette_gain": 2e6})", "render.roulette_gain"},
        {R"("render": {"seed": -1})", "render.seed"},
        {R"("render": {"seed": 1e12})", "render.seed"},
        {R"("render": {"width": 1e400})", "render.width"},  // the parser overflows it to inf: "must be finite"
    };
    int i = 0;
    for (const auto& c : cases) {
        const std::string name = fmt::format("r{}.json", i++);
        SCOPED_TRACE(c[0]);
        expect_error([&] { load_scene(scene(d, name, fmt::format("{},\n{}", c[0], kQuad))); }, {name});
    }
}

// Numbers beyond a float's range would be converted with undefined behaviour.
TEST(Limits, NumbersBeyondFloatRange) {
    TempDir d;
    expect_error([&] { load_scene(scene(d, "a.json", R"("camera": {"eye": [0, 0, 1e39]},)" + kQuad)); },
                 {"a.json: camera.eye[2]", "32-bit float"});
    expect_error(
        [&] {
            load_scene(scene(
                d, "b.json",
                R"("shapes": [{"type": "quad", "corner": [0, 0, 0], "edge1": [-1e300, 0, 0], "edge2": [0, 1, 0]}])"));
        },
        {"b.json: shapes[0].edge1[0]", "32-bit float"});
}

// Geometry that overflows after transforms or shape sizes is rejected, naming the triangle.
TEST(Limits, GeometryBeyondTheFloatRange) {
    TempDir d;
    d.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error(
        [&] { load_scene(scene(d, "m.json", R"("meshes": [{"file": "t.obj", "transform": {"scale": 1e30}}])")); },
        {"m.json", "triangle 0", "finite and within"});
    expect_error(
        [&] {
            load_scene(scene(
                d, "q.json",
                R"("shapes": [{"type": "quad", "corner": [3e38, 0, 0], "edge1": [3e38, 0, 0], "edge2": [0, 1, 0]}])"));
        },
        {"q.json", "triangle", "finite and within"});
    expect_error([&] { load_scene(d.write("big.obj", "v 0 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n")); },
                 {"big.obj", "triangle 0"});
    expect_error(
        [&] { load_scene(scene(d, "c.json", R"("camera": {"eye": [3e38, 0, 0], "target": [-3e38, 0, 0]},)" + kQuad)); },
        {"c.json: camera", "too far apart"});
}

// Punctual lights: a direction that cannot be normalised, a position beyond the scene limit.
TEST(Limits, PunctualLights) {
    TempDir d;
    expect_error(
        [&] {
            load_scene(scene(
                d, "l.json",
                R"("lights": [{"type": "directional", "direction": [3e38, 3e38, 0], "color": [1, 1, 1]}],)" + kQuad));
        },
        {"l.json: lights[0].direction", "unit vector"});
    expect_error(
        [&] {
            load_scene(
                scene(d, "p.json",
                      R"("lights": [{"type": "point", "position": [0, 1e30, 0], "color": [1, 1, 1]}],)" + kQuad));
        },
        {"p.json: lights[0].position", "1e18"});
    expect_error(
        [&] {
            load_scene(scene(
                d, "z.json",
                R"("lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, 0, 0], "color": [1, 1, 1]}],)" +
                    kQuad));
        },
        {"z.json: lights[0].direction", "zero"});
}

// A camera whose up vector is zero or along the view direction has no frame.
TEST(Limits, DegenerateCamera) {
    TempDir d;
    expect_error([&] { load_scene(scene(d, "u.json", R"("camera": {"up": [0, 0, 0]},)" + kQuad)); }, {"camera.up"});
    expect_error(
        [&] {
            load_scene(
                scene(d, "v.json", R"("camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, 2]},)" + kQuad));
        },
        {"camera.up"});
    expect_error([&] { load_scene(scene(d, "f.json", R"("camera": {"fov": 180},)" + kQuad)); }, {"camera.fov"});
    expect_error(
        [&] { load_scene(scene(d, "h.json", R"("camera": {"projection": "orthographic", "height": 0},)" + kQuad)); },
        {"camera.height"});
}

// Negative, zero or out-of-range material parameters, named by their key.
TEST(Limits, MaterialParameters) {
    TempDir d;
    const char* cases[][2] = {
        {R"({"m": {"roughness": -0.1}})", "materials.m.roughness"},
        {R"({"m": {"ior": 0}})", "materials.m.ior"},
        {R"({"m": {"ior": -1.5}})", "materials.m.ior"},
        {R"({"m": {"emission": [1, -1, 1]}})", "materials.m.emission"},
        {R"({"m": {"shininess": -5}})", "materials.m.shininess"},
        {R"({"m": {"sigma": 3}})", "materials.m.sigma"},
        {R"({"m": {"eta": [-1, 1, 1]}})", "materials.m.eta"},
        {R"({"m": {"k": [1, 1, -1]}})", "materials.m.k"},
        {R"({"m": {"diffuse": [1e39, 0, 0]}})", "materials.m.diffuse[0]"},
    };
    int i = 0;
    for (const auto& c : cases) {
        const std::string name = fmt::format("m{}.json", i++);
        SCOPED_TRACE(c[0]);
        expect_error([&] { load_scene(scene(d, name, fmt::format("\"materials\": {},\n{}", c[0], kQuad))); },
                     {name + ": " + c[1]});
    }
    // A reflectance above 1 is clamped, with a warning.
    Scene s = load_scene(scene(d, "w.json", R"("materials": {"m": {"diffuse": [2, 0.5, 0.5]}},
        "shapes": [{"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], "material": "m"}])"));
    EXPECT_TRUE(contains(s.warnings, "creates energy"));
    EXPECT_EQ(s.materials[0].diffuse[0], 1.0f);
}

// MTL: negative, NaN and infinite numbers name the file and line.
TEST(Limits, MtlParameters) {
    TempDir d;
    d.write("t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    const char* cases[] = {"Kd -0.5 0.5 0.5", "Kd nan 0 0", "Ke inf 1 1", "Ns -1", "Ni 0", "Pr 2",
                           "d nan",           "illum 1.5"};
    for (const char* c : cases) {
        SCOPED_TRACE(c);
        d.write("t.mtl", std::string("newmtl a\n") + c + "\n");
        expect_error([&] { load_scene(d.path("t.obj")); }, {"t.mtl:2"});
    }
    // A reflectance above 1 is clamped, with a warning (found by fuzz_obj_mtl).
    d.write("t.mtl", "newmtl a\nKd 1.9 0.5 0.5\nKs 2 0 0\n");
    Scene s = load_scene(d.path("t.obj"));
    EXPECT_TRUE(contains(s.warnings, "t.obj: material 'a': a reflectance (Kd, Ks) above 1"));
    for (const Material& m : s.materials) {
        EXPECT_LE(m.diffuse[0], 1.0f);
        EXPECT_LE(specular_colour(m)[0], 1.0f);
    }
}

// OBJ: NaN/inf positions are errors naming the line; zero-area triangles are dropped with
// a count; a mesh of nothing but zero-area triangles is an error; NaN normals are replaced.
TEST(Limits, ObjDegenerateAndNonFinite) {
    TempDir d;
    expect_error([&] { load_scene(d.write("n.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")); },
                 {"n.obj:2", "finite"});
    expect_error([&] { load_scene(d.write("i.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n")); },
                 {"i.obj:3", "finite"});
    Scene s = load_scene(d.write("z.obj",
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                 "f 1 2 3\nf 1 2 4\nf 1 1 3\n"));
    EXPECT_EQ(s.triangle_count(), 1u + 2u);  // the kept triangle, and the default light's quad
    EXPECT_TRUE(contains(s.warnings, "2 of 3 triangles have zero area and were dropped"));
    expect_error([&] { load_scene(d.write("all.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 3 2 1\n")); },
                 {"all.obj", "every face has zero area"});
    // A form feed is not a blank to tinyobjloader: "vn\f0 0 1" is no normal, and an index
    // naming it is out of range (found by fuzz_obj_mtl: a heap overflow before the fix).
    expect_error(
        [&] { load_scene(d.write("ff.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn\f0 0 1\nf 1//2 2//2 3//2\n")); },
        {"ff.obj:6", "normal index 2 is out of range"});
    Scene nn = load_scene(d.write("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn nan nan nan\nf 1//1 2//1 3//1\n"));
    for (float c : nn.shading[0].n0) EXPECT_TRUE(std::isfinite(c));
    EXPECT_FLOAT_EQ(nn.shading[0].n0[2], 1.0f);
}

// An image header claiming a huge size fails before any pixel memory is allocated.
TEST(Limits, HugeImageHeaderIsRejectedBeforeReading) {
    TempDir d;
    const std::string hdr = d.write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 200000\n");
    expect_error([&] { read_image(hdr); }, {"huge.hdr", "200000x100000", "2^28"});
    std::vector<std::string> warnings;
    expect_error([&] { load_environment_map(hdr, glm::vec3(1.0f), glm::mat3(1.0f), warnings); }, {"huge.hdr"});
    // Truncated pixel data: an error, not a crash.
    std::string cut = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 64 +X 128\n";
    cut += std::string(100, '\x80');
    expect_error([&] { read_image(d.write("cut.hdr", cut)); }, {"cut.hdr"});
}

// A corrupt EXR header is rejected before OpenEXR allocates from it (found by
// fuzz_env_map: a 363-byte file claimed a 1.7 GB attribute; OpenEXR took 2 GB and 8 s).
std::string exr_header(const std::string& attributes) {
    return std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) + attributes + std::string(1, '\0');
}
std::string le32(std::int32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i) s[std::size_t(i)] = char((std::uint32_t(v) >> (8 * i)) & 0xffu);
    return s;
}
std::string box(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1) {
    return std::string("dataWindow\0box2i\0", 17) + le32(16) + le32(x0) + le32(y0) + le32(x1) + le32(y1);
}

TEST(Limits, CorruptExrHeaderIsRejectedBeforeReading) {
    TempDir d;
    const std::string attr =
        d.write("attr.exr", exr_header(std::string("capDate\0string\0", 15) + le32(1751318547) + "xyz"));
    expect_error([&] { read_image(attr); }, {"attr.exr", "attribute 'capDate' claims 1751318547 bytes", "corrupt"});
    const std::string window = d.write("window.exr", exr_header(box(0, 0, 99999, 99999)));
    expect_error([&] { read_image(window); }, {"window.exr", "100000x100000", "2^28"});
    const std::string lines =
        d.write("lines.exr", exr_header(box(0, 0, 9, 1999999) + std::string("compression\0compression\0", 24) +
                                        le32(1) + std::string(1, '\0')));
    expect_error([&] { read_image(lines); }, {"lines.exr", "2000000 scanlines", "offset table"});
    // A channel list whose entries end before its declared size (OpenEXR reads on from where they
    // end, so the walk must too).
    const std::string chlist =
        d.write("chlist.exr", exr_header(std::string("channels\0chlist\0", 16) + le32(20) + std::string("R\0", 2) +
                                         std::string(16, '\0') + std::string(2, '\0')));
    expect_error([&] { read_image(chlist); }, {"chlist.exr", "channel list 'channels' declares 20 bytes", "corrupt"});
    // The stored findings themselves, through the environment loader.
    std::vector<std::string> warnings;
    expect_error(
        [&] {
            load_environment_map(test::fuzz_dir() + "/regressions/env_map/exr_attribute_size_oom.exr", glm::vec3(1.0f),
                                 glm::mat3(1.0f), warnings);
        },
        {"exr_attribute_size_oom.exr", "attribute"});
    expect_error(
        [&] {
            load_environment_map(test::fuzz_dir() + "/regressions/env_map/exr_chlist_size_mismatch_oom.exr",
                                 glm::vec3(1.0f), glm::mat3(1.0f), warnings);
        },
        {"exr_chlist_size_mismatch_oom.exr", "channel list"});
    // A valid EXR still reads.
    write_exr(d.path("ok.exr"), 4, 2, std::vector<float>(24, 0.5f));
    EXPECT_EQ(read_image(d.path("ok.exr")).width, 4);
}

// An uncompressed scanline EXR, written here byte by byte (OpenEXR's file layout): 3x2
// pixels of R, G, B floats, pixel i of line y holding 10 * y + i in each channel.
std::string uncompressed_exr() {
    auto attr = [](const char* name, const char* type, const std::string& value) {
        return std::string(name) + '\0' + type + '\0' + le32(std::int32_t(value.size())) + value;
    };
    auto f32 = [](float f) {
        std::uint32_t u = 0;
        std::memcpy(&u, &f, 4);
        return le32(std::int32_t(u));
    };
    std::string channels;
    for (const char* c : {"B", "G", "R"}) channels += std::string(c) + '\0' + le32(2) + le32(0) + le32(1) + le32(1);
    channels += '\0';
    const std::string window = le32(0) + le32(0) + le32(2) + le32(1);
    std::string exr =
        exr_header(attr("channels", "chlist", channels) + attr("compression", "compression", std::string(1, '\0')) +
                   attr("dataWindow", "box2i", window) + attr("displayWindow", "box2i", window) +
                   attr("lineOrder", "lineOrder", std::string(1, '\0')) + attr("pixelAspectRatio", "float", f32(1)) +
                   attr("screenWindowCenter", "v2f", f32(0) + f32(0)) + attr("screenWindowWidth", "float", f32(1)));
    const std::size_t line_bytes = 8 + 3 * 3 * 4;
    const std::size_t first = exr.size() + 2 * 8;
    for (std::size_t y = 0; y < 2; ++y) {
        const std::uint64_t at = first + y * line_bytes;
        exr += le32(std::int32_t(at & 0xffffffffu)) + le32(std::int32_t(at >> 32));
    }
    for (int y = 0; y < 2; ++y) {
        exr += le32(y) + le32(3 * 3 * 4);
        for (int c = 0; c < 3; ++c)  // B, G, R: each a run of the line's three pixels
            for (int i = 0; i < 3; ++i) exr += f32(float(10 * y + i));
    }
    return exr;
}

// An uncompressed EXR smaller than its scanlines need. OpenEXR itself stops at a file cut
// inside a chunk ("Unexpected end of file"), but reads a chunk that declares fewer bytes
// than its line holds without an error, the rest of the line left as whatever memory held
// (fuzz_env_map's corpus under valgrind: the stored finding). Both are refused by size.
TEST(Limits, UncompressedExrCutShortIsRejected) {
    TempDir d;
    const std::string exr = uncompressed_exr();
    const ImageRGB img = read_image(d.write("whole.exr", exr));
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int i = 0; i < 3; ++i)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgb[std::size_t(3 * (3 * y + i) + c)], float(10 * y + i));
    for (std::size_t cut : {std::size_t(1), std::size_t(30)}) {
        SCOPED_TRACE(cut);
        expect_error([&] { read_image(d.write("cut.exr", exr.substr(0, exr.size() - cut))); },
                     {"cut.exr", "2 uncompressed scanlines of 3 pixels need", "truncated"});
    }
    // Cut before the second line's chunk: its offset points past the end.
    expect_error([&] { read_image(d.write("cut.exr", exr.substr(0, exr.size() - 44))); },
                 {"cut.exr", "chunk 1 is at byte 373, outside its chunks", "incomplete or corrupt"});
    // An offset table of zeros (a writer that stopped early): OpenEXR scanned for the chunks
    // and, where it found none, the lines came back unread.
    std::string zeros = exr;
    zeros.replace(zeros.size() - 2 * 44 - 16, 16, std::string(16, '\0'));
    expect_error([&] { read_image(d.write("zeros.exr", zeros)); }, {"zeros.exr", "chunk 0 is at byte 0"});
    std::vector<std::string> warnings;
    expect_error(
        [&] {
            load_environment_map(test::fuzz_dir() + "/regressions/env_map/exr_uncompressed_cut_short.exr",
                                 glm::vec3(1.0f), glm::mat3(1.0f), warnings);
        },
        {"exr_uncompressed_cut_short.exr", "759 pixels need", "truncated"});
    expect_error(
        [&] {
            load_environment_map(test::fuzz_dir() + "/regressions/env_map/exr_offset_table_zero.exr", glm::vec3(1.0f),
                                 glm::mat3(1.0f), warnings);
        },
        {"exr_offset_table_zero.exr", "chunk 0 is at byte 0"});
}

// Environment scale: negative or non-finite is rejected.
TEST(Limits, EnvironmentScale) {
    TempDir d;
    expect_error(
        [&] { load_scene(scene(d, "e.json", R"("environment": {"constant": [1, 1, 1], "scale": -2},)" + kQuad)); },
        {"e.json: environment.scale"});
    expect_error(
        [&] {
            load_scene(scene(d, "f.json", R"("environment": {"constant": [1, 1, 1], "scale": [1, -1, 1]},)" + kQuad));
        },
        {"f.json: environment.scale"});
    expect_error([&] { load_scene(scene(d, "g.json", R"("environment": {"sky": {"width": 100000}},)" + kQuad)); },
                 {"g.json: environment.sky.width"});
}

// Environment filter: a map is read at the nearest texel unless the scene asks for
// "bilinear"; any other name is an error naming the key and the choices.
TEST(Limits, EnvironmentFilter) {
    TempDir d;
    const std::string sky = R"("environment": {"sky": {"width": 64})";
    EXPECT_EQ(load_scene(scene(d, "a.json", sky + "}," + kQuad)).environment.params.filter, FC_ENV_FILTER_NEAREST);
    EXPECT_EQ(load_scene(scene(d, "b.json", sky + R"(, "filter": "nearest"},)" + kQuad)).environment.params.filter,
              FC_ENV_FILTER_NEAREST);
    EXPECT_EQ(load_scene(scene(d, "c.json", sky + R"(, "filter": "bilinear"},)" + kQuad)).environment.params.filter,
              FC_ENV_FILTER_BILINEAR);
    expect_error([&] { load_scene(scene(d, "e.json", sky + R"(, "filter": "cubic"},)" + kQuad)); },
                 {"e.json: environment.filter", "cubic", "nearest or bilinear"});
}

// Out-of-resources errors say the OpenCL error, the call and what to try.
TEST(Limits, OutOfResourcesMessage) {
    for (cl_int code : {CL_OUT_OF_RESOURCES, CL_MEM_OBJECT_ALLOCATION_FAILURE, CL_OUT_OF_HOST_MEMORY}) {
        expect_error([&] { cl_call("rendering a pass", [&] { throw cl::Error(code, "clEnqueueNDRangeKernel"); }); },
                     {cl_error_name(code), "clEnqueueNDRangeKernel", "rendering a pass", "smaller image or scene"});
    }
    expect_error(
        [&] { cl_call("uploading the scene", [] { throw cl::Error(CL_INVALID_BUFFER_SIZE, "clCreateBuffer"); }); },
        {"CL_INVALID_BUFFER_SIZE", "clCreateBuffer", "uploading the scene"});
}

// A kernel that does not build: the message says so, with the OpenCL status, the device,
// the options (no fast-math flags) and the compiler's log naming the error.
TEST(Limits, KernelBuildFailureIsReportedWithItsLog) {
    expect_error([] { build_program(test::context(), "kernels/integrator/path.cl", {"this is not OpenCL C;"}); },
                 {"kernel build failed", "CL_BUILD_PROGRAM_FAILURE", "kernels/integrator/path.cl",
                  "device:", "options: -cl-std=CL1.2", "--- build log ---", "error"});
}

}  // namespace
}  // namespace facet
