// glTF primitives compressed with KHR_draco_mesh_compression, decoded through Google's
// Draco library (Debian's libdraco-dev): the extension names a bufferView holding the
// Draco bitstream and, per glTF attribute, the Draco attribute's unique id; the decoded
// points are the primitive's vertices in order and its faces the triangles. Private to the
// glTF reader (host/readers/gltf_reader.cpp).
#pragma once

#include <optional>
#include <string>

#include <tiny_gltf.h>

#include "host/readers/triangle_mesh.hpp"

namespace facet::gltf {

inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// A glTF file's bytes (`binary`: a GLB container) with the `indices` member of every Draco
// primitive removed, or nullopt when it has none (or is not valid JSON: tinygltf will say
// so). Debian's tinygltf is built without Draco and refuses an indices accessor without a
// bufferView, which every Draco primitive has; its triangles come from the decoded faces.
std::optional<std::string> without_draco_indices(const std::string& bytes, bool binary);

// Whether `prim` carries the Draco extension.
bool is_draco(const tinygltf::Primitive& prim);

// The primitive's POSITION, NORMAL, TEXCOORD_0 and TANGENT (those the extension names) and
// its triangles. Throws facet::Error "<file>: <place>.extensions.KHR_draco_mesh_compression:
// <problem>" for a bufferView outside its buffer, a bitstream Draco cannot decode, a missing
// POSITION, a non-finite value or more vertices than the accessors declare.
IndexedMesh decode_draco(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& file,
                         const std::string& place);

}  // namespace facet::gltf
