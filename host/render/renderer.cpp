#include "host/render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "host/cl/upload.hpp"
#include "host/error.hpp"
#include "host/render/features.hpp"
#include "host/scene/device_scene.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Fails before any upload when a buffer exceeds the device's largest allocation or all
// of them its global memory, saying what the scene needs and what the device has.
void check_device_memory(const DeviceDesc& dev, std::initializer_list<std::pair<const char*, std::size_t>> buffers) {
    const double mib = 1024.0 * 1024.0;
    std::size_t total = 0;
    for (const auto& [name, bytes] : buffers) {
        total += bytes;
        if (bytes > dev.max_alloc)
            throw Error(
                fmt::format("the scene's {} need {:.1f} MiB in one buffer, but {} allows at most {:.1f} MiB "
                            "per allocation",
                            name, double(bytes) / mib, dev.name, double(dev.max_alloc) / mib));
    }
    if (total > dev.global_mem)
        throw Error(fmt::format("out of device memory: the scene needs {:.1f} MiB, {} has {:.1f} MiB",
                                double(total) / mib, dev.name, double(dev.global_mem) / mib));
}

}  // namespace

Renderer::Renderer(ClContext& ctx, const Scene& scene, const Bvh& bvh, bool generic,
                   const std::vector<std::string>& extra_prelude)
    : ctx_(ctx), width_(scene.settings.width), height_(scene.settings.height) {
    if (width_ < 1 || height_ < 1) throw Error(fmt::format("invalid image size {}x{}", width_, height_));
    const DeviceScene dev = compile(scene, bvh);
    params_ = dev.params;

    check_device_memory(ctx.desc(), {{"BVH nodes", dev.nodes.size_bytes()},
                                     {"triangles", dev.triangles.size_bytes()},
                                     {"shading data", dev.shading.size_bytes()},
                                     {"materials", dev.materials.size() * sizeof(FcMaterial)},
                                     {"lights", dev.lights.size_bytes()},
                                     {"environment map", dev.environment_texels.size_bytes()},
                                     {"environment distribution", dev.environment_distribution.size_bytes()},
                                     {"spheres", dev.spheres.spheres.size() * sizeof(FcSphere)},
                                     {"sphere BVH", dev.spheres.nodes.size() * sizeof(FcBinaryNode)},
                                     {"instances", dev.instancing.instances.size() * sizeof(FcInstance)},
                                     {"instance BVH", dev.instancing.tree.size() * sizeof(FcBinaryNode)},
                                     {"image", 2 * pixel_count() * sizeof(cl_float4)},
                                     {"textures", dev.textures.texels.size() * sizeof(std::uint32_t)},
                                     {"texture uvs", dev.textures.texcoords.size() * sizeof(FcTriTexcoords)}});

    stats_.features = generic ? all_features() : scene_features(scene);
    std::vector<std::string> prelude = generic ? std::vector<std::string>{} : feature_prelude(stats_.features);
    prelude.insert(prelude.end(), extra_prelude.begin(), extra_prelude.end());
    if (bvh.stats.width != 4) prelude.push_back(bvh_prelude(bvh));  // 4-wide: the kernels' default, no line
    build_ = build_program(ctx, "kernels/integrator/path.cl", prelude);
    stats_.compile_seconds = build_.seconds;
    program_ = build_.program;

    auto start = Clock::now();
    cl_call("uploading the scene", [&] {
        const cl::Context& c = ctx.context();
        kernel_ = cl::Kernel(program_, "render_pass");
        std::size_t max_wg = kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(ctx.device());
        local_size_ = std::max<std::size_t>(1, std::min<std::size_t>(64, max_wg));
        params_buf_ = cl::Buffer(c, CL_MEM_READ_ONLY, sizeof(FcRenderParams));
        nodes_ = upload(c, dev.nodes);
        tris_ = upload(c, dev.triangles);
        shading_ = upload(c, dev.shading);
        materials_ = upload(c, std::span<const FcMaterial>(dev.materials));
        lights_ = upload(c, dev.lights);
        light_cdf_ = upload(c, dev.light_cdf);
        env_texels_ = upload(c, dev.environment_texels);
        env_dist_ = upload(c, dev.environment_distribution);
        accum_ = cl::Buffer(c, CL_MEM_READ_WRITE, 2 * pixel_count() * sizeof(cl_float4));
        textures_ = upload(c, std::span<const FcTexture>(dev.textures.table));
        texels_ = upload(c, std::span<const std::uint32_t>(dev.textures.texels));
        material_textures_ = upload(c, std::span<const FcMaterialTextures>(dev.textures.materials));
        texcoords_ = upload(c, std::span<const FcTriTexcoords>(dev.textures.texcoords));
        spheres_ = upload(c, std::span<const FcSphere>(dev.spheres.spheres));
        sphere_nodes_ = upload(c, std::span<const FcBinaryNode>(dev.spheres.nodes));
        instances_ = upload(c, std::span<const FcInstance>(dev.instancing.instances));
        instance_nodes_ = upload(c, std::span<const FcBinaryNode>(dev.instancing.tree));
        // render_pass's arguments, in the order kernels/integrator/path.cl declares them
        cl_uint arg = 0;
        for (const cl::Buffer* b : {&params_buf_, &nodes_, &tris_, &shading_, &materials_, &lights_, &light_cdf_,
                                    &env_texels_, &env_dist_, &accum_, &textures_, &texels_, &material_textures_,
                                    &texcoords_, &spheres_, &sphere_nodes_, &instances_, &instance_nodes_})
            kernel_.setArg(arg++, *b);
    });
    reset();
    stats_.upload_seconds = seconds_since(start);
}

