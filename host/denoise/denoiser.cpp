#include "host/denoise/denoiser.hpp"

#include <chrono>
#include <limits>
#include <span>

#include <fmt/format.h>

#include "host/cl/upload.hpp"
#include "host/error.hpp"

namespace facet {
namespace {

void check_size(const std::vector<float>& v, std::size_t want, const char* what) {
    if (v.size() != want)
        throw Error(fmt::format("denoise: the {} holds {} values, the image needs {}", what, v.size(), want));
}

}  // namespace

FcDenoiseParams denoise_params(std::uint32_t width, std::uint32_t height, const DenoiseVariance& variance,
                               const DenoiseSettings& settings) {
    FcDenoiseParams p{};
    p.width = width, p.height = height;
    p.radius = settings.radius, p.patch_radius = settings.patch_radius;
    p.variance_radius = settings.variance_radius, p.guides = settings.guides;
    p.k_color = settings.k_color, p.sigma_albedo = settings.sigma_albedo;
    p.sigma_normal = settings.sigma_normal, p.sigma_depth = settings.sigma_depth;
    p.variance_scale_a = variance.scale[0], p.variance_scale_b = variance.scale[1];
    p.width8 = (width + 7) / 8 * 8;
    p.pad = settings.radius + settings.patch_radius + 8;
    p.pitch = p.width8 + 2 * p.pad;
    const std::uint64_t plane = std::uint64_t(p.pitch) * (std::uint64_t(height) + 2 * p.pad);
    if (plane > std::numeric_limits<std::uint32_t>::max() / 32)
        throw Error(fmt::format("denoise: {}x{} pixels with a window radius of {} is too large", width, height,
                                settings.radius));
    p.plane = std::uint32_t(plane);
    return p;
}

Denoiser::Denoiser(const ClContext& ctx) : ctx_(ctx) {
    const ProgramBuild build = build_program(ctx_, "kernels/denoise/denoise.cl");
    program_ = build.program;
    build_seconds_ = build.seconds;
}

DenoisedImage denoise(ClContext& ctx, std::uint32_t width, std::uint32_t height, const FilmHalves& halves,
                      const AovImages& features, const DenoiseSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    DenoisedImage out = Denoiser(ctx).run(width, height, halves, features, settings);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

DenoisedImage Denoiser::run(std::uint32_t width, std::uint32_t height, const FilmHalves& halves,
                            const AovImages& features, const DenoiseSettings& settings) const {
    const auto start = std::chrono::steady_clock::now();
    ClContext& ctx = ctx_;
    const std::size_t pixels = std::size_t(width) * height;
    if (pixels == 0) throw Error("denoise: the image is empty");
    if (halves.samples[0] == 0 || halves.samples[1] == 0)
        throw Error("denoise: needs at least 2 samples per pixel (one in each half-image)");
    check_size(halves.rgb[0], 3 * pixels, "first half-image");
    check_size(halves.rgb[1], 3 * pixels, "second half-image");
    check_size(features.albedo, 3 * pixels, "albedo");
    check_size(features.normal, 3 * pixels, "normal");
    check_size(features.depth, pixels, "depth");

    const DenoiseVariance variance = denoise_variance(width, height, halves);
    const FcDenoiseParams p = denoise_params(width, height, variance, settings);
    const int r = int(settings.radius);
    const bool color = (settings.guides & FC_DENOISE_GUIDE_COLOR) != 0;
    const std::size_t plane = p.plane, sums_plane = std::size_t(p.width8) * height;
    const std::size_t term_groups = std::size_t(p.width8 + 2 * p.patch_radius + 7) / 8;
    // Work items: padded pixels (prepare), runs of 8 pixels (terms, accumulate), pixels
    // (finish) and pixels of both halves (variance rows)
    auto items = [](std::size_t n) { return cl::NDRange((n + 63) / 64 * 64); };
    const cl::NDRange prepare_items = items(plane), pixel_items = items(pixels), half_items = items(2 * pixels);
    const cl::NDRange term_items = items(term_groups * (height + 2 * p.patch_radius));
    const cl::NDRange accumulate_items = items(std::size_t(p.width8 / 8) * height);

    DenoisedImage out;
    out.own_variance = variance.own;
    cl_call("denoising", [&] {
        const cl::Context& c = ctx.context();
        cl::CommandQueue& queue = ctx.queue();
        auto in = [&](const std::vector<float>& v) { return upload(c, std::span<const float>(v)); };
        auto scratch = [&](std::size_t floats) { return cl::Buffer(c, CL_MEM_READ_WRITE, floats * sizeof(float)); };
        cl::Buffer a = in(halves.rgb[0]), b = in(halves.rgb[1]);
        cl::Buffer albedo = in(features.albedo), normal = in(features.normal), depth = in(features.depth);
        cl::Buffer params(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof p, const_cast<FcDenoiseParams*>(&p));
        cl::Buffer source = in(variance.source), rows = scratch(2 * pixels), colour = scratch(8 * plane),
                   guides = scratch(7 * plane);
        cl::Buffer sums = scratch(8 * sums_plane);
        cl::Buffer terms = scratch(color ? 2 * plane * std::size_t(2 * r + 1) : 1);
        cl::Buffer out_a = scratch(3 * pixels), out_b = scratch(3 * pixels);
        queue.enqueueFillBuffer(sums, 0.0f, 0, 8 * sums_plane * sizeof(float));

        cl::Kernel variance_rows(program_, "denoise_variance_rows"), prepare(program_, "denoise_prepare");
        cl::Kernel term(program_, "denoise_terms"), accumulate(program_, "denoise_accumulate");
        cl::Kernel finish(program_, "denoise_finish");
        variance_rows.setArg(0, params), variance_rows.setArg(1, source), variance_rows.setArg(2, rows);
        queue.enqueueNDRangeKernel(variance_rows, cl::NullRange, half_items);
        prepare.setArg(0, params), prepare.setArg(1, a), prepare.setArg(2, b), prepare.setArg(3, rows);
        prepare.setArg(4, albedo), prepare.setArg(5, normal), prepare.setArg(6, depth), prepare.setArg(7, colour);
        prepare.setArg(8, guides);
        queue.enqueueNDRangeKernel(prepare, cl::NullRange, prepare_items);
        term.setArg(0, params), term.setArg(1, colour), term.setArg(2, terms);
        accumulate.setArg(0, params), accumulate.setArg(1, colour), accumulate.setArg(2, guides);
        accumulate.setArg(3, terms), accumulate.setArg(4, sums);
        for (cl_int dy = -r; dy <= r; ++dy) {
            if (color) {
                term.setArg(3, dy);
                queue.enqueueNDRangeKernel(term, cl::NullRange, term_items);
            }
            accumulate.setArg(5, dy);
            queue.enqueueNDRangeKernel(accumulate, cl::NullRange, accumulate_items);
        }
        finish.setArg(0, params), finish.setArg(1, colour), finish.setArg(2, sums);
        finish.setArg(3, out_a), finish.setArg(4, out_b);
        queue.enqueueNDRangeKernel(finish, cl::NullRange, pixel_items);
        out.half[0].resize(3 * pixels), out.half[1].resize(3 * pixels);
        queue.enqueueReadBuffer(out_a, CL_TRUE, 0, 3 * pixels * sizeof(float), out.half[0].data());
        queue.enqueueReadBuffer(out_b, CL_TRUE, 0, 3 * pixels * sizeof(float), out.half[1].data());
    });
    out.rgb.resize(3 * pixels);
    for (std::size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] = 0.5f * (out.half[0][i] + out.half[1][i]);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace facet
