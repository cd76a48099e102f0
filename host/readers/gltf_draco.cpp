// Draco-compressed glTF primitives (gltf_draco.hpp).
#include "host/readers/gltf_draco.hpp"

#include <cmath>
#include <cstdint>
#include <memory>

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/mesh/mesh.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "host/error.hpp"
#include "host/readers/gltf_accessor.hpp"

namespace facet::gltf {
namespace {

// The Draco attribute named `id`'s value at every point, N floats each, all finite.
template <int N>
std::vector<float> attribute_values(const draco::Mesh& mesh, int id, const std::string& where) {
    const draco::PointAttribute* att = id >= 0 ? mesh.GetAttributeByUniqueId(std::uint32_t(id)) : nullptr;
    if (att == nullptr) throw Error(fmt::format("{}: no Draco attribute of id {}", where, id));
    if (att->num_components() < N)
        throw Error(fmt::format("{}: Draco attribute {} has {} components, {} wanted", where, id,
                                int(att->num_components()), N));
    std::vector<float> out(std::size_t(mesh.num_points()) * N);
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        float* v = &out[std::size_t(p.value()) * N];
        if (!att->ConvertValue<float, N>(att->mapped_index(p), v))
            throw Error(fmt::format("{}: Draco attribute {} cannot be read as floats", where, id));
        for (int c = 0; c < N; ++c)
            if (!std::isfinite(v[c]))
                throw Error(
                    fmt::format("{}: Draco attribute {} has a non-finite value at point {}", where, id, p.value()));
    }
    return out;
}

// The extension's integer member `key`, or -1.
int member_int(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return -1;
    return index_value(object.Get(key));
}

// Removes `indices` from the Draco primitives of `doc`; whether any was removed.
bool strip_indices(nlohmann::json& doc) {
    bool changed = false;
    if (!doc.is_object() || !doc.contains("meshes") || !doc["meshes"].is_array()) return false;
    for (nlohmann::json& mesh : doc["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (nlohmann::json& prim : mesh["primitives"]) {
            if (!prim.is_object() || !prim.contains("extensions") || !prim["extensions"].is_object()) continue;
            if (!prim["extensions"].contains(kDracoExtension) || !prim.contains("indices")) continue;
            prim.erase("indices");
            changed = true;
        }
    }
    return changed;
}

std::uint32_t le32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = v << 8 | std::uint8_t(b[at + std::size_t(k)]);
    return v;
}

void put_le32(std::string& b, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b.push_back(char(v >> (8 * k) & 0xffu));
}

}  // namespace

std::optional<std::string> without_draco_indices(const std::string& bytes, bool binary) {
    if (bytes.find(kDracoExtension) == std::string::npos) return std::nullopt;
    if (!binary) {
        nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
        if (doc.is_discarded() || !strip_indices(doc)) return std::nullopt;
        return doc.dump();
    }
    // GLB: a 12-byte header (magic, version, length), then chunks of (length, type, data);
    // the first is the JSON (type 0x4E4F534A), padded with spaces to 4 bytes.
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || le32(bytes, 16) != 0x4E4F534Au) return std::nullopt;
    const std::uint32_t json_length = le32(bytes, 12);
    if (json_length > bytes.size() - 20) return std::nullopt;
    nlohmann::json doc = nlohmann::json::parse(bytes.substr(20, json_length), nullptr, false);
    if (doc.is_discarded() || !strip_indices(doc)) return std::nullopt;
    std::string json = doc.dump();
    json.append((4 - json.size() % 4) % 4, ' ');
    const std::string rest = bytes.substr(20 + json_length);
    std::string out = "glTF";
    put_le32(out, 2);
    put_le32(out, std::uint32_t(12 + 8 + json.size() + rest.size()));
    put_le32(out, std::uint32_t(json.size()));
    put_le32(out, 0x4E4F534Au);
    return out + json + rest;
}

bool is_draco(const tinygltf::Primitive& prim) { return prim.extensions.count(kDracoExtension) > 0; }

IndexedMesh decode_draco(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& file,
                         const std::string& place) {
    const std::string where = fmt::format("{}: {}.extensions.{}", file, place, kDracoExtension);
    const tinygltf::Value& ext = prim.extensions.at(kDracoExtension);
    const int view = member_int(ext, "bufferView");
    if (view < 0) throw Error(fmt::format("{}: bufferView must be an index (a whole number >= 0)", where));
    if (std::size_t(view) >= model.bufferViews.size())
        throw Error(
            fmt::format("{}: bufferView {} does not exist ({} bufferViews)", where, view, model.bufferViews.size()));
    const tinygltf::BufferView& bv = model.bufferViews[std::size_t(view)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size())
        throw Error(fmt::format("{}: bufferView {} names buffer {}, which does not exist", where, view, bv.buffer));
    const std::vector<unsigned char>& bytes = model.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteOffset > bytes.size() || bv.byteLength > bytes.size() - bv.byteOffset)
        throw Error(fmt::format("{}: bufferView {} ({} bytes at {}) lies outside its buffer of {} bytes", where, view,
                                bv.byteLength, bv.byteOffset, bytes.size()));
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data() + bv.byteOffset), bv.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        throw Error(fmt::format("{}: Draco cannot decode it: {}", where, decoded.status().error_msg_string()));
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh || mesh->num_points() == 0) throw Error(fmt::format("{}: the Draco mesh has no points", where));

    // The accessors of the uncompressed attributes state the vertex count the file promises.
    const auto position = prim.attributes.find("POSITION");
    if (position != prim.attributes.end() && position->second >= 0 &&
        std::size_t(position->second) < model.accessors.size() &&
        model.accessors[std::size_t(position->second)].count != mesh->num_points())
        throw Error(fmt::format("{}: the Draco mesh has {} points, accessor {} (POSITION) declares {}", where,
                                mesh->num_points(), position->second,
                                model.accessors[std::size_t(position->second)].count));
    const tinygltf::Value& attributes = ext.Get("attributes");
    const int pos_id = member_int(attributes, "POSITION");
    if (pos_id < 0) throw Error(fmt::format("{}: attributes has no POSITION index (a whole number >= 0)", where));
    IndexedMesh m;
    const std::vector<float> p = attribute_values<3>(*mesh, pos_id, where);
    for (std::size_t i = 0; i + 2 < p.size(); i += 3) m.positions.emplace_back(p[i], p[i + 1], p[i + 2]);
    if (const int id = member_int(attributes, "NORMAL"); id >= 0) {
        const std::vector<float> n = attribute_values<3>(*mesh, id, where);
        for (std::size_t i = 0; i + 2 < n.size(); i += 3) m.normals.emplace_back(n[i], n[i + 1], n[i + 2]);
    }
    if (const int id = member_int(attributes, "TEXCOORD_0"); id >= 0) {
        const std::vector<float> t = attribute_values<2>(*mesh, id, where);
        for (std::size_t i = 0; i + 1 < t.size(); i += 2) m.texcoords.emplace_back(t[i], t[i + 1]);
    }
    if (const int id = member_int(attributes, "TANGENT"); id >= 0) {
        const std::vector<float> t = attribute_values<4>(*mesh, id, where);
        for (std::size_t i = 0; i + 3 < t.size(); i += 4) m.tangents.emplace_back(t[i], t[i + 1], t[i + 2], t[i + 3]);
    }
    m.indices.reserve(std::size_t(mesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh->face(f)[k].value();
            if (v >= mesh->num_points())
                throw Error(fmt::format("{}: face {} names point {} of {}", where, f.value(), v, mesh->num_points()));
            m.indices.push_back(v);
        }
    return m;
}

}  // namespace facet::gltf
