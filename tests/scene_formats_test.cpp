// SceneFormats.*: which files load_scene takes, and the scene files of other renderers
// (pbrt, Mitsuba, Tungsten) refused for what they are.
#include <bit>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>
#include <zlib.h>

#include "host/readers/load_scene.hpp"
#include "host/readers/ply_reader.hpp"
#include "host/readers/text_parse.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::expect_error;
using test::TempDir;

// A unit square (two triangles, one quad face) and a triangle above it, facing +z.
const std::string kPlyHeader = "element vertex 7\nproperty float x\nproperty float y\nproperty float z\n";
const std::string kPlyAsciiBody = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n0 1 1\n4 0 1 2 3\n3 4 5 6\n";

std::string ascii_ply() {
    return "ply\nformat ascii 1.0\ncomment facet test\n" + kPlyHeader +
           "element face 2\nproperty list uchar int vertex_indices\nend_header\n" + kPlyAsciiBody;
}

// The same mesh in binary, with normals (all along +x, so that the file's are seen),
// in either byte order.
std::string binary_ply(bool big_endian) {
    std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\n" + kPlyHeader +
                      "property float nx\nproperty float ny\nproperty float nz\n"
                      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    auto put = [&](const void* p, std::size_t n) {
        std::string bytes(static_cast<const char*>(p), n);
        if (big_endian) std::reverse(bytes.begin(), bytes.end());
        out += bytes;
    };
    const float v[7][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    for (const auto& p : v) {
        for (float c : p) put(&c, 4);
        for (float n : {1.0f, 0.0f, 0.0f}) put(&n, 4);
    }
    const std::vector<std::vector<std::int32_t>> faces = {{0, 1, 2, 3}, {4, 5, 6}};
    for (const auto& f : faces) {
        out += static_cast<char>(f.size());
        for (std::int32_t i : f) put(&i, 4);
    }
    return out;
}

std::string gzip(const std::string& text) {
    uLongf size = compressBound(uLong(text.size())) + 64;
    std::string out(size, '\0');
    z_stream z{};
    EXPECT_EQ(deflateInit2(&z, 6, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    z.avail_in = uInt(text.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

TEST(SceneFormats, PlyAsciiBinaryAndGzipped) {
    TempDir d;
    const std::vector<std::pair<std::string, std::string>> files = {{"a.ply", ascii_ply()},
                                                                    {"le.ply", binary_ply(false)},
                                                                    {"be.ply", binary_ply(true)},
                                                                    {"z.ply.gz", gzip(ascii_ply())}};
    for (const auto& [name, content] : files) {
        SCOPED_TRACE(name);
        Scene s;
        load_ply(d.write(name, content), s);
        ASSERT_EQ(s.triangle_count(), 3u);
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& v : s.vertices) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        EXPECT_EQ(lo, glm::vec3(0.0f));
        EXPECT_EQ(hi, glm::vec3(1.0f));
        const bool has_normals = name == "le.ply" || name == "be.ply";
        for (std::size_t t = 0; t < 3; ++t) {
            EXPECT_NEAR(test::face_normal(s, t).z, 1.0f, 1e-6f);  // winding kept
            EXPECT_NEAR(s.shading[t].n0[has_normals ? 0 : 2], 1.0f, 1e-6f);
        }
        ASSERT_EQ(s.normal_sources.size(), 1u);
        EXPECT_NE(s.normal_sources[0].find(has_normals ? "9 corners from the file" : "9 smoothed"), std::string::npos)
            << s.normal_sources[0];
    }
}

TEST(SceneFormats, PlyOnItsOwnAndInJson) {
    TempDir d;
    d.write("mesh.ply", ascii_ply());
    const Scene alone = load_scene(d.path("mesh.ply"));
    EXPECT_EQ(alone.triangle_count(), 3u + 2u);  // and the default light's quad
    EXPECT_EQ(alone.lights.size(), 3u);          // the quad's two triangles and the white environment
    EXPECT_EQ(alone.camera.target, glm::vec3(0.5f));
    const Scene json = load_scene(test::scene(d, "s.json", R"("meshes": [{"file": "mesh.ply",
        "transform": {"scale": [-1, 1, 1]}, "normals": "flat"}])"));
    ASSERT_EQ(json.triangle_count(), 3u);
    EXPECT_EQ(json.vertices[1].x, -1.0f);
    EXPECT_NEAR(test::face_normal(json, 0).z, 1.0f, 1e-6f);  // mirrored, front face kept
    expect_error(
        [&] {
            load_scene(test::scene(d, "m.json", R"("materials": {"b": {}}, "meshes": [{"file": "mesh.ply",
        "materials": {"a": "b"}}])"));
        },
        {"m.json", "meshes[0].materials", "only an OBJ has"});
}

TEST(SceneFormats, BadPlyFilesNameTheFile) {
    TempDir d;
    expect_error([&] { load_scene(d.write("text.ply", "solid cube\n")); }, {"text.ply:1:", "not a PLY file"});
    const std::string header = ascii_ply().substr(0, ascii_ply().find("end_header"));
    expect_error([&] { load_scene(d.write("head.ply", header)); }, {"head.ply:", "no 'end_header'"});
    expect_error([&] { load_scene(d.write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty vec3 p\n")); },
                 {"type.ply:4:", "property TYPE NAME"});
    std::string out_of_range = ascii_ply();
    out_of_range.replace(out_of_range.find("4 0 1 2 3"), 9, "4 0 1 2 9");
    expect_error([&] { load_scene(d.write("range.ply", out_of_range)); }, {"range.ply"});
    const std::string full = ascii_ply();
    expect_error([&] { load_scene(d.write("cut.ply", full.substr(0, full.size() / 2))); }, {"cut.ply"});
    expect_error([&] { load_scene(d.write("cut.ply.gz", gzip(full).substr(0, 20))); }, {"cut.ply.gz", "gzip"});
    expect_error([&] { load_scene(d.write("empty.ply", "ply\nformat ascii 1.0\nend_header\n")); },
                 {"empty.ply", "no vertices or no faces"});
}

TEST(SceneFormats, PbrtFilesAreNamed) {
    TempDir d;
    const std::string v4 =
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\n"
        "ColorSpace \"srgb\"\nWorldBegin\nShape \"sphere\" \"float radius\" 1\n";
    expect_error([&] { load_scene(d.write("scene.pbrt", v4)); },
                 {"scene.pbrt: not a facet scene: this looks like a pbrt-v4 file"});
    expect_error([&] { load_scene(d.write("old.pbrt", v4 + "WorldEnd\n")); }, {"old.pbrt", "a pbrt-v3 file"});
    // By content under another extension.
    expect_error([&] { load_scene(d.write("scene.txt", v4)); }, {"scene.txt", "a pbrt-v4 file"});
}

TEST(SceneFormats, MitsubaFilesAreNamed) {
    TempDir d;
    expect_error(
        [&] {
            load_scene(d.write("cbox.xml",
                               "<?xml version=\"1.0\"?>\n<scene version=\"3.0.0\">\n"
                               "  <integrator type=\"path\"/>\n</scene>\n"));
        },
        {"cbox.xml: not a facet scene: this looks like a Mitsuba 3 scene"});
    expect_error([&] { load_scene(d.write("old.xml", "<scene version=\"0.6.0\">\n</scene>\n")); },
                 {"old.xml", "a Mitsuba 0.6 scene"});
    // Other XML is an unknown format, not Mitsuba.
    expect_error([&] { load_scene(d.write("other.xml", "<?xml version=\"1.0\"?>\n<COLLADA/>\n")); },
                 {"other.xml", "unknown scene format"});
}

TEST(SceneFormats, TungstenSceneIsNamed) {
    TempDir d;
    const auto p = d.write("scene.json", R"({"media": [], "bsdfs": [{"name": "white", "albedo": 0.8}],
        "primitives": [{"type": "quad", "bsdf": "white"}],
        "camera": {"type": "pinhole"}, "integrator": {"type": "path_tracer"}, "renderer": {"spp": 64}})");
    expect_error([&] { load_scene(p); }, {"scene.json: not a facet scene: this looks like a Tungsten scene"});
}

TEST(SceneFormats, UnknownExtensionNamesTheFormats) {
    TempDir d;
    expect_error([&] { load_scene(d.write("model.abc", "Ogawa")); },
                 {"model.abc", "unknown scene format '.abc'", ".obj", ".ply", ".gltf", ".stl (STL)", ".fbx (FBX)",
                  ".dae (Collada)", ".3ds (3DS)"});
}

// `facet render scenes/`: the error says it is a folder, not "unknown scene format ''".
TEST(SceneFormats, FolderIsNamedAFolder) {
    TempDir d;
    expect_error([&] { load_scene(d.dir().string()); }, {"is a folder, not a scene file"});
}

// An MTL written on Windows names ".\\tex.png": read as "./tex.png" when no file has the
// backslash in its name.
TEST(SceneFormats, WindowsTexturePathIsNormalised) {
    TempDir d;
    const std::string tex = d.write("tex.png", "x");
    EXPECT_EQ(text::join_asset_path(d.dir().string(), ".\\tex.png"), tex);
    EXPECT_EQ(text::join_asset_path(d.dir().string(), "tex.png"), tex);
}

}  // namespace
}  // namespace facet
