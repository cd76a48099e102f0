#include "host/readers/obj_validate.hpp"

#include <cmath>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/text_parse.hpp"

namespace facet {
namespace {

struct LineCtx {
    const std::string& path;
    int line;

    [[noreturn]] void fail(const std::string& what) const { throw Error(fmt::format("{}:{}: {}", path, line, what)); }
};

// `v`, `vn`, `vt`: between min and max numeric fields after the keyword.
void check_numbers(const LineCtx& ctx, const std::vector<std::string_view>& f, std::size_t min, std::size_t max,
                   bool finite_xyz) {
    const std::string_view kw = f[0];
    const std::size_t n = f.size() - 1;
    if (n < min) {
        ctx.fail(fmt::format("'{}' needs {} numbers, found {}", kw, min, n));
    }
    if (n > max) ctx.fail(fmt::format("'{}' takes at most {} numbers, found {}", kw, max, n));
    for (std::size_t i = 1; i < f.size(); ++i) {
        float value = 0.0f;
        if (!text::parse_float(f[i], value)) {
            ctx.fail(fmt::format("'{}': field {} ('{}') is {}", kw, i, f[i], text::number_problem(f[i])));
        }
        if (finite_xyz && i <= 3 && !std::isfinite(value)) {
            ctx.fail(fmt::format("'{}': coordinate {} is {} (positions must be finite)", kw, i, f[i]));
        }
    }
}

// One index of a face corner: 1-based, or negative (relative to the end so far).
void check_index(const LineCtx& ctx, std::string_view field, std::string_view part, const char* what,
                 std::size_t count) {
    long idx = 0;
    if (!text::parse_int(part, idx)) {
        ctx.fail(fmt::format("face vertex '{}': {} index '{}' is not an integer", field, what, part));
    }
    if (idx == 0) ctx.fail(fmt::format("face vertex '{}': {} index 0 (OBJ indices start at 1)", field, what));
    const long n = static_cast<long>(count);
    const long resolved = idx > 0 ? idx : n + idx + 1;
    if (resolved < 1 || resolved > n) {
        ctx.fail(
            fmt::format("face vertex '{}': {} index {} is out of range ({} defined so far)", field, what, idx, count));
    }
}

void check_face(const LineCtx& ctx, const std::vector<std::string_view>& f, const ObjScan& s) {
    if (f.size() < 4) {
        ctx.fail(fmt::format("face has {} vertices, needs at least 3", f.size() - 1));
    }
    for (std::size_t i = 1; i < f.size(); ++i) {
        std::string_view field = f[i];
        std::string_view parts[3];
        std::size_t count = 0, start = 0;
        for (std::size_t j = 0; j <= field.size(); ++j) {
            if (j < field.size() && field[j] != '/') continue;
            if (count == 3) ctx.fail(fmt::format("face vertex '{}' has more than 3 indices", field));
            parts[count++] = field.substr(start, j - start);
            start = j + 1;
        }
        check_index(ctx, field, parts[0], "position", s.positions);
        if (count >= 2 && !parts[1].empty()) check_index(ctx, field, parts[1], "texcoord", s.texcoords);
        if (count == 3) {
            if (parts[2].empty()) ctx.fail(fmt::format("face vertex '{}': empty normal index", field));
            check_index(ctx, field, parts[2], "normal", s.normals);
        }
    }
}

}  // namespace

ObjScan validate_obj(const std::string& path, std::string_view content) {
    ObjScan scan;
    const auto lines = text::split_lines(content);
    for (std::size_t li = 0; li < lines.size(); ++li) {
        const LineCtx ctx{path, static_cast<int>(li + 1)};
        const auto f = text::split_fields(lines[li]);
        if (f.empty()) continue;
        const std::string_view kw = f[0];
        if (kw == "v") {
            check_numbers(ctx, f, 3, 7, true);
            ++scan.positions;
        } else if (kw == "vn") {
            check_numbers(ctx, f, 3, 3, false);
            ++scan.normals;
        } else if (kw == "vt") {
            check_numbers(ctx, f, 1, 3, false);
            ++scan.texcoords;
        } else if (kw == "f") {
            check_face(ctx, f, scan);
            ++scan.faces;
        } else if (kw == "s") {
            long group = 0;
            if (f.size() != 2 || (f[1] != "off" && (!text::parse_int(f[1], group) || group < 0 || group > 0xffffffffL)))
                ctx.fail("'s' expects 'off' or a smoothing group number >= 0");
        } else if (kw == "mtllib") {
            if (f.size() < 2) ctx.fail("'mtllib' without a file name");
            for (std::size_t i = 1; i < f.size(); ++i) {
                scan.mtllibs.push_back({ctx.line, std::string(f[i])});
            }
        } else if (kw == "usemtl") {
            if (f.size() >= 2) {
                scan.usemtls.push_back({ctx.line, std::string(text::rest_after_keyword(lines[li]))});
            }
        }
        // Anything else (o, g, l, p, vp, cstype, ...) is left to tinyobjloader or ignored.
    }
    if (scan.faces == 0) {
        throw Error(fmt::format("{}: no faces (an OBJ scene needs at least one 'f' statement)", path));
    }
    return scan;
}

}  // namespace facet
