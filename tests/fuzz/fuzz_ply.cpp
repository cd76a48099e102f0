// libFuzzer harness "ply": the target is facet::fuzz::ply in harnesses.hpp, which
// says what the input is; fuzz_util.hpp says what counts as a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    facet::fuzz::ply(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
