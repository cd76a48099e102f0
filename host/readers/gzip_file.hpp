// Files that may be gzip'd (the Stanford scans ship as .ply.gz): read whole, inflated
// with zlib when they start with gzip's magic bytes.
#pragma once

#include <cstdint>
#include <string>

namespace facet {

// The most bytes a gzip'd file may inflate to: 1 GiB, beyond the largest scans shipped
// gzip'd (a PLY of 40 million triangles), so that a small file of zeros cannot claim the
// memory (a 5 MB .ply.gz inflated to 4.2 GB before any check).
constexpr std::uint64_t kMaxInflatedBytes = std::uint64_t(1) << 30;

// The file's bytes (read_input_file's checks), inflated when gzip'd, stopping with an
// error as soon as the inflated bytes pass `max_inflated` (the memory is taken as the
// bytes come, never more than that). Throws facet::Error "<what> '<path>': <reason>".
std::string read_maybe_gzipped(const std::string& path, const char* what,
                               std::uint64_t max_inflated = kMaxInflatedBytes);

// The path's extension, lower case, looking through ".gz": "x.PLY.gz" -> ".ply".
std::string extension_under_gz(const std::string& path);

}  // namespace facet
