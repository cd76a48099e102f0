// Typed, checked access to a parsed JSON scene: every failure throws facet::Error
// "scene.json: <json path>: what is wrong", e.g. "scene.json: camera.fov: must be in
// (0, 180), got 200" or "scene.json: unknown key 'materails' at top level (did you
// mean 'materials'?)".
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>
#include <string_view>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace facet {

using Json = nlohmann::json;

// Parses `text`; a syntax error becomes "file:LINE:COLUMN: JSON syntax error: ...".
Json parse_json(const std::string& file, const std::string& text);

// Keys given twice in one object (the parser keeps the last silently), as warnings
// "file: key 'K' is given twice in one object; the last value is used".
std::vector<std::string> duplicate_json_keys(const std::string& file, const std::string& text);

class JsonReader {
public:
    explicit JsonReader(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const std::string& path, const std::string& what) const;

    static std::string key(const std::string& path, std::string_view k);
    static std::string index(const std::string& path, std::size_t i);

    // `v` must be an object holding only keys from `known`.
    void object(const Json& v, const std::string& path, std::initializer_list<std::string_view> known) const;
    void require(const Json& obj, const std::string& path, std::string_view k) const;

    double number(const Json& v, const std::string& path) const;  // finite
    // A number in the range; `open_lo`/`open_hi` exclude the ends.
    float number_in(const Json& v, const std::string& path, double lo, double hi, bool open_lo = false,
                    bool open_hi = false) const;
    std::int64_t integer(const Json& v, const std::string& path, std::int64_t lo, std::int64_t hi) const;
    bool boolean(const Json& v, const std::string& path) const;
    std::string string(const Json& v, const std::string& path) const;
    glm::vec3 vec3(const Json& v, const std::string& path) const;
    glm::vec3 color(const Json& v, const std::string& path) const;  // components >= 0

private:
    std::string file_;
};

}  // namespace facet
