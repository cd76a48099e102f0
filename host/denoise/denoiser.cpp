#include "host/denoise/denoiser.hpp"

#include <chrono>
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

// 3 floats a pixel to 4, the fourth from `fourth` (one a pixel) or 0.
std::vector<float> pack4(const std::vector<float>& rgb, const std::vector<float>* fourth) {
    const std::size_t pixels = rgb.size() / 3;
    std::vector<float> v(4 * pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 3; ++c) v[4 * i + c] = rgb[3 * i + c];
        v[4 * i + 3] = fourth ? (*fourth)[i] : 0.0f;
    }
    return v;
}

}  // namespace

DenoisedImage denoise(ClContext& ctx, std::uint32_t width, std::uint32_t height, const FilmHalves& halves,
                      const AovImages& features, const DenoiseSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t pixels = std::size_t(width) * height;
    if (pixels == 0) throw Error("denoise: the image is empty");
    if (halves.samples[0] == 0 || halves.samples[1] == 0)
        throw Error("denoise: needs at least 2 samples per pixel (one in each half-image)");
    check_size(halves.rgb[0], 3 * pixels, "first half-image");
    check_size(halves.rgb[1], 3 * pixels, "second half-image");
    check_size(features.albedo, 3 * pixels, "albedo");
    check_size(features.normal, 3 * pixels, "normal");
    check_size(features.depth, pixels, "depth");

    FcDenoiseParams p{};
    p.width = width, p.height = height;
    p.radius = settings.radius, p.patch_radius = settings.patch_radius;
    p.variance_radius = settings.variance_radius, p.guides = settings.guides;
    p.k_color = settings.k_color, p.sigma_albedo = settings.sigma_albedo;
    p.sigma_normal = settings.sigma_normal, p.sigma_depth = settings.sigma_depth;
    // The variance of half k's pixel means: E[(a - b)^2] n_other / (n_a + n_b)
    const double n = double(halves.samples[0] + halves.samples[1]);
    p.variance_scale_a = float(double(halves.samples[1]) / n);
    p.variance_scale_b = float(double(halves.samples[0]) / n);

    DenoisedImage out;
    const ProgramBuild build = build_program(ctx, "kernels/denoise/denoise.cl");
    const std::vector<float> half_a = pack4(halves.rgb[0], nullptr), half_b = pack4(halves.rgb[1], nullptr);
    const std::vector<float> albedo_depth = pack4(features.albedo, &features.depth);
    const std::vector<float> normal = pack4(features.normal, nullptr);
    const int r = int(settings.radius);
    // One work item a pixel, in groups of 64 (the kernels skip the items past the image)
    const cl::NDRange global((pixels + 63) / 64 * 64), local(64);
    cl_call("denoising", [&] {
        const cl::Context& c = ctx.context();
        cl::CommandQueue& queue = ctx.queue();
        auto in = [&](const std::vector<float>& v) { return upload(c, std::span<const float>(v)); };
        auto scratch = [&](std::size_t floats) { return cl::Buffer(c, CL_MEM_READ_WRITE, floats * sizeof(float)); };
        cl::Buffer a = in(half_a), b = in(half_b), guide_albedo = in(albedo_depth), guide_normal = in(normal);
        cl::Buffer params(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof p, &p);
        cl::Buffer ca = scratch(4 * pixels), cb = scratch(4 * pixels), sum_a = scratch(4 * pixels),
                   sum_b = scratch(4 * pixels), out_a = scratch(3 * pixels), out_b = scratch(3 * pixels);
        const bool color = (settings.guides & FC_DENOISE_GUIDE_COLOR) != 0;
        cl::Buffer terms = scratch(color ? 2 * pixels * std::size_t(2 * r + 1) : 1);
        const float zero = 0.0f;
        queue.enqueueFillBuffer(sum_a, zero, 0, 4 * pixels * sizeof(float));
        queue.enqueueFillBuffer(sum_b, zero, 0, 4 * pixels * sizeof(float));

        cl::Kernel variance(build.program, "denoise_variance"), term(build.program, "denoise_terms");
        cl::Kernel accumulate(build.program, "denoise_accumulate"), finish(build.program, "denoise_finish");
        variance.setArg(0, params), variance.setArg(1, a), variance.setArg(2, b);
        variance.setArg(3, ca), variance.setArg(4, cb);
        queue.enqueueNDRangeKernel(variance, cl::NullRange, global, local);
        term.setArg(0, params), term.setArg(1, ca), term.setArg(2, cb), term.setArg(3, terms);
        accumulate.setArg(0, params), accumulate.setArg(1, ca), accumulate.setArg(2, cb);
        accumulate.setArg(3, guide_albedo), accumulate.setArg(4, guide_normal), accumulate.setArg(5, terms);
        accumulate.setArg(6, sum_a), accumulate.setArg(7, sum_b);
        for (cl_int dy = -r; dy <= r; ++dy) {
            if (color) {
                term.setArg(4, dy);
                queue.enqueueNDRangeKernel(term, cl::NullRange, global, local);
            }
            accumulate.setArg(8, dy);
            queue.enqueueNDRangeKernel(accumulate, cl::NullRange, global, local);
        }
        finish.setArg(0, params), finish.setArg(1, ca), finish.setArg(2, cb), finish.setArg(3, sum_a);
        finish.setArg(4, sum_b), finish.setArg(5, out_a), finish.setArg(6, out_b);
        queue.enqueueNDRangeKernel(finish, cl::NullRange, global, local);
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
