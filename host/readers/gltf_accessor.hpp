// glTF accessors read into typed arrays with every index, offset, stride and count
// checked against the file's buffers first (a malformed file gives an error naming the
// accessor, never a read outside a buffer). Private to the glTF reader.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <tiny_gltf.h>

namespace facet::gltf {

// Each throws facet::Error "<file>: <place>: accessor N: <problem>", `place` saying
// which attribute asked (e.g. "meshes[0].primitives[1].attributes.POSITION").
// VEC3 FLOAT, every component finite (POSITION, NORMAL).
std::vector<glm::vec3> read_vec3(const tinygltf::Model& m, int accessor, const std::string& file,
                                 const std::string& place);
// VEC4 FLOAT, every component finite (TANGENT: xyz, handedness w = +-1).
std::vector<glm::vec4> read_tangents(const tinygltf::Model& m, int accessor, const std::string& file,
                                     const std::string& place);
// VEC2 FLOAT or normalised UNSIGNED_BYTE / UNSIGNED_SHORT (TEXCOORD_n), finite.
std::vector<glm::vec2> read_vec2(const tinygltf::Model& m, int accessor, const std::string& file,
                                 const std::string& place);
// SCALAR UNSIGNED_BYTE / UNSIGNED_SHORT / UNSIGNED_INT, each < `vertex_count` (indices).
std::vector<std::uint32_t> read_indices(const tinygltf::Model& m, int accessor, std::size_t vertex_count,
                                        const std::string& file, const std::string& place);

// An index held in an extension's JSON value: the value when it is a whole number in
// [0, INT_MAX], else -1. (tinygltf's GetNumberAsInt converts any real number to int,
// which is undefined behaviour beyond int's range, e.g. for 1e300.)
int index_value(const tinygltf::Value& v);

}  // namespace facet::gltf
