// Opening the files facet reads (scenes, OBJ, MTL, environment maps, references) so that
// a hostile path cannot make it read without end or misreport why it failed: only
// regular files (after following links; /dev/zero, FIFOs and sockets are refused), at
// most a fixed size, and every error names the file and the system's reason (errno).
#pragma once

#include <cstdint>
#include <string>

namespace facet {

// The largest file facet reads into memory (text formats, images): 4 GiB.
constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t(4) << 30;

// Checks that `path` is a readable regular file of at most `max_bytes` and returns its
// size; throws facet::Error "<what> '<path>': <reason>" otherwise.
std::uint64_t check_input_file(const std::string& path, const char* what, std::uint64_t max_bytes = kMaxInputFileBytes);

// The whole file, with the checks of check_input_file.
std::string read_input_file(const std::string& path, const char* what, std::uint64_t max_bytes = kMaxInputFileBytes);

}  // namespace facet
