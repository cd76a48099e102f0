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
    const double n = double(halves.samples[0] + halves.samples[1]);

    DenoisedImage out;
    const ProgramBuild build = build_program(ctx, "kernels/denoise/denoise.cl");
    cl_call("denoising", [&] {
        const cl::Context& c = ctx.context();
        auto in = [&](const std::vector<float>& v) { return upload(c, std::span<const float>(v)); };
        cl::Buffer half[2] = {in(halves.rgb[0]), in(halves.rgb[1])};
        cl::Buffer albedo = in(features.albedo), normal = in(features.normal), depth = in(features.depth);
        cl::Buffer variance(c, CL_MEM_READ_WRITE, pixels * sizeof(float));
        cl::Buffer result(c, CL_MEM_WRITE_ONLY, 3 * pixels * sizeof(float));
        cl::Buffer params(c, CL_MEM_READ_ONLY, sizeof p);
        cl::Kernel var_kernel(build.program, "denoise_variance"), filter(build.program, "denoise_filter");
        for (int k = 0; k < 2; ++k) {
            // The variance of half k's pixel means: E[(a - b)^2] n_other / (n_a + n_b)
            p.variance_scale = float(double(halves.samples[1 - k]) / n);
            ctx.queue().enqueueWriteBuffer(params, CL_TRUE, 0, sizeof p, &p);
            var_kernel.setArg(0, params), var_kernel.setArg(1, half[k]), var_kernel.setArg(2, half[1 - k]);
            var_kernel.setArg(3, variance);
            ctx.queue().enqueueNDRangeKernel(var_kernel, cl::NullRange, cl::NDRange(pixels));
            filter.setArg(0, params), filter.setArg(1, half[k]), filter.setArg(2, variance);
            filter.setArg(3, albedo), filter.setArg(4, normal), filter.setArg(5, depth), filter.setArg(6, result);
            ctx.queue().enqueueNDRangeKernel(filter, cl::NullRange, cl::NDRange(pixels));
            out.half[k].resize(3 * pixels);
            ctx.queue().enqueueReadBuffer(result, CL_TRUE, 0, 3 * pixels * sizeof(float), out.half[k].data());
        }
    });
    out.rgb.resize(3 * pixels);
    for (std::size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] = 0.5f * (out.half[0][i] + out.half[1][i]);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace facet
