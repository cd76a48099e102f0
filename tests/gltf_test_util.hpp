// glTF models the tests build in memory (tinygltf writes them out): one buffer that each
// accessor's data is appended to, 4-byte aligned, behind its own buffer view.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>

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

}  // namespace facet::test
