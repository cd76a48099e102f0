// How the readers obtain shading normals, and the line `facet info` prints about it
// (Scene::normal_sources). docs/scene-format.md, "Normals", gives the rules per format.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace facet {

// A mesh's normal rule: "file" (the default) follows the file (its normals; OBJ's
// smoothing groups; PLY smooth, glTF flat where it has none), "smooth" gives every
// corner without a file normal the area-weighted vertex normal, "flat" gives every
// triangle its face normal, whatever the file says.
enum class NormalRule { File, Smooth, Flat };
std::optional<NormalRule> normal_rule_from_name(std::string_view name);

// How many triangle corners got a normal of each kind.
struct NormalCounts {
    std::size_t file = 0;      // the file's own normal
    std::size_t smoothed = 0;  // an area-weighted vertex normal (smoothing group, PLY, "smooth")
    std::size_t flat = 0;      // the face normal
};

// "cube.obj: normals: 24 corners from the file, 12 flat (no normal in the file, smoothing
// off)": `smoothed_why` and `flat_why` say why (the rule, or the format's own reason).
std::string describe_normals(const std::string& path, const NormalCounts& counts, std::string_view smoothed_why,
                             std::string_view flat_why);
// The reason a rule forced: "\"normals\": \"smooth\"" or "\"normals\": \"flat\"".
std::string_view forced_reason(NormalRule rule);

}  // namespace facet
