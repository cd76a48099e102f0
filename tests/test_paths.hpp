// Folders the tests read, fixed at configure time (tests/CMakeLists.txt). They are defined in
// test_paths.cpp alone, so that no other test source depends on where the checkout lies.
#pragma once

#include <string>

namespace facet::test {

std::string scenes_dir();  // the repository's scenes/
std::string assets_dir();  // ../shared/assets beside the checkout (tests skip without it)
std::string fuzz_dir();    // tests/fuzz: the fuzzers' corpus and stored regressions

}  // namespace facet::test
