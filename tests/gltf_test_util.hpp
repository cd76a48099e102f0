// glTF models the tests build in memory (tinygltf writes them out): one buffer that each
// accessor's data is appended to, 4-byte aligned, behind its own buffer view.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace facet::test {

struct GltfBuilder {
    tinygltf::Model m;

    GltfBuilder() {
        m.buffers.emplace_back();
        m.asset.version = "2.0";
        m.scenes.emplace_back();
        m.defaultScene = 0;
    }

    int accessor(const void* data, std::size_t bytes, int component, int type, std::size_t count) {
        auto& buf = m.buffers[0].data;
        while (buf.size() % 4) buf.push_back(0);
        tinygltf::BufferView bv;
        bv.buffer = 0;
        bv.byteOffset = buf.size();
        bv.byteLength = bytes;
        buf.insert(buf.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + bytes);
        m.bufferViews.push_back(bv);
        tinygltf::Accessor a;
        a.bufferView = int(m.bufferViews.size() - 1);
        a.componentType = component;
        a.type = type;
        a.count = count;
        m.accessors.push_back(a);
        return int(m.accessors.size() - 1);
    }
};

// A one-triangle glTF whose material "glass" of metallicFactor `metallic` has `material_json`
// (members after those two, e.g. "extensions").
inline std::string one_triangle_gltf(const std::string& material_json, double metallic = 0.0) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
 "materials": [{"name": "glass", "pbrMetallicRoughness": {"metallicFactor": )" +
           std::to_string(metallic) + "}, " + material_json + R"(}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
}

}  // namespace facet::test
