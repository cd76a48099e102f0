// The normal rules' names and the `facet info` line.
#include "host/readers/mesh_normals.hpp"

#include <vector>

#include <fmt/format.h>

namespace facet {

std::optional<NormalRule> normal_rule_from_name(std::string_view name) {
    if (name == "file") return NormalRule::File;
    if (name == "smooth") return NormalRule::Smooth;
    if (name == "flat") return NormalRule::Flat;
    return std::nullopt;
}

std::string_view forced_reason(NormalRule rule) {
    return rule == NormalRule::Smooth ? "\"normals\": \"smooth\"" : "\"normals\": \"flat\"";
}

std::string describe_normals(const std::string& path, const NormalCounts& counts, std::string_view smoothed_why,
                             std::string_view flat_why) {
    std::vector<std::string> parts;
    if (counts.file > 0) parts.push_back(fmt::format("{} corners from the file", counts.file));
    if (counts.smoothed > 0) parts.push_back(fmt::format("{} smoothed ({})", counts.smoothed, smoothed_why));
    if (counts.flat > 0) parts.push_back(fmt::format("{} flat ({})", counts.flat, flat_why));
    return fmt::format("{}: normals: {}", path, fmt::join(parts, ", "));
}

}  // namespace facet
