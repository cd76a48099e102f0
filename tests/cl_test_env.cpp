#include "tests/cl_test_env.hpp"

#include <cstdlib>
#include <map>
#include <memory>

namespace facet::test {

ClContext& context() {
    static ClContext ctx = [] {
        const char* sel = std::getenv("FACET_TEST_DEVICE");
        return ClContext::create(sel ? sel : "");
    }();
    return ctx;
}

cl::Program& program(const std::string& entry) {
    static std::map<std::string, std::unique_ptr<cl::Program>> programs;
    auto& slot = programs[entry];
    if (!slot) slot = std::make_unique<cl::Program>(build_program(context(), entry).program);
    return *slot;
}

}  // namespace facet::test
