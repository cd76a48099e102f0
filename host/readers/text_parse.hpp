// Small helpers for the line-oriented text formats (OBJ, MTL): reading a file,
// splitting it into lines and fields, and strict number parsing that never throws.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace facet::text {

// The whole file (read_input_file: a regular file within kMaxInputFileBytes) without a UTF-8
// byte-order mark; throws facet::Error "<what> '<path>': <reason>" when it cannot be read or
// is UTF-16 (it begins with a UTF-16 byte-order mark).
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

// Why parse_float refused a field: "out of range for a float (about 1.2e-38 to 3.4e38)"
// or "not a valid number".
const char* number_problem(std::string_view field);

// The directory part of a path ("" for a bare file name), and `rel` resolved against it.
std::string directory_of(const std::string& path);
std::string join_path(const std::string& dir, const std::string& rel);
// A file named by a model (an MTL texture) in `dir`: as join_path, but a name written on
// Windows (".\\tex.jpg", "maps\\a.png") has its backslashes read as separators when the
// name as written does not exist.
std::string join_asset_path(const std::string& dir, const std::string& rel);

}  // namespace facet::text
