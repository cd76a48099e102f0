// Scene files of other renderers (pbrt, Mitsuba, Tungsten) recognised by their look, so
// that facet refuses them with "not a facet scene: this looks like a pbrt-v4 file" rather
// than with a syntax or unknown-key error that sends the user looking for a typo.
#pragma once

#include <string>
#include <string_view>

#include "host/readers/json_schema.hpp"

namespace facet {

// What a file of extension `ext` (lower case, with its dot) starting with `head` looks
// like: "a pbrt-v4 file", "a pbrt-v3 file", "a Mitsuba 3 scene", "a Mitsuba 0.6 scene",
// or "" when it looks like none of them.
std::string foreign_scene_kind(std::string_view ext, std::string_view head);

// What a parsed JSON scene looks like: "a Tungsten scene" (its top level holds
// "primitives" with "bsdfs", "integrator", "renderer" or "camera"), or "".
std::string foreign_json_kind(const Json& root);

// Throws facet::Error "<path>: not a facet scene: this looks like <kind> (...)".
[[noreturn]] void refuse_foreign_scene(const std::string& path, const std::string& kind);

}  // namespace facet
