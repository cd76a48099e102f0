// BSDF evaluation and sampling throughput per model on the OpenCL device.
#include <algorithm>
#include <chrono>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"

namespace facet {

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
    return rows;
}

}  // namespace facet
