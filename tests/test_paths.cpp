#include "tests/test_paths.hpp"

namespace facet::test {

std::string scenes_dir() { return FACET_SCENES_DIR; }
std::string assets_dir() { return FACET_ASSETS_DIR; }
std::string fuzz_dir() { return FACET_FUZZ_DIR; }

}  // namespace facet::test
