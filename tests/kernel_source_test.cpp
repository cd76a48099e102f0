// The kernel source assembler (host/cl/kernel_source.cpp) on a kernels/ folder of its own
// (FACET_KERNEL_DIR): a file is inlined at every include, so an include inside a disabled
// #if block leaves the file to the next include; #line directives keep each line's own file
// and number across skipped blocks; an included file without an include guard is an error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/cl/kernel_source.hpp"
#include "host/cl/runtime.hpp"
#include "host/error.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

class KernelSource : public testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(tmp_.dir() / "kernels");
        setenv("FACET_KERNEL_DIR", (tmp_.dir() / "kernels").c_str(), 1);
    }
    void TearDown() override { unsetenv("FACET_KERNEL_DIR"); }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(tmp_.dir() / "kernels" / name) << text;
    }
    test::TempDir tmp_;
};

const char* kHelper =
    "/* a helper */\n#ifndef HELPER_CL\n#define HELPER_CL\ninline int helper(void) { return 7; }\n#endif\n";

TEST_F(KernelSource, IncludeInADisabledBlockLeavesTheFileToTheNextInclude) {
    write("helper.cl", kHelper);
    write("entry.cl",
          "#if 0\n#include \"kernels/helper.cl\"\n#endif\n#include \"kernels/helper.cl\"\n"
          "__kernel void k(__global int* out) { out[0] = helper(); }\n");
    const AssembledSource src = assemble_program("kernels/entry.cl");
    EXPECT_EQ(src.files, (std::vector<std::string>{"kernels/entry.cl", "kernels/helper.cl"}));
    const ProgramBuild build = build_program(test::context(), "kernels/entry.cl");
    cl::Buffer out(test::context().context(), CL_MEM_WRITE_ONLY, sizeof(cl_int));
    cl::Kernel k(build.program, "k");
    k.setArg(0, out);
    test::context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
    cl_int value = 0;
    test::context().queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(value), &value);
    EXPECT_EQ(value, 7);
}

TEST_F(KernelSource, ErrorsNameTheRealFileAndLineAfterSkippedBlocks) {
    write("helper.cl", kHelper);
    // Line 5 of entry.cl is an error, after a skipped block that includes helper.cl.
    write("entry.cl",
          "#if 0\n#include \"kernels/helper.cl\"\n#endif\n__kernel void k(__global int* out) {\n"
          "    out[0] = no_such_function();\n}\n");
    try {
        build_program(test::context(), "kernels/entry.cl");
        FAIL() << "the build should fail";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("kernels/entry.cl:5:"), std::string::npos) << e.what();
    }
}

TEST_F(KernelSource, IncludedFileWithoutAGuardIsAnError) {
    write("bare.cl", "inline int bare(void) { return 1; }\n");
    write("entry.cl", "#include \"kernels/bare.cl\"\n");
    try {
        assemble_program("kernels/entry.cl");
        FAIL() << "an unguarded include should be refused";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("kernels/bare.cl has no include guard"), std::string::npos) << e.what();
    }
}

TEST_F(KernelSource, IncludeCycleEnds) {
    write("a.cl", "#ifndef A_CL\n#define A_CL\n#include \"kernels/b.cl\"\ninline int a(void) { return 1; }\n#endif\n");
    write("b.cl", "#ifndef B_CL\n#define B_CL\n#include \"kernels/a.cl\"\ninline int b(void) { return 2; }\n#endif\n");
    write("entry.cl", "#include \"kernels/a.cl\"\n__kernel void k(__global int* o) { o[0] = a() + b(); }\n");
    const AssembledSource src = assemble_program("kernels/entry.cl");
    EXPECT_EQ(src.files, (std::vector<std::string>{"kernels/entry.cl", "kernels/a.cl", "kernels/b.cl"}));
}

}  // namespace
}  // namespace facet