void Renderer::reset() {
    cl_call("clearing the image", [&] {
        ctx_.queue().enqueueFillBuffer(accum_, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}}, 0,
                                       2 * pixel_count() * sizeof(cl_float4));
        ctx_.queue().finish();
    });
    stats_.samples_per_pixel = 0;
    stats_.render_seconds = 0.0;
}

std::vector<float> Renderer::accumulation() const {
    std::vector<float> sums(2 * pixel_count() * 4);
    cl_call("reading the image back",
            [&] { ctx_.queue().enqueueReadBuffer(accum_, CL_TRUE, 0, sums.size() * sizeof(float), sums.data()); });
    return sums;
}

void Renderer::restore(const std::vector<float>& sums, std::uint64_t spp, double render_seconds) {
    if (sums.size() != 2 * pixel_count() * 4)
        throw Error(fmt::format("a film of {} values does not fit a {}x{} image", sums.size(), width_, height_));
    if (spp > 0xffffffffull) throw Error(fmt::format("a film of {} samples per pixel is beyond 2^32", spp));
    cl_call("uploading the film",
            [&] { ctx_.queue().enqueueWriteBuffer(accum_, CL_TRUE, 0, sums.size() * sizeof(float), sums.data()); });
    stats_.samples_per_pixel = spp;
    stats_.render_seconds = render_seconds;
}

void Renderer::launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) {
    launch_samples(stats_.samples_per_pixel, count, row_begin, row_count);
}

void Renderer::launch_samples(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin,
                              std::uint32_t row_count) {
    if (count == 0 || row_begin >= params_.height) return;
    if (first + count > 0x100000000ull)
        throw Error(fmt::format("sample indices {} to {} are beyond 2^32", first, first + count - 1));
    cl_call("rendering a pass", [&] {
        FcRenderParams p = params_;
        p.sample_begin = std::uint32_t(first);
        p.sample_count = count;
        p.row_begin = row_begin;
        p.row_count = std::min(row_count, params_.height - row_begin);
        // Blocking write: `p` lives on the stack.
        ctx_.queue().enqueueWriteBuffer(params_buf_, CL_TRUE, 0, sizeof p, &p);
        // A fixed work-group size and a global size rounded up to it: drivers that
        // specialise kernels per launch geometry (PoCL does) then build them once.
        std::size_t items = std::size_t(p.row_count) * params_.width;
        std::size_t global = (items + local_size_ - 1) / local_size_ * local_size_;
        ctx_.queue().enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(local_size_));
        ctx_.queue().finish();
    });
}

void Renderer::end_pass(std::uint32_t count, double seconds) {
    stats_.samples_per_pixel += count;
    stats_.render_seconds += seconds;
}

void Renderer::render(std::uint32_t count, std::uint32_t max_rows_per_launch) {
    if (count == 0) return;
    auto start = Clock::now();
    std::uint32_t rows =
        max_rows_per_launch ? std::min<std::uint32_t>(max_rows_per_launch, params_.height) : params_.height;
    for (std::uint32_t row = 0; row < params_.height; row += rows) launch(count, row, rows);
    end_pass(count, seconds_since(start));
}

Renderer::Halves Renderer::halves() const {
    const std::size_t n = pixel_count();
    std::vector<float> sums(2 * n * 4);
    cl_call("reading the image back",
            [&] { ctx_.queue().enqueueReadBuffer(accum_, CL_TRUE, 0, sums.size() * sizeof(float), sums.data()); });
    return film_halves(sums, n, SampleRanges{{0, stats_.samples_per_pixel}});
}

std::vector<float> Renderer::image(double* rejected_samples) const {
    const Halves h = halves();
    if (rejected_samples) *rejected_samples = h.rejected;
    return film_mean(h);
}

}  // namespace facet
