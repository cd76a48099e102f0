// Helpers of the environment tests (environment_test.cpp, environment_chi2_test.cpp):
// an EnvironmentMap on the device and the kernels of kernels/test/environment_kernels.cl.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "tests/cl_test_env.hpp"
#include "host/scene/environment_map.hpp"

namespace facet::test::env {

constexpr double kPi = std::numbers::pi;
inline const char* kProgram = "kernels/test/environment_kernels.cl";

// The sums over work-items of each of their float4 results' four parts, in double.
inline std::array<double, 4> sum_items(const std::vector<cl_float4>& r) {
    std::array<double, 4> s{};
    for (const cl_float4& v : r)
        for (int c = 0; c < 4; ++c) s[c] += double(v.s[c]);
    return s;
}

struct DeviceEnv {
    cl::Buffer params, texels, dist;
    explicit DeviceEnv(const EnvironmentMap& e) {
        const cl::Context& c = context().context();
        params = cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcEnvironment),
                            const_cast<FcEnvironment*>(&e.params));
        texels = cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, e.texels.size() * sizeof(float),
                            const_cast<float*>(e.texels.data()));
        dist = cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, e.distribution.size() * sizeof(float),
                          const_cast<float*>(e.distribution.data()));
    }
};

// A rotation (world to map) about a tilted axis, so that no axis is left in place.
inline glm::mat3 test_rotation() {
    return glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, -0.5f))));
}

// Map-frame direction of (theta, phi) by the convention of kernels/shared/environment_layout.h.
inline glm::dvec3 map_direction(double theta, double phi) {
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// World direction of a map-frame direction: to_map^T m.
inline cl_float4 to_world(const FcEnvironment& p, const glm::dvec3& m) {
    double w[3];
    for (int c = 0; c < 3; ++c)
        w[c] = double(p.to_map[0][c]) * m.x + double(p.to_map[1][c]) * m.y + double(p.to_map[2][c]) * m.z;
    return cl_float4{{float(w[0]), float(w[1]), float(w[2]), 0.0f}};
}

// n unit directions spread evenly over the sphere (a Fibonacci spiral about z).
inline std::vector<cl_float4> spiral_directions(int n) {
    std::vector<cl_float4> dirs;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n, ph = 2.399963 * i, s = std::sqrt(1.0 - z * z);
        dirs.push_back({{float(s * std::cos(ph)), float(s * std::sin(ph)), float(z), 0.0f}});
    }
    return dirs;
}

// A smooth map: a bright lobe, a band and a gradient (values > 0), w x h texels.
inline std::vector<float> smooth_map(int w, int h) {
    std::vector<float> rgb(std::size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double th = kPi * (y + 0.5) / h, ph = 2.0 * kPi * (x + 0.5) / w;
            const double lobe = std::exp(8.0 * (std::cos(th - 0.9) * std::cos(ph - 2.0) - 1.0));
            const double v = 0.2 + 0.1 * std::sin(3.0 * ph) * std::sin(th) + 5.0 * lobe;
            for (int c = 0; c < 3; ++c) rgb[3 * (std::size_t(y) * w + x) + c] = float(v * (1.0 + 0.3 * c));
        }
    return rgb;
}

struct SampleBatch {
    std::vector<cl_float4> dir_pdf, radiance, eval;
};

inline SampleBatch sample_batch(const EnvironmentMap& e, std::size_t n, std::uint32_t seed) {
    DeviceEnv d(e);
    ClContext& ctx = context();
    SampleBatch b;
    std::vector<cl::Buffer> out;
    for (int i = 0; i < 3; ++i) out.emplace_back(ctx.context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Kernel k(program(kProgram), "env_sample_batch");
    k.setArg(0, d.params);
    k.setArg(1, d.texels);
    k.setArg(2, d.dist);
    k.setArg(3, seed);
    for (int i = 0; i < 3; ++i) k.setArg(4 + i, out[i]);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    for (auto* v : {&b.dir_pdf, &b.radiance, &b.eval}) v->resize(n);
    ctx.queue().enqueueReadBuffer(out[0], CL_TRUE, 0, n * sizeof(cl_float4), b.dir_pdf.data());
    ctx.queue().enqueueReadBuffer(out[1], CL_TRUE, 0, n * sizeof(cl_float4), b.radiance.data());
    ctx.queue().enqueueReadBuffer(out[2], CL_TRUE, 0, n * sizeof(cl_float4), b.eval.data());
    return b;
}

// (radiance, pdf) at each direction.
inline std::vector<cl_float4> eval_batch(const EnvironmentMap& e, const std::vector<cl_float4>& dirs) {
    DeviceEnv d(e);
    ClContext& ctx = context();
    cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dirs.size() * sizeof(cl_float4),
                  const_cast<cl_float4*>(dirs.data()));
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, dirs.size() * sizeof(cl_float4));
    cl::Kernel k(program(kProgram), "env_eval_batch");
    k.setArg(0, d.params);
    k.setArg(1, d.texels);
    k.setArg(2, d.dist);
    k.setArg(3, in);
    k.setArg(4, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(dirs.size()));
    std::vector<cl_float4> r(dirs.size());
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, r.size() * sizeof(cl_float4), r.data());
    return r;
}

// World directions of every texel centre of a map (row-major), and the midpoint rule's
// solid-angle weight sin(theta) dtheta dphi of each: exact for the piecewise-constant
// p(u, v) / sin(theta) density. With sub > 1, the centres of a grid sub times finer: at
// sub = 2 the quarters of each texel, on which the bilinear lookup's p(u, v) is bilinear,
// so that the rule is exact for it too.
inline void texel_centres(const EnvironmentMap& e, std::vector<cl_float4>& dirs, std::vector<double>& weights,
                          int sub = 1) {
    const int w = e.params.width * sub, h = e.params.height * sub;
    dirs.clear();
    weights.clear();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double th = kPi * (y + 0.5) / h;
            dirs.push_back(to_world(e.params, map_direction(th, 2.0 * kPi * (x + 0.5) / w)));
            weights.push_back(std::sin(th) * (kPi / h) * (2.0 * kPi / w));
        }
}

}  // namespace facet::test::env
