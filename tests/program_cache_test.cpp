// facet's program-binary cache (used for drivers other than PoCL, forced here with
// FACET_PROGRAM_CACHE=1): written on a source build, used on the next, and a binary
// the driver refuses falls back to a source build that replaces it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/cl/runtime.hpp"
#include "host/error.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

class ProgramCache : public testing::Test {
protected:
    void SetUp() override {
        dir_ = tmp_.dir() / "cache";
        setenv("FACET_PROGRAM_CACHE", "1", 1);
        setenv("FACET_CACHE_DIR", dir_.c_str(), 1);
    }
    void TearDown() override {
        unsetenv("FACET_PROGRAM_CACHE");
        unsetenv("FACET_CACHE_DIR");
    }
    test::TempDir tmp_;  // private to this process: ctest runs these two tests side by side
    fs::path dir_;
};

TEST_F(ProgramCache, WrittenUsedAndRebuiltWhenRefused) {
    // A nonce in the prelude keeps PoCL's own cache out of the way.
    std::vector<std::string> prelude = {"// program cache test"};
    ProgramBuild first = build_program(test::context(), "kernels/test/layout_kernels.cl", prelude);
    EXPECT_FALSE(first.from_cache);
    ASSERT_FALSE(first.cache_file.empty());
    ASSERT_TRUE(fs::exists(first.cache_file)) << first.cache_file;
    EXPECT_EQ(fs::path(first.cache_file).parent_path(), dir_);

    ProgramBuild second = build_program(test::context(), "kernels/test/layout_kernels.cl", prelude);
    EXPECT_TRUE(second.from_cache);
    EXPECT_EQ(second.cache_file, first.cache_file);
    cl::Kernel k(second.program, "report_layout");  // the cached program works

    // Other options or sources are other entries.
    ProgramBuild other = build_program(test::context(), "kernels/test/layout_kernels.cl", {"// another"});
    EXPECT_NE(other.cache_file, first.cache_file);

    std::ofstream(first.cache_file, std::ios::binary | std::ios::trunc) << "not a binary";
    ProgramBuild third = build_program(test::context(), "kernels/test/layout_kernels.cl", prelude);
    EXPECT_FALSE(third.from_cache) << "a refused binary falls back to a source build";
    cl::Kernel k3(third.program, "report_layout");
    EXPECT_GT(fs::file_size(first.cache_file), 100u) << "and the entry is replaced";
}

TEST_F(ProgramCache, OffWithZero) {
    setenv("FACET_PROGRAM_CACHE", "0", 1);
    ProgramBuild b = build_program(test::context(), "kernels/test/layout_kernels.cl", {"// cache off"});
    EXPECT_TRUE(b.cache_file.empty());
    EXPECT_FALSE(fs::exists(dir_));
}

// FACET_CL_VENDOR_OPTIONS (runtime.hpp): NVIDIA's code-generation options reach the
// driver's options (and so the cache key); an option that could change float results is
// refused by name, and the program is not built with it.
TEST_F(ProgramCache, VendorOptionsAreNvidiasCodeGenerationOnly) {
    const DeviceDesc& dev = test::context().desc();
    unsetenv("FACET_CL_VENDOR_OPTIONS");
    EXPECT_EQ(build_options_for(dev).find("-cl-nv-"), std::string::npos);
    setenv("FACET_CL_VENDOR_OPTIONS", " -cl-nv-maxrregcount=128  -cl-nv-opt-level=3 ", 1);
    EXPECT_NE(build_options_for(dev).find(" -cl-nv-maxrregcount=128 -cl-nv-opt-level=3"), std::string::npos)
        << build_options_for(dev);
    setenv("FACET_CL_VENDOR_OPTIONS", "-cl-nv-maxrregcount=128 -cl-mad-enable", 1);
    try {
        build_options_for(dev);
        ADD_FAILURE() << "-cl-mad-enable was taken";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'-cl-mad-enable'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(build_program(test::context(), "kernels/test/layout_kernels.cl", {}), Error);
    unsetenv("FACET_CL_VENDOR_OPTIONS");
}

}  // namespace
}  // namespace facet
