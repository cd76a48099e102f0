// Uploading host arrays to an OpenCL device.
#pragma once

#include <span>

#include <CL/opencl.hpp>

namespace facet {

// A read-only buffer holding `v` (OpenCL forbids empty buffers: an empty span gives one
// zero element).
template <typename T>
cl::Buffer upload(const cl::Context& ctx, std::span<const T> v) {
    const T zero{};
    const std::span<const T> data = v.empty() ? std::span<const T>(&zero, 1) : v;
    return cl::Buffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size_bytes(), const_cast<T*>(data.data()));
}

}  // namespace facet
