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

namespace facet {
namespace {

std::vector<std::filesystem::path> inputs(const char* harness) {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path dir = std::filesystem::path(FACET_FUZZ_DIR) / "regressions" / harness;
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

// The stored seed corpus loads (or fails cleanly) too: the harnesses' conventions hold.
TEST(FuzzRegression, SeedCorpus) {
    for (const char* h : {"scene_json", "obj_mtl", "env_map", "gltf", "ply"}) {
        const std::filesystem::path dir = std::filesystem::path(FACET_FUZZ_DIR) / "corpus" / h;
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
