// Small helpers for the line-oriented text formats (OBJ, MTL): reading a file,
// splitting it into lines and fields, and strict number parsing that never throws.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace facet::text {

// The whole file; throws facet::Error "<what> '<path>': cannot open" when unreadable.
std::string read_file(const std::string& path, const char* what);

// Lines without their terminators ("\n", "\r\n" or a lone "\r"); lines[i] is line i + 1.
std::vector<std::string_view> split_lines(std::string_view text);

// Whitespace-separated fields, ignoring everything from a '#' on.
std::vector<std::string_view> split_fields(std::string_view line);

// The rest of a line after its first field, trimmed (names that may hold spaces).
std::string_view rest_after_keyword(std::string_view line);

// Strict parses: the whole field must be a number ("1e3", "-0.5", "nan", "inf" are
// numbers; "1.0abc" and "" are not).
bool parse_float(std::string_view field, float& out);
bool parse_int(std::string_view field, long& out);

// The directory part of a path ("" for a bare file name), and `rel` resolved against it.
std::string directory_of(const std::string& path);
std::string join_path(const std::string& dir, const std::string& rel);

}  // namespace facet::text
