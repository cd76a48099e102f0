// Every input the fuzzers found a bug with (tests/fuzz/regressions/<harness>/), replayed
// through the same harness code in this (gcc) build: each must load or give a
// facet::Error, and a scene that loads must keep the invariants of tests/fuzz/fuzz_util.hpp
// (a broken invariant aborts). The fuzz build replays them too (tests/fuzz/run_fuzzers.sh).
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz/harnesses.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

std::vector<std::filesystem::path> inputs(const char* harness) {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path dir = std::filesystem::path(test::fuzz_dir()) / "regressions" / harness;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const char* harness, const std::function<void(std::string_view)>& target) {
    for (const auto& file : inputs(harness)) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NO_THROW(target(bytes));
    }
}

TEST(FuzzRegression, SceneJson) { replay("scene_json", fuzz::scene_json); }
TEST(FuzzRegression, ObjMtl) { replay("obj_mtl", fuzz::obj_mtl); }
TEST(FuzzRegression, EnvMap) { replay("env_map", fuzz::env_map); }
TEST(FuzzRegression, Gltf) { replay("gltf", fuzz::gltf); }
TEST(FuzzRegression, Ply) { replay("ply", fuzz::ply); }

// The glTF and PLY findings loaded as a user's file (load_scene): a clear error that names
// the file and the problem, or a scene (a face of 1000 vertices is a valid PLY).
TEST(FuzzRegression, GltfAndPlyFindingsFailCleanly) {
    struct Case {
        const char* file;
        const char* error;      // a part of the message, or nullptr: the file loads
        std::size_t triangles;  // when it loads: its triangles and the default light's two
    };
    const Case cases[] = {
        {"gltf/image_bufferview_outside_buffer.glb", "bufferView lies outside its buffer", 0},
        {"gltf/buffer_uri_names_its_folder.gltf", "is a directory, not a file", 0},
        {"gltf/buffer_uri_names_parent_folder.gltf", "is a directory, not a file", 0},
        // an index given as a real beyond int's range (tinygltf's int conversion is UB there)
        {"gltf/light_index_beyond_int.gltf", "light 3.33333e+115 does not exist (1 lights)", 0},
        {"gltf/draco_buffer_view_beyond_int.gltf", "bufferView must be an index", 0},
        {"ply/face_index_out_of_range.ply", "face 0 names vertex 7, but there are 3 vertices", 0},
        {"ply/face_negative_index.ply", "face 0 names vertex", 0},
        {"ply/face_of_two_vertices.ply", "no triangle with a non-zero area", 0},
        {"ply/face_of_no_vertices.ply", nullptr, 1 + 2},
        {"ply/face_of_1000_vertices.ply", nullptr, 998 + 2},  // a fan
        {"ply/binary_truncated_mid_face.ply", "element 'face' 1 has a list of 3 values, more than the file holds", 0},
        {"ply/binary_face_count_beyond_file.ply", "element 'face' 0 has a list of 200 values, more than the file", 0},
        {"ply/binary_list_count_negative.ply", "element 'face' 0 has a list count of -1 (negative)", 0},
        // Assimp 5.2 wrote past its arrays (heap corruption: fuzz_ply in CI) or read past a
        // face's index list (texcoords); facet refuses these before Assimp reads them.
        {"ply/element_vertex_twice.ply", ":7: a second element 'vertex'", 0},
        {"ply/face_and_tristrips.ply", ":9: 'tristrips' elements are not read", 0},
        {"ply/face_texcoord_without_indices.ply", ":13: element 'face' 0 has a 'texcoord' list of 6 values for 0", 0},
        {"ply/header_name_with_nul.ply", ":4: byte 0x0E in a PLY header line", 0},
        {"ply/format_line_twice.ply", ":2: expected 'format ascii|binary_little_endian", 0},
        {"ply/face_texcoord_beyond_indices.ply", ":15: element 'face' 1 has a 'texcoord' list of 8 values for 1", 0},
        {"ply/header_line_with_hash.ply", ":15: '#' in a PLY header line", 0},
        {"ply/ascii_list_count_huge.ply", ":16: byte 0x00 in the PLY body", 0},
        // a form feed ends a line for Assimp, not for the check: it read a list count of 5777...
        {"ply/ascii_body_formfeed.ply", ":20: byte 0x0C in the PLY body", 0},
    };
    for (const Case& c : cases) {
        const std::string path = (std::filesystem::path(test::fuzz_dir()) / "regressions" / c.file).string();
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path));
        try {
            const Scene scene = load_scene(path);
            EXPECT_EQ(c.error, nullptr) << "loaded, but an error was expected";
            EXPECT_EQ(scene.triangle_count(), c.triangles);
        } catch (const Error& e) {
            const std::string what = e.what();
            ASSERT_NE(c.error, nullptr) << "unexpected error: " << what;
            EXPECT_NE(what.find(path), std::string::npos) << what;
            EXPECT_NE(what.find(c.error), std::string::npos) << what;
        }
    }
}

// The stored seed corpus loads (or fails cleanly) too: the harnesses' conventions hold.
TEST(FuzzRegression, SeedCorpus) {
    for (const char* h : {"scene_json", "obj_mtl", "env_map", "gltf", "ply"}) {
        const std::filesystem::path dir = std::filesystem::path(test::fuzz_dir()) / "corpus" / h;
        for (const auto& e : std::filesystem::directory_iterator(dir)) {
            SCOPED_TRACE(e.path().string());
            std::ifstream in(e.path(), std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const std::string name(h);
            EXPECT_NO_THROW(name == "scene_json" ? fuzz::scene_json(bytes)
                            : name == "obj_mtl"  ? fuzz::obj_mtl(bytes)
                            : name == "gltf"     ? fuzz::gltf(bytes)
                            : name == "ply"      ? fuzz::ply(bytes)
                                                 : fuzz::env_map(bytes));
        }
    }
}

}  // namespace
}  // namespace facet
