// glTF accessors, bounds-checked (glTF 2.0 specification, 3.6 "Binary Data Storage").
#include "host/readers/gltf_accessor.hpp"

#include <climits>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet::gltf {
namespace {

struct View {
    const unsigned char* base;  // the accessor's first element
    std::size_t stride;         // bytes from one element to the next
    std::size_t count;
};

std::size_t component_size(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

// The accessor's bytes, after checking that every element lies inside its buffer.
View view(const tinygltf::Model& m, int index, int want_type, std::size_t components, const std::string& file,
          const std::string& place) {
    auto fail = [&](const std::string& what) {
        throw Error(fmt::format("{}: {}: accessor {}: {}", file, place, index, what));
    };
    if (index < 0 || std::size_t(index) >= m.accessors.size())
        throw Error(
            fmt::format("{}: {}: accessor {} does not exist ({} accessors)", file, place, index, m.accessors.size()));
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    if (a.sparse.isSparse) fail("sparse accessors are not supported");
    if (a.type != want_type)
        fail(fmt::format("has type {}, expected {}", a.type,
                         want_type == TINYGLTF_TYPE_SCALAR ? "SCALAR"
                         : want_type == TINYGLTF_TYPE_VEC2 ? "VEC2"
                         : want_type == TINYGLTF_TYPE_VEC3 ? "VEC3"
                                                           : "VEC4"));
    const std::size_t size = component_size(a.componentType);
    if (size == 0) fail(fmt::format("unknown componentType {}", a.componentType));
    if (a.count == 0) fail("count is 0");
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= m.bufferViews.size())
        fail(fmt::format("bufferView {} does not exist (an accessor without one is all zeros: not supported)",
                         a.bufferView));
    const tinygltf::BufferView& bv = m.bufferViews[std::size_t(a.bufferView)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= m.buffers.size())
        fail(fmt::format("bufferViews[{}] names buffer {}, which does not exist", a.bufferView, bv.buffer));
    const std::vector<unsigned char>& data = m.buffers[std::size_t(bv.buffer)].data;
    const std::size_t element = size * components;
    const std::size_t stride = bv.byteStride == 0 ? element : bv.byteStride;
    if (stride < element || stride > 252) fail(fmt::format("byteStride {} is invalid for its elements", stride));
    // In 64-bit arithmetic every term is below 2^62 (counts and offsets come from JSON
    // integers, strides are at most 252), so the sums cannot wrap.
    const unsigned long long last = 1ull * a.byteOffset + 1ull * stride * (a.count - 1) + element;
    if (a.count > (1ull << 40) || a.byteOffset > (1ull << 40) || last > bv.byteLength)
        fail(fmt::format("{} elements from byte {} overrun bufferViews[{}] ({} bytes)", a.count, a.byteOffset,
                         a.bufferView, bv.byteLength));
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        fail(fmt::format("bufferViews[{}] (bytes {} + {}) overruns buffer {} ({} bytes)", a.bufferView, bv.byteOffset,
                         bv.byteLength, bv.buffer, data.size()));
    return {data.data() + bv.byteOffset + a.byteOffset, stride, a.count};
}

template <typename T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);  // glTF is little-endian, as facet's hosts are
    return v;
}

float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? float(p[0]) / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return normalized ? float(load<std::uint16_t>(p)) / 65535.0f : float(load<std::uint16_t>(p));
        default:
            return 0.0f;
    }
}

}  // namespace

std::vector<glm::vec3> read_vec3(const tinygltf::Model& m, int accessor, const std::string& file,
                                 const std::string& place) {
    const View v = view(m, accessor, TINYGLTF_TYPE_VEC3, 3, file, place);
    if (m.accessors[std::size_t(accessor)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw Error(fmt::format("{}: {}: accessor {}: expected FLOAT components", file, place, accessor));
    std::vector<glm::vec3> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.base + i * v.stride;
        out[i] = glm::vec3(load<float>(p), load<float>(p + 4), load<float>(p + 8));
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
            throw Error(fmt::format("{}: {}: accessor {}: element {} is not finite ({}, {}, {})", file, place, accessor,
                                    i, out[i].x, out[i].y, out[i].z));
    }
    return out;
}

std::vector<glm::vec4> read_tangents(const tinygltf::Model& m, int accessor, const std::string& file,
                                     const std::string& place) {
    const View v = view(m, accessor, TINYGLTF_TYPE_VEC4, 4, file, place);
    if (m.accessors[std::size_t(accessor)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw Error(fmt::format("{}: {}: accessor {}: expected FLOAT components", file, place, accessor));
    std::vector<glm::vec4> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.base + i * v.stride;
        out[i] = glm::vec4(load<float>(p), load<float>(p + 4), load<float>(p + 8), load<float>(p + 12));
        const glm::vec4 t = out[i];
        if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || !std::isfinite(t.w))
            throw Error(fmt::format("{}: {}: accessor {}: element {} is not finite", file, place, accessor, i));
    }
    return out;
}

std::vector<glm::vec2> read_vec2(const tinygltf::Model& m, int accessor, const std::string& file,
                                 const std::string& place) {
    const View v = view(m, accessor, TINYGLTF_TYPE_VEC2, 2, file, place);
    const tinygltf::Accessor& a = m.accessors[std::size_t(accessor)];
    const bool ok = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                    (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                      a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
    if (!ok)
        throw Error(
            fmt::format("{}: {}: accessor {}: expected FLOAT or normalised UNSIGNED_BYTE/UNSIGNED_SHORT "
                        "components",
                        file, place, accessor));
    const std::size_t size = component_size(a.componentType);
    std::vector<glm::vec2> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.base + i * v.stride;
        out[i] =
            glm::vec2(component(p, a.componentType, a.normalized), component(p + size, a.componentType, a.normalized));
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
            throw Error(fmt::format("{}: {}: accessor {}: element {} is not finite", file, place, accessor, i));
    }
    return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& m, int accessor, std::size_t vertex_count,
                                        const std::string& file, const std::string& place) {
    const View v = view(m, accessor, TINYGLTF_TYPE_SCALAR, 1, file, place);
    const int type = m.accessors[std::size_t(accessor)].componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw Error(fmt::format("{}: {}: accessor {}: indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT",
                                file, place, accessor));
    std::vector<std::uint32_t> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.base + i * v.stride;
        out[i] = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? p[0]
                 : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<std::uint16_t>(p)
                                                                  : load<std::uint32_t>(p);
        if (out[i] >= vertex_count)
            throw Error(fmt::format("{}: {}: accessor {}: index {} is {}, but the primitive has {} vertices", file,
                                    place, accessor, i, out[i], vertex_count));
    }
    return out;
}

int index_value(const tinygltf::Value& v) {
    if (v.IsInt()) return v.Get<int>() >= 0 ? v.Get<int>() : -1;
    if (!v.IsNumber()) return -1;
    const double d = v.GetNumberAsDouble();
    return d >= 0.0 && d <= double(INT_MAX) && d == std::floor(d) ? int(d) : -1;
}

}  // namespace facet::gltf
