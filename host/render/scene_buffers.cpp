#include "host/render/scene_buffers.hpp"

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {

std::vector<BufferNeed> scene_buffer_needs(const DeviceScene& scene, std::size_t accum_bytes) {
    std::vector<BufferNeed> needs;
    for (const DeviceScene::Array& a : scene.arrays()) needs.push_back({a.what, a.bytes.size()});
    needs.push_back({"image", accum_bytes});
    return needs;
}

void check_device_memory(const DeviceDesc& dev, const std::vector<BufferNeed>& needs) {
    const double mib = 1024.0 * 1024.0;
    std::size_t total = 0;
    for (const BufferNeed& b : needs) {
        total += b.bytes;
        if (b.bytes > dev.max_alloc)
            throw Error(
                fmt::format("the scene's {} need {:.1f} MiB in one buffer, but {} allows at most {:.1f} MiB "
                            "per allocation",
                            b.what, double(b.bytes) / mib, dev.name, double(dev.max_alloc) / mib));
    }
    if (total > dev.global_mem)
        throw Error(fmt::format("out of device memory: the scene needs {:.1f} MiB, {} has {:.1f} MiB",
                                double(total) / mib, dev.name, double(dev.global_mem) / mib));
}

SceneBuffers upload_scene(const cl::Context& ctx, const DeviceScene& scene) {
    SceneBuffers b;
    b.params = cl::Buffer(ctx, CL_MEM_READ_ONLY, sizeof(FcRenderParams));
    for (const DeviceScene::Array& a : scene.arrays()) {
        const std::vector<std::byte> zero(a.bytes.empty() ? a.element : 0);  // one element of zeros
        const void* data = a.bytes.empty() ? zero.data() : a.bytes.data();
        const std::size_t size = a.bytes.empty() ? zero.size() : a.bytes.size();
        b.arrays.emplace_back(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, size, const_cast<void*>(data));
    }
    return b;
}

cl_uint bind_scene(cl::Kernel& kernel, const SceneBuffers& buffers) {
    cl_uint arg = 0;
    kernel.setArg(arg++, buffers.params);
    for (const cl::Buffer& b : buffers.arrays) kernel.setArg(arg++, b);
    return arg;
}

}  // namespace facet
