// util/safe_write.hpp: the old file or the complete new one, never a torn one; no
// temporary left; messages with the real reason and the target's name.
#include <gtest/gtest.h>

#include <unistd.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Everything in `dir` but the names given.
int stray_files(const fs::path& dir, std::initializer_list<std::string> expected) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        bool known = false;
        for (const std::string& name : expected) known = known || e.path().filename() == name;
        n += known ? 0 : 1;
    }
    return n;
}

using test::error_of;

TEST(SafeWrite, ReplacesTheFileWhole) {
    test::TempDir dir;
    const std::string path = dir.write("a.csv", "old");
    write_bytes_safely(path, "report", "new contents");
    EXPECT_EQ(slurp(path), "new contents");
    EXPECT_EQ(stray_files(dir.dir(), {"a.csv"}), 0);
}

TEST(SafeWrite, FailedWriteKeepsTheOldFileAndNoTemporary) {
    test::TempDir dir;
    const std::string path = dir.write("a.exr", "old image");
    std::string seen_tmp;
    const std::string msg = error_of([&] {
        write_file_safely(path, "image", [&](const std::string& tmp) {
            seen_tmp = tmp;
            std::ofstream(tmp) << "half";
            throw Error(tmp + ": writing failed: No space left on device");
        });
    });
    EXPECT_EQ(slurp(path), "old image");
    EXPECT_FALSE(fs::exists(seen_tmp));
    EXPECT_EQ(stray_files(dir.dir(), {"a.exr"}), 0);
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_EQ(msg.find(fs::path(seen_tmp).filename().string()), std::string::npos)
        << "the message names the temporary: " << msg;
}

TEST(SafeWrite, VerifyFailureKeepsTheOldFile) {
    test::TempDir dir;
    const std::string path = dir.write("a.png", "old");
    EXPECT_NE(error_of([&] {
                  write_file_safely(
                      path, "image", [](const std::string& tmp) { std::ofstream(tmp) << "torn"; },
                      [&](const std::string&) { throw Error(path + ": reads back short"); });
              }),
              "");
    EXPECT_EQ(slurp(path), "old");
    EXPECT_EQ(stray_files(dir.dir(), {"a.png"}), 0);
}

TEST(SafeWrite, RenameFailureGivesTheRealReason) {
    // The old code printed "cannot move the written image into place: Success": the
    // rename's error was overwritten by the removal of the temporary.
    test::TempDir dir;
    const std::string path = dir.path("a.csv");
    const std::string msg = error_of([&] {
        write_file_safely(path, "report", [&](const std::string& tmp) {
            std::ofstream(tmp) << "x";
            fs::create_directories(fs::path(path) / "sub");  // a folder appears in the way
        });
    });
    EXPECT_NE(msg.find("Is a directory"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("Success"), std::string::npos) << msg;
    EXPECT_EQ(stray_files(dir.dir(), {"a.csv"}), 0);
}

TEST(SafeWrite, TemporariesAreUniqueShortAndKeepTheExtension) {
    test::TempDir dir;
    const std::string a = temporary_path_for(dir.path("x.exr"));
    const std::string b = temporary_path_for(dir.path("x.exr"));
    EXPECT_NE(a, b);
    EXPECT_EQ(fs::path(a).extension(), ".exr");
    EXPECT_NE(fs::path(a).filename().string().find(std::to_string(::getpid())), std::string::npos);
    const std::string long_name(NAME_MAX - 4, 'n');
    const std::string t = temporary_path_for(dir.path(long_name + ".exr"));
    EXPECT_LE(fs::path(t).filename().string().size(), std::size_t(NAME_MAX));
    EXPECT_EQ(fs::path(t).extension(), ".exr");
    // And a write through it works.
    write_bytes_safely(dir.path(long_name + ".exr"), "image", "ok");
    EXPECT_EQ(slurp(dir.path(long_name + ".exr")), "ok");
}

TEST(SafeWrite, SymlinkKeepsTheLinkAndReplacesItsTarget) {
    test::TempDir dir;
    const std::string real = dir.write("real.csv", "old");
    fs::create_symlink(real, dir.path("link.csv"));
    write_bytes_safely(dir.path("link.csv"), "report", "new");
    EXPECT_TRUE(fs::is_symlink(dir.path("link.csv")));
    EXPECT_EQ(slurp(real), "new");
}

TEST(SafeWrite, CheckOutputPathRefusesWhatCannotBeWritten) {
    test::TempDir dir;
    fs::create_directories(dir.path("folder"));
    EXPECT_NE(error_of([&] { check_output_path(dir.path("folder"), "--out"); }).find("is a folder"), std::string::npos);
    EXPECT_NE(error_of([&] { check_output_path(dir.path("folder") + "/", "--out"); }).find("folder"),
              std::string::npos);
    EXPECT_NE(error_of([&] { check_output_path("/dev/full", "--out"); }).find("not a regular file"), std::string::npos);
    const std::string msg =
        error_of([&] { check_output_path(dir.path(std::string(NAME_MAX + 1, 'n') + ".exr"), "--out"); });
    EXPECT_NE(msg.find("more than"), std::string::npos) << msg;
    // A missing folder is created; nothing is left in it.
    check_output_path(dir.path("new/sub/a.exr"), "--out");
    EXPECT_TRUE(fs::is_directory(dir.path("new/sub")));
    EXPECT_TRUE(fs::is_empty(dir.path("new/sub")));
    // A folder that cannot be created: its parent is a file.
    dir.write("file", "x");
    EXPECT_NE(error_of([&] { check_output_path(dir.path("file/a.exr"), "--out"); }).find("--out"), std::string::npos);
}

TEST(SafeWrite, ImageWriteFailureKeepsTheOldImage) {
    test::TempDir dir;
    const std::string path = dir.path("a.exr");
    write_exr(path, 2, 2, std::vector<float>(12, 0.5f));
    const std::string before = slurp(path);
    // No writer for the format: the old file stays, no temporary.
    EXPECT_NE(error_of([&] { write_exr(dir.path("a.nosuchformat"), 2, 2, std::vector<float>(12, 1.0f)); }), "");
    EXPECT_EQ(slurp(path), before);
    EXPECT_EQ(stray_files(dir.dir(), {"a.exr"}), 0);
    ImageRGB back = read_image(path);
    EXPECT_EQ(back.rgb[0], 0.5f);
}

TEST(SafeWrite, FloatImageFormats) {
    std::string why;
    EXPECT_TRUE(can_write_float_image("out/a.exr", &why)) << why;
    EXPECT_TRUE(can_write_float_image("out/a.EXR", &why)) << why;
    EXPECT_FALSE(can_write_float_image("out/a.png", &why));
    EXPECT_NE(why.find("out/a.exr"), std::string::npos) << why;
    EXPECT_FALSE(can_write_float_image("out/a", &why));
    EXPECT_NE(why.find("no extension"), std::string::npos) << why;
    EXPECT_FALSE(can_write_float_image("out/a.xyz", &why));
    EXPECT_NE(why.find(".xyz"), std::string::npos) << why;
}

}  // namespace
}  // namespace facet
