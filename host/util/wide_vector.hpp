// Lengths, unit vectors and triangle areas that stay right over the whole coordinate
// range (docs/scene-format.md: +-1e18). A cross product of float edges above ~4e9 has a
// squared length beyond the float range (and one of edges below ~1e-10 one below it),
// so these are computed in double and rounded to float once at the end.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace facet {

inline glm::dvec3 wide_cross(glm::vec3 a, glm::vec3 b) { return glm::cross(glm::dvec3(a), glm::dvec3(b)); }

inline double wide_length(glm::vec3 v) { return glm::length(glm::dvec3(v)); }

// The unit vector along v, or `fallback` when v is zero or not finite.
inline glm::vec3 unit_or(glm::dvec3 v, glm::vec3 fallback) {
    const double len = glm::length(v);
    if (!(len > 0.0) || !std::isfinite(len)) return fallback;
    return glm::vec3(v / len);
}

// The triangle's unit normal along cross(p1 - p0, p2 - p0), or +z when it has no area.
inline glm::vec3 triangle_normal(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
    return unit_or(wide_cross(p1 - p0, p2 - p0), glm::vec3(0.0f, 0.0f, 1.0f));
}

inline double triangle_area(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
    return 0.5 * glm::length(wide_cross(p1 - p0, p2 - p0));
}

}  // namespace facet
