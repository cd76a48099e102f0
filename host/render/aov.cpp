#include "host/render/aov.hpp"

#include <algorithm>
#include <chrono>

#include "host/cl/upload.hpp"
#include "host/render/features.hpp"
#include "host/render/scene_buffers.hpp"

namespace facet {
namespace {

// Rows per launch: about 2^18 pixel-samples of primary rays and delta bounces, far below
// any display watchdog.
std::uint32_t rows_per_launch(std::uint32_t width, std::uint32_t spp) {
    const std::uint64_t per_row = std::uint64_t(width) * std::max<std::uint32_t>(spp, 1);
    return std::uint32_t(std::max<std::uint64_t>(1, (std::uint64_t(1) << 18) / per_row));
}

}  // namespace

AovImages render_aovs(ClContext& ctx, const Scene& scene, const Bvh& bvh, std::uint32_t spp) {
    return render_aovs(ctx, scene, bvh, compile(scene, bvh), spp);
}

AovImages render_aovs(ClContext& ctx, const Scene& scene, const Bvh& bvh, const DeviceScene& dev, std::uint32_t spp) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint32_t width = dev.params.width, height = dev.params.height;
    const std::size_t pixels = std::size_t(width) * height;
    std::vector<cl_float4> sums(2 * pixels);
    check_device_memory(ctx.desc(), scene_buffer_needs(dev, sums.size() * sizeof(cl_float4)));
    const ProgramBuild build = build_program(ctx, "kernels/aov/aov.cl", scene_program_prelude(scene, bvh));
    cl_call("rendering the AOVs", [&] {
        const cl::Context& c = ctx.context();
        cl::Kernel kernel(build.program, "aov_pass");
        const std::size_t local = std::max<std::size_t>(
            1, std::min<std::size_t>(64, kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(ctx.device())));
        const SceneBuffers buffers = upload_scene(c, dev);
        cl::Buffer accum(c, CL_MEM_READ_WRITE, sums.size() * sizeof(cl_float4));
        ctx.queue().enqueueFillBuffer(accum, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}}, 0, sums.size() * sizeof(cl_float4));
        // aov_pass(FC_SCENE_KERNEL_PARAMS, accum)
        kernel.setArg(bind_scene(kernel, buffers), accum);
        const std::uint32_t rows = rows_per_launch(width, spp);
        for (std::uint32_t row = 0; row < height; row += rows) {
            FcRenderParams p = dev.params;
            p.seed = aov_seed(dev.params.seed);
            p.sample_begin = 0;
            p.sample_count = spp;
            p.row_begin = row;
            p.row_count = std::min(rows, height - row);
            ctx.queue().enqueueWriteBuffer(buffers.params, CL_TRUE, 0, sizeof p, &p);
            const std::size_t items = std::size_t(p.row_count) * width;
            ctx.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange((items + local - 1) / local * local),
                                             cl::NDRange(local));
            ctx.queue().finish();
        }
        ctx.queue().enqueueReadBuffer(accum, CL_TRUE, 0, sums.size() * sizeof(cl_float4), sums.data());
    });
    AovImages out;
    out.albedo.resize(3 * pixels);
    out.normal.resize(3 * pixels);
    out.depth.resize(pixels);
    const float inv = spp > 0 ? 1.0f / float(spp) : 0.0f;
    for (std::size_t i = 0; i < pixels; ++i) {
        const cl_float4& a = sums[i];
        const cl_float4& n = sums[pixels + i];
        for (int c = 0; c < 3; ++c) {
            out.albedo[3 * i + std::size_t(c)] = a.s[c] * inv;
            out.normal[3 * i + std::size_t(c)] = n.s[c] * inv;
        }
        out.depth[i] = a.s[3] > 0.0f ? n.s[3] / a.s[3] : 0.0f;
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace facet
