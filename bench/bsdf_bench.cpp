// BSDF evaluation and sampling throughput per model on the OpenCL device.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"

namespace facet {

namespace {

// Seconds of the fastest of three launches after a warm-up one.
double best_time(ClContext& ctx, cl::Kernel& kernel, std::size_t items) {
    double best = 1e30;
    for (int rep = 0; rep < 4; ++rep) {
        auto start = std::chrono::steady_clock::now();
        ctx.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(items), cl::NDRange(64));
        ctx.queue().finish();
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (rep > 0) best = std::min(best, s);
    }
    return best;
}

// The GGX visible-normal samplers (Heitz 2018, spherical caps, bounded) side by side:
// normals per second and the fraction whose reflection of wo goes below the horizon.
nlohmann::json bench_ggx_samplers(ClContext& ctx, cl::Program& program, bool quick) {
    const std::size_t items = quick ? 16384 : 65536;
    const cl_uint iterations = quick ? 32 : 128;
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, items * sizeof(float));
    cl::Buffer lost(ctx.context(), CL_MEM_READ_WRITE, items * sizeof(cl_uint));
    nlohmann::json rows = nlohmann::json::array();
    bench_print(
        "\n### GGX visible-normal samplers\n\n| sampler | alpha | theta_o | M normals/s | rejected |\n"
        "|---|---|---|---|---|\n");
    for (int sampling : {FC_SAMPLE_VISIBLE, FC_SAMPLE_SPHERICAL_CAP, FC_SAMPLE_BOUNDED})
        for (float alpha : {0.1f, 0.5f, 1.0f})
            for (double deg : {0.0, 45.0, 80.0}) {
                Material mat = make_material("conductor");
                mat.sampling = sampling;
                mat.alpha_x = mat.alpha_y = alpha;
                FcMaterial m = device_material(mat);
                cl::Buffer mb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof m, &m);
                const double t = deg * 3.14159265358979323846 / 180.0;
                cl_float4 wo = {{float(std::sin(t)), 0.0f, float(std::cos(t)), 0.0f}};
                cl::Kernel kernel(program, "ndf_sampler_bench");
                kernel.setArg(0, mb), kernel.setArg(1, wo), kernel.setArg(2, iterations), kernel.setArg(3, out);
                kernel.setArg(4, lost);
                const double rate = double(items) * iterations / best_time(ctx, kernel, items) * 1e-6;
                std::vector<cl_uint> counts(items);
                ctx.queue().enqueueReadBuffer(lost, CL_TRUE, 0, items * sizeof(cl_uint), counts.data());
                double rejected = 0.0;
                for (cl_uint c : counts) rejected += c;
                rejected /= double(items) * iterations;
                const std::string name = enum_to_name(MaterialEnum::Sampling, sampling);
                bench_print("| {} | {:g} | {:g} | {:.1f} | {:.3f} |\n", name, alpha, deg, rate, rejected);
                rows.push_back({{"sampler", name},
                                {"alpha", alpha},
                                {"theta_o", deg},
                                {"m_normals_per_s", rate},
                                {"rejected", rejected}});
            }
    return rows;
}

}  // namespace

nlohmann::json bench_bsdfs(ClContext& ctx, bool quick) {
    cl::Program program = build_program(ctx, "kernels/bench/bsdf_bench.cl").program;
    const std::size_t items = quick ? 16384 : 65536;
    const cl_uint iterations = quick ? 16 : 64;
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, items * sizeof(float));
    nlohmann::json rows = nlohmann::json::array();
    bench_print("\n### BSDF throughput\n\n| model | eval + pdf M/s | sample M/s |\n|---|---|---|\n");
    for (std::string_view name : material_model_names()) {
        FcMaterial m = device_material(make_material(std::string(name)));
        cl::Buffer mb(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof m, &m);
        double rate[2];
        const char* kernels[2] = {"bsdf_eval_bench", "bsdf_sample_bench"};
        for (int k = 0; k < 2; ++k) {
            cl::Kernel kernel(program, kernels[k]);
            kernel.setArg(0, mb), kernel.setArg(1, iterations), kernel.setArg(2, out);
            double best = 1e30;
            for (int rep = 0; rep < 3; ++rep) {
                auto start = std::chrono::steady_clock::now();
                ctx.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(items), cl::NDRange(64));
                ctx.queue().finish();
                double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (rep > 0) best = std::min(best, s);  // the first launch warms up
            }
            rate[k] = double(items) * iterations / best * 1e-6;
        }
        bench_print("| {} | {:.1f} | {:.1f} |\n", name, rate[0], rate[1]);
        rows.push_back({{"model", name}, {"eval_pdf_m_per_s", rate[0]}, {"sample_m_per_s", rate[1]}});
    }
    rows.push_back({{"samplers", bench_ggx_samplers(ctx, program, quick)}});
    return rows;
}

}  // namespace facet
