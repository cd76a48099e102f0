#include "host/render/renderer.hpp"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "host/cl/upload.hpp"
#include "host/error.hpp"
#include "host/film/film_layout.hpp"
#include "host/render/features.hpp"
#include "host/render/packet_paths.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

Renderer::Renderer(ClContext& ctx, const Scene& scene, const Bvh& bvh, bool generic,
                   const std::vector<std::string>& extra_prelude)
    : Renderer(ctx, scene, bvh, compile(scene, bvh), generic, extra_prelude) {}

Renderer::Renderer(ClContext& ctx, const Scene& scene, const Bvh& bvh, const DeviceScene& dev, bool generic,
                   const std::vector<std::string>& extra_prelude)
    : ctx_(ctx), width_(int(dev.params.width)), height_(int(dev.params.height)) {
    if (width_ < 1 || height_ < 1) throw Error(fmt::format("invalid image size {}x{}", width_, height_));
    params_ = dev.params;
    const std::size_t accum_bytes = film_floats(pixel_count()) * sizeof(float);
    check_device_memory(ctx.desc(), scene_buffer_needs(dev, accum_bytes));

    stats_.features = generic ? all_features() : scene_features(scene);
    std::vector<std::string> prelude = scene_program_prelude(scene, bvh, generic);
    const unsigned native_width = ctx.device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>();
    stats_.packet_paths = packet_paths_for(ctx.desc(), native_width, stats_.features, lights_in_packets(scene),
                                           dev.params.sampler, generic);
    if (stats_.packet_paths) {
        stats_.packet_width = packet_width_for(native_width);
        prelude.push_back("#define FC_PACKET_PATHS 1");
        prelude.push_back(fmt::format("#define FC_PACKET_WIDTH {}", stats_.packet_width));
        if (!lambertian_materials(scene)) prelude.push_back("#define FC_PACKET_BSDF_PER_LANE 1");
        if (!packet_trace_for(bvh.stats.triangles)) prelude.push_back("#define FC_PACKET_TRACE 0");
        else
            prelude.push_back(fmt::format("#define FC_PACKET_TRACE_MIN {}", packet_trace_min_for(bvh.stats.triangles)));
    }
    prelude.insert(prelude.end(), extra_prelude.begin(), extra_prelude.end());
    build_ = build_program(ctx, kRenderProgram, prelude);
    stats_.compile_seconds = build_.seconds;
    program_ = build_.program;

    auto start = Clock::now();
    cl_call("uploading the scene", [&] {
        kernel_ = cl::Kernel(program_, stats_.packet_paths ? "packet_pass" : "render_pass");
        std::size_t max_wg = kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(ctx.device());
        // 64 pixels a work-group in either form (a packet work-item renders packet_width of
        // them): larger groups of packets leave a CPU thread idle at the end of each launch.
        const std::size_t group = stats_.packet_paths ? 64 / stats_.packet_width : 64;
        local_size_ = std::max<std::size_t>(1, std::min<std::size_t>(group, max_wg));
        scene_ = upload_scene(ctx.context(), dev);
        accum_ = cl::Buffer(ctx.context(), CL_MEM_READ_WRITE, accum_bytes);
        // render_pass(FC_SCENE_KERNEL_PARAMS, accum), or packet_pass likewise
        kernel_.setArg(bind_scene(kernel_, scene_), accum_);
    });
    reset();
    stats_.upload_seconds = seconds_since(start);
}

void Renderer::reset() {
    cl_call("clearing the image", [&] {
        ctx_.queue().enqueueFillBuffer(accum_, 0.0f, 0, film_floats(pixel_count()) * sizeof(float));
        ctx_.queue().finish();
    });
    stats_.samples_per_pixel = 0;
    stats_.render_seconds = 0.0;
}

std::vector<float> Renderer::accumulation() const {
    std::vector<float> sums;
    read_accumulation(sums);
    return sums;
}

void Renderer::read_accumulation(std::vector<float>& into) const {
    into.resize(film_floats(pixel_count()));
    cl_call("reading the image back",
            [&] { ctx_.queue().enqueueReadBuffer(accum_, CL_TRUE, 0, into.size() * sizeof(float), into.data()); });
}

void Renderer::restore(const std::vector<float>& sums, std::uint64_t spp, double render_seconds) {
    if (sums.size() != film_floats(pixel_count()))
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
        ctx_.queue().enqueueWriteBuffer(scene_.params, CL_TRUE, 0, sizeof p, &p);
        // A fixed work-group size and a global size rounded up to it: drivers that
        // specialise kernels per launch geometry (PoCL does) then build them once.
        std::size_t items =
            std::size_t(p.row_count) *
            (stats_.packet_paths ? packet_items_per_row(params_.width, stats_.packet_width, count) : params_.width);
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
    return film_halves(accumulation(), pixel_count(), SampleRanges{{0, stats_.samples_per_pixel}}, true);
}

std::vector<float> Renderer::image(double* rejected_samples) const {
    // The means alone: no second moments
    const Halves h = film_halves(accumulation(), pixel_count(), SampleRanges{{0, stats_.samples_per_pixel}}, false);
    if (rejected_samples) *rejected_samples = h.rejected;
    return film_mean(h);
}

}  // namespace facet
