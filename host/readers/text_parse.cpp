#include "host/readers/text_parse.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/util/input_file.hpp"

namespace facet::text {

std::string read_file(const std::string& path, const char* what) {
    std::string text = read_input_file(path, what);  // regular files only, size-capped, errno named
    // UTF-8's byte-order mark, which Windows editors write, is not text: left in, it glued
    // itself to the first line's keyword (an OBJ's first vertex was dropped).
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    else if (text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF')))
        throw Error(
            fmt::format("{} '{}': UTF-16 text (it begins with a UTF-16 byte-order mark); it is read as ASCII "
                        "or UTF-8: save it as UTF-8",
                        what, path));
    return text;
}

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(start, i - start));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        start = i + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

// Blanks and tabs only, as tinyobjloader's IS_SPACE: with '\v' or '\f' counted here too,
// "vn\f0 0 1" was a normal to the validator but no statement to tinyobjloader, and face
// indices checked against the validator's count overran tinyobjloader's arrays (found by
// fuzz_obj_mtl).
static bool is_space(char c) { return c == ' ' || c == '\t'; }

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        if (i >= line.size() || line[i] == '#') break;
        std::size_t start = i;
        while (i < line.size() && !is_space(line[i]) && line[i] != '#') ++i;
        fields.push_back(line.substr(start, i - start));
    }
    return fields;
}

std::string_view rest_after_keyword(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && is_space(line[i])) ++i;
    while (i < line.size() && !is_space(line[i])) ++i;
    while (i < line.size() && is_space(line[i])) ++i;
    std::size_t end = line.size();
    while (end > i && is_space(line[end - 1])) --end;
    return line.substr(i, end - i);
}

bool parse_float(std::string_view field, float& out) {
    if (field.empty()) return false;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (*first == '+') ++first;  // from_chars rejects a leading '+', OBJ writers emit it
    if (first == last) return false;
    auto [ptr, ec] = std::from_chars(first, last, out);
    if (ec == std::errc::result_out_of_range) return false;
    return ec == std::errc() && ptr == last;
}

const char* number_problem(std::string_view field) {
    if (!field.empty() && field[0] == '+') field.remove_prefix(1);
    float v = 0.0f;
    const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
    if (ec == std::errc::result_out_of_range && ptr == field.data() + field.size())
        return "out of range for a float (about 1.2e-38 to 3.4e38 in magnitude)";
    return "not a valid number";
}

bool parse_int(std::string_view field, long& out) {
    if (field.empty()) return false;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (*first == '+') ++first;
    if (first == last) return false;
    auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

std::string directory_of(const std::string& path) { return std::filesystem::path(path).parent_path().string(); }

std::string join_path(const std::string& dir, const std::string& rel) {
    std::filesystem::path p(rel);
    if (p.is_absolute() || dir.empty()) return p.string();
    return (std::filesystem::path(dir) / p).string();
}

std::string join_asset_path(const std::string& dir, const std::string& rel) {
    const std::string as_written = join_path(dir, rel);
    std::error_code ec;
    if (rel.find('\\') == std::string::npos || std::filesystem::exists(as_written, ec)) return as_written;
    std::string slashed = rel;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    return join_path(dir, std::filesystem::path(slashed).lexically_normal().string());
}

}  // namespace facet::text
