#include "host/readers/json_schema.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

std::string type_name(const Json& v) {
    switch (v.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "an array";
        case Json::value_t::string:
            return "a string";
        case Json::value_t::boolean:
            return "a boolean";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float:
            return "a number";
        default:
            return "an unsupported value";
    }
}

}  // namespace

std::vector<std::string> duplicate_json_keys(const std::string& file, const std::string& text) {
    std::vector<std::set<std::string>> open;  // the keys seen in each enclosing object
    std::vector<std::string> out;
    Json::parser_callback_t check = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) {
            open.emplace_back();
        } else if (event == Json::parse_event_t::object_end) {
            if (!open.empty()) open.pop_back();
        } else if (event == Json::parse_event_t::key && !open.empty() && parsed.is_string()) {
            const std::string key = parsed.get<std::string>();
            if (!open.back().insert(key).second)
                out.push_back(
                    fmt::format("{}: key '{}' is given twice in one object; the last value is used", file, key));
        }
        return true;
    };
    try {
        const Json parsed = Json::parse(text, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
        (void)parsed;
    } catch (const Json::exception&) {
        // syntax errors are parse_json's to report
    }
    return out;
}

Json parse_json(const std::string& file, const std::string& text) {
    try {
        // Scene files may hold // and /* */ comments (not standard JSON, but every
        // practitioner annotates a scene).
        return Json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const Json::parse_error& e) {
        // e.byte is the 1-based offset of the last character read.
        const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < end; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        // nlohmann's message: "[json.exception.parse_error.101] parse error at line L,
        // column C: <description>"; keep the description.
        std::string what = e.what();
        if (const auto at = what.find("column "); at != std::string::npos) {
            if (const auto colon = what.find(": ", at); colon != std::string::npos) {
                what = what.substr(colon + 2);
            }
        }
        throw Error(fmt::format("{}:{}:{}: JSON syntax error: {}", file, line, column, what));
    } catch (const Json::exception& e) {
        // Not a syntax error but a value the parser cannot hold, e.g. out_of_range.406 for
        // a number that overflows a double ("1e400"): no position is known.
        std::string what = e.what();
        if (const auto bracket = what.find("] "); bracket != std::string::npos) what = what.substr(bracket + 2);
        throw Error(fmt::format("{}: JSON error: {}", file, what));
    }
}

void JsonReader::fail(const std::string& path, const std::string& what) const {
    if (path.empty()) throw Error(fmt::format("{}: {}", file_, what));
    throw Error(fmt::format("{}: {}: {}", file_, path, what));
}

std::string JsonReader::key(const std::string& path, std::string_view k) {
    return path.empty() ? std::string(k) : fmt::format("{}.{}", path, k);
}

std::string JsonReader::index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

void JsonReader::object(const Json& v, const std::string& path, std::initializer_list<std::string_view> known) const {
    if (!v.is_object()) fail(path, fmt::format("expected an object, got {}", type_name(v)));
    for (const auto& item : v.items()) {
        const std::string& k = item.key();
        if (std::find(known.begin(), known.end(), k) != known.end()) continue;
        std::string_view best;
        std::size_t best_distance = 3;  // suggest only close matches
        for (std::string_view candidate : known) {
            const std::size_t d = edit_distance(k, candidate);
            if (d < best_distance) {
                best_distance = d;
                best = candidate;
            }
        }
        const std::string where = path.empty() ? "at top level" : fmt::format("in '{}'", path);
        const std::string hint = best.empty() ? "" : fmt::format(" (did you mean '{}'?)", best);
        throw Error(fmt::format("{}: unknown key '{}' {}{}", file_, k, where, hint));
    }
}

void JsonReader::require(const Json& obj, const std::string& path, std::string_view k) const {
    if (!obj.contains(k)) fail(path, fmt::format("missing required key '{}'", k));
}

double JsonReader::number(const Json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, fmt::format("expected a number, got {}", type_name(v)));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "must be finite");
    // Every number ends up in a float: beyond its range the conversion is undefined.
    if (std::fabs(d) > double(std::numeric_limits<float>::max()))
        fail(path, fmt::format("{} is beyond the range of a 32-bit float (+-3.4e38)", d));
    return d;
}

float JsonReader::number_in(const Json& v, const std::string& path, double lo, double hi, bool open_lo,
                            bool open_hi) const {
    const double d = number(v, path);
    const bool below = open_lo ? d <= lo : d < lo;
    const bool above = open_hi ? d >= hi : d > hi;
    if (below || above) {
        fail(path, fmt::format("must be in {}{}, {}{}, got {}", open_lo ? '(' : '[', lo, hi, open_hi ? ')' : ']', d));
    }
    return static_cast<float>(d);
}

std::int64_t JsonReader::integer(const Json& v, const std::string& path, std::int64_t lo, std::int64_t hi) const {
    if (!v.is_number()) fail(path, fmt::format("expected an integer, got {}", type_name(v)));
    const double d = number(v, path);
    if (d != std::floor(d)) fail(path, fmt::format("expected an integer, got {}", d));
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) {
        fail(path, fmt::format("must be in [{}, {}], got {}", lo, hi, d));
    }
    return static_cast<std::int64_t>(d);
}

bool JsonReader::boolean(const Json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, fmt::format("expected true or false, got {}", type_name(v)));
    return v.get<bool>();
}

std::string JsonReader::string(const Json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, fmt::format("expected a string, got {}", type_name(v)));
    return v.get<std::string>();
}

glm::vec3 JsonReader::vec3(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) {
        fail(path, fmt::format("expected an array of 3 numbers, got {}{}", type_name(v),
                               v.is_array() ? fmt::format(" of {}", v.size()) : ""));
    }
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        out[i] = static_cast<float>(number(v[static_cast<std::size_t>(i)], index(path, static_cast<std::size_t>(i))));
    }
    return out;
}

glm::vec3 JsonReader::color(const Json& v, const std::string& path) const {
    const glm::vec3 c = vec3(v, path);
    for (int i = 0; i < 3; ++i) {
        if (c[i] < 0.0f) fail(path, fmt::format("colour components must not be negative, got {}", c[i]));
    }
    return c;
}

}  // namespace facet
