// glm::vec3 to and from the float[3] of the kernels' shared structs.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

inline void store(float out[3], glm::vec3 v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

inline glm::vec3 load(const float v[3]) { return glm::vec3(v[0], v[1], v[2]); }

}  // namespace facet
