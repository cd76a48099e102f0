// Shared OpenCL state for the tests: one context on the default device (PoCL on CI)
// and programs built once per test process.
#pragma once

#include <string>

#include "host/cl/runtime.hpp"

namespace facet::test {

// The context every test uses (device from $FACET_TEST_DEVICE, else the default).
ClContext& context();

// The program rooted at `entry` (e.g. "kernels/test/trace_kernels.cl"), built once.
cl::Program& program(const std::string& entry);

}  // namespace facet::test
