// The kernels' resource report (host/cl/kernel_resources.hpp): ptxas's verbose log read per
// entry function, and every kernel of a real program listed with the driver's figures.
#include <gtest/gtest.h>

#include "host/cl/kernel_resources.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

// The shape of NVIDIA's -cl-nv-verbose build log (ptxas's -v output): per entry function a
// "Compiling entry function" line, its frame and spills, then its registers.
const char* kPtxasLog = R"(ptxas info    : 0 bytes gmem
ptxas info    : Compiling entry function 'render_pass' for 'sm_90'
ptxas info    : Function properties for render_pass
    312 bytes stack frame, 40 bytes spill stores, 44 bytes spill loads
ptxas info    : Used 128 registers, 480 bytes cmem[0], 16 bytes cmem[2]
ptxas info    : Compiling entry function 'aov_pass' for 'sm_90'
ptxas info    : Function properties for aov_pass
    0 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads
ptxas info    : Used 72 registers, 480 bytes cmem[0]
ptxas info    : Function properties for fc_helper
    8 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads
)";

TEST(KernelResources, PtxasLogReadPerEntryFunction) {
    const auto figures = parse_ptxas_log(kPtxasLog);
    ASSERT_EQ(figures.count("render_pass"), 1u);
    ASSERT_EQ(figures.count("aov_pass"), 1u);
    const PtxasFigures& r = figures.at("render_pass");
    EXPECT_EQ(r.registers, 128);
    EXPECT_EQ(r.stack_bytes, 312);
    EXPECT_EQ(r.spill_store_bytes, 40);
    EXPECT_EQ(r.spill_load_bytes, 44);
    EXPECT_EQ(figures.at("aov_pass").registers, 72);
    EXPECT_EQ(figures.at("aov_pass").spill_load_bytes, 0);
    // A function with a frame but no register line keeps "unknown" registers.
    EXPECT_EQ(figures.at("fc_helper").registers, -1);
    EXPECT_EQ(figures.at("fc_helper").stack_bytes, 8);
    EXPECT_TRUE(parse_ptxas_log("").empty());
    EXPECT_TRUE(parse_ptxas_log("Used 12 registers\n").empty());  // no function named yet
}

TEST(KernelResources, EveryKernelOfTheDenoiseProgram) {
    const std::vector<KernelResources> ks = build_and_report_kernels(test::context(), "kernels/denoise/denoise.cl");
    std::vector<std::string> names;
    for (const KernelResources& k : ks) {
        names.push_back(k.kernel);
        EXPECT_GE(k.max_work_group, 1u) << k.kernel;
        EXPECT_GE(k.preferred_multiple, 1u) << k.kernel;
        // PoCL and Oclgrind print no ptxas log.
        EXPECT_EQ(k.ptxas.registers, -1) << k.kernel;
    }
    const std::vector<std::string> expected = {"denoise_accumulate", "denoise_finish", "denoise_prepare",
                                               "denoise_terms", "denoise_variance_rows"};
    EXPECT_EQ(names, expected);
}

}  // namespace
}  // namespace facet
