// PLY headers, checked line by line.
#include "host/readers/ply_header.hpp"

#include <vector>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/text_parse.hpp"

namespace facet {
namespace {

bool scalar_type(std::string_view t) {
    for (std::string_view k : {"char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
                               "int16", "uint16", "int32", "uint32", "float32", "float64"})
        if (t == k) return true;
    return false;
}

// The elements of an ASCII body checked against the header: each on its own line (PLY's
// rule) with exactly its properties' values, so a line with a number missing is an error
// naming it rather than shifting every later value by one; and a list whose count is more
// than the file holds is refused before Assimp allocates for it (minutes for a count of
// 7777777777777: fuzz_ply). `lists[e]` says which properties of element e are lists.
// `first_line` is the body's first line number in the file.
void check_ascii_body(const std::string& path, std::string_view body, const std::vector<std::string>& names,
                      const std::vector<std::uint64_t>& counts, const std::vector<std::vector<bool>>& lists,
                      int first_line) {
    std::size_t pos = 0;
    long line = first_line;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    auto next = [&]() -> std::string_view {  // the next value on this line, "" at its end
        while (pos < body.size() && blank(body[pos])) ++pos;
        const std::size_t start = pos;
        while (pos < body.size() && !blank(body[pos]) && body[pos] != '\n') ++pos;
        return body.substr(start, pos - start);
    };
    for (std::size_t e = 0; e < names.size(); ++e)
        for (std::uint64_t i = 0; i < counts[e]; ++i) {
            while (pos < body.size() && (blank(body[pos]) || body[pos] == '\n'))  // blank lines between
                if (body[pos++] == '\n') ++line;
            if (pos >= body.size())
                throw Error(fmt::format("{}: the PLY file ends inside element '{}' {} of {} (cut short)", path,
                                        names[e], i, counts[e]));
            std::size_t values = 0, wanted = 0;
            auto short_line = [&]() {
                return Error(
                    fmt::format("{}:{}: element '{}' {} has {} values on its line, fewer than its "
                                "properties need",
                                path, line, names[e], i, values));
            };
            for (bool list : lists[e]) {
                const std::string_view t = next();
                ++wanted;
                if (t.empty()) throw short_line();
                ++values;
                if (!list) continue;
                long n = 0;
                if (!text::parse_int(t, n) || n < 0 || std::uint64_t(n) > (body.size() - pos) / 2 + 1)
                    throw Error(fmt::format("{}: element '{}' {} has a list of '{}' values, more than the file holds",
                                            path, names[e], i, t));
                for (long k = 0; k < n; ++k, ++wanted, ++values)
                    if (next().empty()) throw short_line();
            }
            if (!next().empty())
                throw Error(
                    fmt::format("{}:{}: element '{}' {} has more values on its line than the {} its "
                                "properties take",
                                path, line, names[e], i, wanted));
        }
}

}  // namespace

PlyHeader check_ply_header(const std::string& path, std::string_view bytes) {
    PlyHeader h;
    auto fail = [&](int line, const std::string& what) { throw Error(fmt::format("{}:{}: {}", path, line, what)); };
    std::size_t pos = 0;
    std::string element;
    std::uint64_t elements = 0;  // every element's count, summed
    std::vector<std::string> names;
    std::vector<std::uint64_t> counts;
    std::vector<std::vector<bool>> lists;  // per element, whether each property is a list
    bool format = false;
    int body_line = 0;  // the first line after end_header
    for (int line = 1;; ++line) {
        const std::size_t end = bytes.find('\n', pos);
        if (end == std::string_view::npos || line > 100000)
            fail(line, "the PLY header has no 'end_header' line (the file is cut short or not a PLY file)");
        std::string_view text = bytes.substr(pos, end - pos);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        pos = end + 1;
        // PLY has no '#' comments: split_fields would cut "end_header#" to end_header
        // while Assimp reads on past it into the binary data (and crashed there: fuzz_ply),
        // so a '#' anywhere but in a comment line is an error.
        const auto f = text::split_fields(text);
        if (text.find('#') != std::string_view::npos && !(!f.empty() && (f[0] == "comment" || f[0] == "obj_info")))
            fail(line, "'#' in a PLY header line (PLY has no '#' comments; use a 'comment' line)");
        if (line == 1) {
            if (f.size() != 1 || f[0] != "ply") fail(1, "not a PLY file (the first line must be 'ply')");
            continue;
        }
        if (f.empty() || f[0] == "comment" || f[0] == "obj_info") continue;
        if (f[0] == "end_header") {
            body_line = line + 1;
            break;
        }
        if (f[0] == "format") {
            if (f.size() != 3 || (f[1] != "ascii" && f[1] != "binary_little_endian" && f[1] != "binary_big_endian"))
                fail(line, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
            h.binary = f[1] != "ascii";
            format = true;
        } else if (f[0] == "element") {
            long count = 0;
            if (f.size() != 3 || !text::parse_int(f[2], count) || count < 0 || count > (1L << 40))
                fail(line, "expected 'element NAME COUNT' with a count in [0, 2^40]");
            element = std::string(f[1]);
            elements += std::uint64_t(count);
            names.push_back(element);
            counts.push_back(std::uint64_t(count));
            lists.emplace_back();
            if (element == "vertex") h.vertices = std::uint64_t(count);
            if (element == "face") h.faces = std::uint64_t(count);
        } else if (f[0] == "property") {
            if (element.empty()) fail(line, "a property before any element");
            const bool list = f.size() == 5 && f[1] == "list" && scalar_type(f[2]) && scalar_type(f[3]);
            if (!list && !(f.size() == 3 && scalar_type(f[1])))
                fail(line, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
            lists.back().push_back(list);
        } else {
            fail(line, fmt::format("unknown PLY header line '{}'", f[0]));
        }
    }
    if (!format) fail(2, "the PLY header has no 'format' line");
    if (h.vertices == 0 || h.faces == 0)
        throw Error(fmt::format("{}: the PLY file has no vertices or no faces (element vertex / element face)", path));
    // Every element takes at least one byte (binary) or two (ASCII: a number and a blank):
    // a header promising more is cut short or corrupt (and would make Assimp allocate for it).
    if (elements > (bytes.size() - pos) / (h.binary ? 1 : 2) + 1)
        throw Error(
            fmt::format("{}: the PLY header promises {} elements, but only {} bytes follow it (the file is "
                        "cut short or corrupt)",
                        path, elements, bytes.size() - pos));
    h.body_offset = pos;
    if (!h.binary) check_ascii_body(path, bytes.substr(pos), names, counts, lists, body_line);
    return h;
}

}  // namespace facet
