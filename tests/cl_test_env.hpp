// Shared OpenCL state for the tests: one context on the default device (PoCL on CI)
// and programs built once per test process.
#pragma once

#include <string>
#include <vector>

#include "host/cl/runtime.hpp"

namespace facet::test {

// The context every test uses (device from $FACET_TEST_DEVICE, else the default).
ClContext& context();

// The program rooted at `entry` (e.g. "kernels/test/trace_kernels.cl"), built once.
cl::Program& program(const std::string& entry);

// Runs kernel `name` of program `entry` as out[i] = f(in[i]) (arguments: in, out), one
// work item per element, and returns out.
template <typename In, typename Out>
std::vector<Out> run_elementwise(const std::string& entry, const char* name, const std::vector<In>& in) {
    ClContext& ctx = context();
    cl::Buffer a(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(In),
                 const_cast<In*>(in.data()));
    cl::Buffer b(ctx.context(), CL_MEM_WRITE_ONLY, in.size() * sizeof(Out));
    cl::Kernel k(program(entry), name);
    k.setArg(0, a), k.setArg(1, b);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(in.size()));
    std::vector<Out> out(in.size());
    ctx.queue().enqueueReadBuffer(b, CL_TRUE, 0, out.size() * sizeof(Out), out.data());
    return out;
}

}  // namespace facet::test
