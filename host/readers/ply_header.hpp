// A PLY header checked line by line before Assimp reads the file, so that a malformed
// header gives "file.ply:LINE: ..." (and never reaches Assimp, which loops forever on a
// header without end_header).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace facet {

struct PlyHeader {
    std::uint64_t vertices = 0, faces = 0;
    bool binary = false;
    std::size_t body_offset = 0;  // the first byte after "end_header\n"
    // An ASCII body with blank lines between elements (or a lone carriage return), written
    // one element per line as Assimp 5.2 needs it; empty when the body is read as it is.
    std::string ascii_body;
};

// Throws facet::Error naming `path` and the line when the header is not a PLY header
// (first line "ply", a format line, elements with counts and typed properties, and
// "end_header"), when it has no vertex or face element, names an element twice or has
// 'tristrips', or when the body (ASCII or binary) does not hold what the header says:
// Assimp 5.2 reads past its arrays on such files (docs/robustness.md).
PlyHeader check_ply_header(const std::string& path, std::string_view bytes);

}  // namespace facet
