// libFuzzer harness "env_map": the target is facet::fuzz::env_map in harnesses.hpp, which
// says what the input is; fuzz_util.hpp says what counts as a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <OpenImageIO/imageio.h>

#include "tests/fuzz/harnesses.hpp"

// One thread: OpenEXR's thread pool costs more than these tiny images take to decode,
// and findings reproduce the same way every time.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    OIIO::attribute("threads", 1);
    OIIO::attribute("exr_threads", -1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    facet::fuzz::env_map(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
