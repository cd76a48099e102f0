// Files that may be gzip'd (the Stanford scans ship as .ply.gz): read whole, inflated
// with zlib when they start with gzip's magic bytes.
#pragma once

#include <string>

namespace facet {

// The file's bytes (read_input_file's checks), inflated when gzip'd; the inflated size
// is held to kMaxInputFileBytes too. Throws facet::Error "<what> '<path>': <reason>".
std::string read_maybe_gzipped(const std::string& path, const char* what);

// The path's extension, lower case, looking through ".gz": "x.PLY.gz" -> ".ply".
std::string extension_under_gz(const std::string& path);

}  // namespace facet
