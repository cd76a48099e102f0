// The compiled device scene (host/scene/device_scene.hpp) on one OpenCL device: the memory
// it needs, checked before any upload, one buffer per array of kernels/shared/scene_arrays.h,
// and the one bind loop of every kernel that takes FC_SCENE_KERNEL_PARAMS
// (kernels/scene/scene_view.cl): render_pass and aov_pass.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host/cl/runtime.hpp"
#include "host/scene/device_scene.hpp"

namespace facet {

// One buffer a render needs on the device: what it holds, for messages, and its size.
struct BufferNeed {
    std::string what;
    std::size_t bytes = 0;
};

// Every array of the device scene (list order), then the accumulation buffer of
// `accum_bytes` ("image"), as the memory check counts them.
std::vector<BufferNeed> scene_buffer_needs(const DeviceScene& scene, std::size_t accum_bytes);

// Throws facet::Error before any upload when a buffer exceeds the device's largest
// allocation, or all of them its global memory, saying what the scene needs and what the
// device has.
void check_device_memory(const DeviceDesc& dev, const std::vector<BufferNeed>& needs);

// The scene on one device: the parameter block (written before each launch) and one
// read-only buffer per array, in list order.
struct SceneBuffers {
    cl::Buffer params;
    std::vector<cl::Buffer> arrays;
};

// Uploads every array (a one-element placeholder when empty: OpenCL has no empty buffers).
SceneBuffers upload_scene(const cl::Context& ctx, const DeviceScene& scene);

// Binds the parameter block and the arrays as the kernel's first arguments; returns the
// index of the next argument.
cl_uint bind_scene(cl::Kernel& kernel, const SceneBuffers& buffers);

}  // namespace facet
