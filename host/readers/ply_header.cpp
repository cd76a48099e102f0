// PLY headers, checked line by line, and the body walked against them.
#include "host/readers/ply_header.hpp"

#include <vector>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/text_parse.hpp"

namespace facet {
namespace {

// The bytes of one value of a PLY scalar type, 0 when `t` is not one.
int scalar_bytes(std::string_view t) {
    for (std::string_view k : {"char", "uchar", "int8", "uint8"})
        if (t == k) return 1;
    for (std::string_view k : {"short", "ushort", "int16", "uint16"})
        if (t == k) return 2;
    for (std::string_view k : {"int", "uint", "float", "int32", "uint32", "float32"})
        if (t == k) return 4;
    for (std::string_view k : {"double", "float64"})
        if (t == k) return 8;
    return 0;
}

struct PlyProperty {
    std::string name;
    bool list = false;
    int count_bytes = 0;  // a list's count type
    bool count_signed = false;
    int value_bytes = 0;
    char value_kind = 'f';  // 'f' float, 'i' signed, 'u' unsigned integer
};

char value_kind(std::string_view t) {
    if (t == "float" || t == "float32" || t == "double" || t == "float64") return 'f';
    return t[0] == 'u' ? 'u' : 'i';
}

// Whether an ASCII value reads as a whole the way Assimp 5.2 reads its type: an unsigned
// integer as digits (strtoul10), a signed one with an optional sign (strtol10), a real as
// fast_atoreal_move does (sign, digits, point, exponent, or nan / inf / infinity). Where
// Assimp stops inside a value it takes the rest for the next one ("1-5" as 1 and -5), so
// a list count could be read from a place facet's walk did not check.
bool reads_whole(std::string_view t, char kind) {
    std::size_t k = 0;
    auto digits = [&]() {
        const std::size_t s = k;
        while (k < t.size() && t[k] >= '0' && t[k] <= '9') ++k;
        return k - s;
    };
    if (kind != 'u' && k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
    if (kind != 'f') return digits() > 0 && k == t.size();
    std::string word(t.substr(k));
    for (char& c : word) c = char(c | 0x20);  // lower case for letters
    if (word == "nan" || word == "inf" || word == "infinity") return true;
    std::size_t n = digits();
    if (k < t.size() && t[k] == '.') {
        ++k;
        n += digits();
    }
    if (n == 0) return false;
    if (k < t.size() && (t[k] == 'e' || t[k] == 'E')) {
        ++k;
        if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
        if (digits() == 0) return false;
    }
    return k == t.size();
}

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

// Assimp 5.2 reads a face's 'texcoord' list as two values per entry of its vertex index
// list, indexing that list without a bound (and a null one when the face has none): a
// list of more than two per vertex is refused. Assimp takes the last property of each
// name, so the last lengths seen are what count. `line` is 0 in a binary body.
struct FaceLists {
    long indices = -1, texcoords = -1;  // -1: the face has no such list
    void note(const PlyProperty& p, long n) {
        if (p.name == "vertex_index" || p.name == "vertex_indices") indices = n;
        if (p.name == "texcoord") texcoords = n;
    }
    void check(const std::string& path, long line, std::uint64_t i) const {
        if (texcoords <= 0 || texcoords <= 2 * (indices < 0 ? 0 : indices)) return;
        throw Error(fmt::format(
            "{}{}: element 'face' {} has a 'texcoord' list of {} values for {} vertices (two "
            "per vertex at most)",
            path, line > 0 ? fmt::format(":{}", line) : std::string(), i, texcoords, indices < 0 ? 0 : indices));
    }
};

// The elements of an ASCII body checked against the header: each on its own line (PLY's
// rule) with exactly its properties' values, so a line with a number missing is an error
// naming it rather than shifting every later value by one; and a list whose count is more
// than the file holds is refused before Assimp allocates for it (minutes for a count of
// 7777777777777: fuzz_ply). `first_line` is the body's first line number in the file.
// Assimp 5.2 reads one element per line and takes a second blank line in a row (a first
// one after "\r\n"), a line of blanks, or a lone carriage return for an element, so such a
// body loaded with elements shifted (a face lost, silently). Returns whether the body has
// one; with `out`, writes it as Assimp reads it (one line per element, values as written).
bool check_ascii_body(const std::string& path, std::string_view body, const std::vector<PlyElement>& elements,
                      int first_line, std::string* out) {
    std::size_t pos = 0;
    long line = first_line;
    bool rewrite = false, first = true;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    auto lone_cr = [&]() { return body[pos] == '\r' && pos + 1 < body.size() && body[pos + 1] != '\n'; };
    auto next = [&]() -> std::string_view {  // the next value on this line, "" at its end
        while (pos < body.size() && blank(body[pos])) {
            if (lone_cr()) rewrite = true;
            ++pos;
        }
        const std::size_t start = pos;
        while (pos < body.size() && !blank(body[pos]) && body[pos] != '\n') {
            const auto b = static_cast<unsigned char>(body[pos]);
            if (b < 0x20 || b == 0x7F)
                throw Error(
                    fmt::format("{}:{}: byte 0x{:02X} in the PLY body (an ASCII body holds numbers)", path, line, b));
            ++pos;
        }
        const std::string_view t = body.substr(start, pos - start);
        if (out && !t.empty()) {
            if (!out->empty() && out->back() != '\n') out->push_back(' ');
            out->append(t);
        }
        return t;
    };
    for (const PlyElement& el : elements)
        for (std::uint64_t i = 0; i < el.count; ++i) {
            int newlines = 0;
            while (pos < body.size() && (blank(body[pos]) || body[pos] == '\n')) {  // blank lines between
                if (lone_cr()) rewrite = true;
                if (body[pos++] == '\n') ++line, ++newlines;
            }
            if (newlines > (first ? 0 : 1)) rewrite = true;
            first = false;
            if (pos >= body.size())
                throw Error(fmt::format("{}: the PLY file ends inside element '{}' {} of {} (cut short)", path, el.name,
                                        i, el.count));
            if (out && !out->empty()) out->push_back('\n');
            std::size_t values = 0, wanted = 0;
            auto short_line = [&]() {
                return Error(
                    fmt::format("{}:{}: element '{}' {} has {} values on its line, fewer than its "
                                "properties need",
                                path, line, el.name, i, values));
            };
            FaceLists face;
            for (const PlyProperty& p : el.properties) {
                const std::string_view t = next();
                ++wanted;
                if (t.empty()) throw short_line();
                ++values;
                auto check_value = [&](std::string_view v, char kind) {
                    if (!reads_whole(v, kind))
                        throw Error(fmt::format("{}:{}: element '{}' {} has '{}' where its property '{}' needs {}",
                                                path, line, el.name, i, v, p.name,
                                                kind == 'f'   ? "a number"
                                                : kind == 'i' ? "an integer"
                                                              : "an unsigned integer (digits)"));
                };
                if (!p.list) {
                    check_value(t, p.value_kind);
                    continue;
                }
                // Digits only: Assimp reads an unsigned count with strtoul10 (no sign).
                long n = 0;
                if (!reads_whole(t, 'u') || !text::parse_int(t, n) || std::uint64_t(n) > (body.size() - pos) / 2 + 1)
                    throw Error(fmt::format("{}: element '{}' {} has a list of '{}' values, more than the file holds",
                                            path, el.name, i, t));
                face.note(p, n);
                for (long k = 0; k < n; ++k, ++wanted, ++values) {
                    const std::string_view v = next();
                    if (v.empty()) throw short_line();
                    check_value(v, p.value_kind);
                }
            }
            if (!next().empty())
                throw Error(
                    fmt::format("{}:{}: element '{}' {} has more values on its line than the {} its "
                                "properties take",
                                path, line, el.name, i, wanted));
            if (el.name == "face") face.check(path, line, i);
        }
    if (out) out->push_back('\n');
    return rewrite;
}

// A binary body walked against the header: every list's count read (in the file's byte
// order) and its values found inside the file, so a count beyond it or a file cut short is
// an error naming the element before Assimp reads (past the end) or allocates for it.
void check_binary_body(const std::string& path, std::string_view body, const std::vector<PlyElement>& elements,
                       bool big_endian) {
    std::size_t pos = 0;
    auto cut_short = [&](const PlyElement& el, std::uint64_t i) {
        return Error(
            fmt::format("{}: the PLY file ends inside element '{}' {} of {} (cut short)", path, el.name, i, el.count));
    };
    for (const PlyElement& el : elements)
        for (std::uint64_t i = 0; i < el.count; ++i) {
            FaceLists face;
            for (const PlyProperty& p : el.properties) {
                if (!p.list) {
                    if (body.size() - pos < std::size_t(p.value_bytes)) throw cut_short(el, i);
                    pos += std::size_t(p.value_bytes);
                    continue;
                }
                if (body.size() - pos < std::size_t(p.count_bytes)) throw cut_short(el, i);
                unsigned char b[4] = {};
                for (int k = 0; k < p.count_bytes; ++k)
                    b[k] = static_cast<unsigned char>(body[pos + std::size_t(big_endian ? p.count_bytes - 1 - k : k)]);
                pos += std::size_t(p.count_bytes);
                const std::uint32_t u = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
                                        std::uint32_t(b[3]) << 24;
                const int bits = 8 * p.count_bytes;
                if (p.count_signed && (u >> (bits - 1)) & 1u)
                    throw Error(fmt::format("{}: element '{}' {} has a list count of {} (negative)", path, el.name, i,
                                            std::int64_t(u) - (std::int64_t(1) << bits)));
                if (std::uint64_t(u) * std::uint64_t(p.value_bytes) > body.size() - pos)
                    throw Error(fmt::format("{}: element '{}' {} has a list of {} values, more than the file holds",
                                            path, el.name, i, u));
                face.note(p, long(u));
                pos += std::size_t(u) * std::size_t(p.value_bytes);
            }
            if (el.name == "face") face.check(path, 0, i);
        }
}

}  // namespace

PlyHeader check_ply_header(const std::string& path, std::string_view bytes) {
    PlyHeader h;
    auto fail = [&](int line, const std::string& what) { throw Error(fmt::format("{}:{}: {}", path, line, what)); };
    std::size_t pos = 0;
    std::uint64_t total = 0;  // every element's count, summed
    std::vector<PlyElement> elements;
    bool format = false, big_endian = false;
    int body_line = 0;            // the first line after end_header
    int break_in_properties = 0;  // a comment or blank line after an element line, until a property
    bool break_is_comment = false;
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
        const bool comment = !f.empty() && (f[0] == "comment" || f[0] == "obj_info");
        if (text.find('#') != std::string_view::npos && !comment)
            fail(line, "'#' in a PLY header line (PLY has no '#' comments; use a 'comment' line)");
        // A header is text: a control byte (a NUL, a lone carriage return, ...) ends a field
        // or a line for Assimp where it does not for this check, so the two would read
        // different headers and Assimp would take the body at another step (it allocated
        // 32 GB for a "count" so read: fuzz_ply). Bytes above 127 only in comments.
        for (const char c : text) {
            const auto b = static_cast<unsigned char>(c);
            if ((b < 0x20 && b != '\t') || b == 0x7F || (b >= 0x80 && !comment))
                fail(line, fmt::format("byte 0x{:02X} in a PLY header line (a header is ASCII text{})", b,
                                       b >= 0x80 ? ", beyond comments" : ""));
        }
        if (line == 1) {
            if (f.size() != 1 || f[0] != "ply") fail(1, "not a PLY file (the first line must be 'ply')");
            continue;
        }
        // Assimp 5.2 takes the second line for the format line, whatever follows: a format
        // given elsewhere, or twice, would have it read another body than the one checked
        // here (an ASCII "format" on line 2 and a binary one on line 3: 15 GB, fuzz_ply).
        if (line == 2 && (f.empty() || f[0] != "format"))
            fail(2, "the second line of a PLY file must be its 'format' line");
        // Assimp 5.2 ends an element's property list at a comment or blank line and skips
        // the properties after it as unknown lines: its body layout would not be this one.
        if (f.empty() || comment) {
            if (!elements.empty() && break_in_properties == 0) {
                break_in_properties = line;
                break_is_comment = comment;
            }
            continue;
        }
        if (f[0] == "property" && break_in_properties > 0)
            fail(break_in_properties,
                 fmt::format("a {} between the properties of element '{}' (Assimp 5.2 ends the element there): "
                             "put it before the 'element' line",
                             break_is_comment ? "comment" : "blank line", elements.back().name));
        break_in_properties = 0;
        if (f[0] == "end_header") {
            body_line = line + 1;
            break;
        }
        if (f[0] == "format") {
            if (format) fail(line, "a second 'format' line");
            if (f.size() != 3 || (f[1] != "ascii" && f[1] != "binary_little_endian" && f[1] != "binary_big_endian") ||
                !reads_whole(f[2], 'f'))
                fail(line, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
            h.binary = f[1] != "ascii";
            big_endian = f[1] == "binary_big_endian";
            format = true;
        } else if (f[0] == "element") {
            // Digits only, below 2^32: Assimp reads the count with strtoul10 (no sign, an
            // unsigned int), and any other reading would walk another body than Assimp's.
            long count = 0;
            if (f.size() != 3 || !reads_whole(f[2], 'u') || !text::parse_int(f[2], count) || count > 0xFFFFFFFFL)
                fail(line, "expected 'element NAME COUNT' with a count of digits only, below 2^32");
            // Assimp 5.2 takes 'element TextureFile' for a texture's file name, with no count.
            if (f[1] == "TextureFile")
                fail(line,
                     "an element named 'TextureFile' (Assimp 5.2 reads that name as a texture file, not an element)");
            // Assimp 5.2 sizes its arrays by the first 'vertex' and the first 'face' or
            // 'tristrips' element and writes every later one's past them (heap corruption,
            // found by fuzz_ply); and of a strip it keeps one triangle. So each name once,
            // and strips refused.
            for (const PlyElement& e : elements)
                if (e.name == f[1])
                    fail(line, fmt::format("a second element '{}' (each element is declared once)", f[1]));
            if (f[1] == "tristrips")
                fail(line,
                     "'tristrips' elements are not read (Assimp 5.2 keeps one triangle of each strip): write the "
                     "triangles as a 'face' element");
            elements.push_back({std::string(f[1]), std::uint64_t(count), {}});
            total += std::uint64_t(count);
            if (f[1] == "vertex") h.vertices = std::uint64_t(count);
            if (f[1] == "face") h.faces = std::uint64_t(count);
        } else if (f[0] == "property") {
            if (elements.empty()) fail(line, "a property before any element");
            PlyProperty p;
            if (f.size() == 5 && f[1] == "list" && scalar_bytes(f[2]) > 0 && scalar_bytes(f[3]) > 0) {
                if (value_kind(f[2]) == 'f')
                    fail(line, fmt::format("a list's count type must be an integer type, not '{}'", f[2]));
                p = {std::string(f[4]), true, scalar_bytes(f[2]), value_kind(f[2]) == 'i', scalar_bytes(f[3]),
                     value_kind(f[3])};
            } else if (f.size() == 3 && scalar_bytes(f[1]) > 0) {
                p = {std::string(f[2]), false, 0, false, scalar_bytes(f[1]), value_kind(f[1])};
            } else {
                fail(line, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
            }
            elements.back().properties.push_back(std::move(p));
        } else {
            fail(line, fmt::format("unknown PLY header line '{}'", f[0]));
        }
    }
    if (h.vertices == 0 || h.faces == 0)
        throw Error(fmt::format("{}: the PLY file has no vertices or no faces (element vertex / element face)", path));
    // Every element takes at least one byte (binary) or two (ASCII: a number and a blank):
    // a header promising more is cut short or corrupt (and would make Assimp allocate for it).
    if (total > (bytes.size() - pos) / (h.binary ? 1 : 2) + 1)
        throw Error(
            fmt::format("{}: the PLY header promises {} elements, but only {} bytes follow it (the file is "
                        "cut short or corrupt)",
                        path, total, bytes.size() - pos));
    h.body_offset = pos;
    if (h.binary) check_binary_body(path, bytes.substr(pos), elements, big_endian);
    else if (check_ascii_body(path, bytes.substr(pos), elements, body_line, nullptr)) {
        h.ascii_body.reserve(bytes.size() - pos + 1);  // at most the body and a final newline
        check_ascii_body(path, bytes.substr(pos), elements, body_line, &h.ascii_body);
    }
    return h;
}

}  // namespace facet
