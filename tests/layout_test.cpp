// The device lays out every shared struct exactly as the host does.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "tests/cl_test_env.hpp"
#include "kernels/shared/all.h"
#include "kernels/shared/layout_fields.h"

namespace facet {
namespace {

TEST(Layout, DeviceMatchesHost) {
    std::vector<int> host;
    std::vector<std::string> names;
#define FC_SIZE(T)                  \
    host.push_back(int(sizeof(T))); \
    names.push_back("sizeof(" #T ")");
#define FC_OFFSET(T, f)                  \
    host.push_back(int(offsetof(T, f))); \
    names.push_back("offsetof(" #T ", " #f ")");
    FC_LAYOUT_STRUCTS(FC_SIZE)
    FC_LAYOUT_FIELDS(FC_OFFSET)
#undef FC_SIZE
#undef FC_OFFSET

    ClContext& ctx = test::context();
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, host.size() * sizeof(int));
    cl::Kernel k(test::program("kernels/test/layout_kernels.cl"), "report_layout");
    k.setArg(0, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
    std::vector<int> device(host.size());
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, device.size() * sizeof(int), device.data());
    for (std::size_t i = 0; i < host.size(); ++i) EXPECT_EQ(device[i], host[i]) << names[i];
}

}  // namespace
}  // namespace facet
