// Helpers of the microfacet tests: materials, directions, and the kernels of
// kernels/test/microfacet_kernels.cl run on batches.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tests/chi2_test_util.hpp"
#include "tests/cl_test_env.hpp"
#include "kernels/shared/material_layout.h"

namespace facet::test::mf {

constexpr int kModeMicrofacet = 0;
constexpr int kModeNdf = 1;
constexpr int kModeSpecular = 2;
constexpr int kModeBsdf = 3;

struct Vec3 {
    double x, y, z;
};

inline cl_float4 f4(const Vec3& v) {
    cl_float4 r;
    r.s[0] = float(v.x);
    r.s[1] = float(v.y);
    r.s[2] = float(v.z);
    r.s[3] = 0.0f;
    return r;
}

// The direction at polar angle `deg` degrees and azimuth phi (radians).
inline Vec3 direction(double deg, double phi) {
    double t = deg * std::numbers::pi / 180.0;
    return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

inline Vec3 mirror(const Vec3& w) { return {-w.x, -w.y, w.z}; }

inline FcMaterial lobe_material(int diffuse_model, int specular_model) {
    FcMaterial m{};
    for (int c = 0; c < 3; ++c) {
        m.diffuse[c] = 0.5f;
        m.specular[c] = 0.04f;
        m.eta[c] = 1.5f;
        m.k[c] = 0.0f;
    }
    m.diffuse_model = diffuse_model;
    m.specular_model = specular_model;
    m.ndf = FC_NDF_GGX;
    m.geometry = FC_G_SMITH_CORRELATED;
    m.fresnel = FC_FRESNEL_SCHLICK;
    m.alpha_x = m.alpha_y = 0.3f;
    m.exponent_x = m.exponent_y = 20.0f;
    m.ior = 1.5f;
    m.sigma = 0.5f;
    m.sampling = FC_SAMPLE_VISIBLE;
    return m;
}

// A microfacet lobe alone, F = 1, height-correlated Smith G.
inline FcMaterial microfacet_material(int ndf, int sampling, float ax, float ay) {
    FcMaterial m = lobe_material(FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET);
    m.ndf = ndf;
    m.sampling = sampling;
    m.alpha_x = ax;
    m.alpha_y = ay;
    m.fresnel = FC_FRESNEL_ONE;
    return m;
}

inline cl::Program& program() { return test::program("kernels/test/microfacet_kernels.cl"); }

inline cl::Buffer material_buffer(const FcMaterial& m) {
    return cl::Buffer(context().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(FcMaterial),
                      const_cast<FcMaterial*>(&m));
}

template <typename T>
cl::Buffer upload(const std::vector<T>& v) {
    return cl::Buffer(context().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(T),
                      const_cast<T*>(v.data()));
}

template <typename T>
std::vector<T> download(const cl::Buffer& b, std::size_t n) {
    std::vector<T> v(n);
    context().queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(T), v.data());
    return v;
}

// The densities (mode as in the kernels) at the given directions.
inline std::vector<float> pdfs(const FcMaterial& m, const Vec3& wo, int mode, const std::vector<cl_float4>& dirs) {
    cl::Buffer mat = material_buffer(m), in = upload(dirs);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, dirs.size() * sizeof(float));
    cl::Kernel k(program(), "mf_pdf_batch");
    k.setArg(0, mat);
    k.setArg(1, f4(wo));
    k.setArg(2, mode);
    k.setArg(3, in);
    k.setArg(4, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(dirs.size()));
    return download<float>(out, dirs.size());
}

constexpr unsigned kItems = 4096;
constexpr unsigned kPerItem = 245;  // 4096 x 245 = 1,003,520 samples
constexpr unsigned kGroup = 256;    // work-items per local histogram

// The chart histogram of kItems * per_item samples (cells, refused, invalid).
inline std::vector<std::uint32_t> histogram(const FcMaterial& m, const Vec3& wo, int mode, const chi2::Chart& chart,
                                            unsigned seed, unsigned per_item = kPerItem) {
    std::vector<float> te(chart.theta_edges.begin(), chart.theta_edges.end());
    std::vector<float> pe(chart.phi_edges.begin(), chart.phi_edges.end());
    std::vector<std::uint32_t> zero(std::size_t(chart.cells()) + 2, 0u);
    cl::Buffer mat = material_buffer(m), tb = upload(te), pb = upload(pe);
    cl::Buffer hist(context().context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, zero.size() * sizeof(std::uint32_t),
                    zero.data());
    cl::Kernel k(program(), "mf_sample_hist");
    k.setArg(0, mat);
    k.setArg(1, f4(wo));
    k.setArg(2, mode);
    k.setArg(3, seed);
    k.setArg(4, per_item);
    k.setArg(5, chart.n_theta());
    k.setArg(6, chart.n_phi());
    k.setArg(7, tb);
    k.setArg(8, pb);
    k.setArg(9, float(chart.phi0));
    k.setArg(10, hist);
    k.setArg(11, cl::Local(zero.size() * sizeof(std::uint32_t)));
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(kItems), cl::NDRange(kGroup));
    return download<std::uint32_t>(hist, zero.size());
}

// The width of a lobe across its plane of incidence (chi2::make_lobe_chart): reflected
// lobes are compressed by cos(theta_o); normals are not.
inline double lobe_perp(int mode, const Vec3& wo, double width) {
    return mode == kModeNdf ? width : width * std::max(wo.z, 1e-4);
}

// Samples `sampled` and tests the samples against the pdf of `density` (normally the same).
inline chi2::Result chi_square_mismatch(const FcMaterial& sampled, const FcMaterial& density, const Vec3& wo, int mode,
                                        const Vec3& axis, double width, double level, unsigned seed) {
    const double a[3] = {axis.x, axis.y, axis.z};
    chi2::Chart chart = chi2::make_lobe_chart(a, width, lobe_perp(mode, wo, width));
    chi2::Quadrature q = chi2::make_quadrature(chart);
    std::vector<double> mass = chi2::cell_masses(q, pdfs(density, wo, mode, q.dirs));
    auto hist = histogram(sampled, wo, mode, chart, seed);
    return chi2::test(hist, mass, std::uint64_t(kItems) * kPerItem, level);
}

inline chi2::Result chi_square(const FcMaterial& m, const Vec3& wo, int mode, const Vec3& axis, double width,
                               double level, unsigned seed) {
    return chi_square_mismatch(m, m, wo, mode, axis, width, level, seed);
}

// The integral of the density over the sphere, by the chart's quadrature.
inline double pdf_mass(const FcMaterial& m, const Vec3& wo, int mode, const Vec3& axis, double width) {
    const double a[3] = {axis.x, axis.y, axis.z};
    chi2::Quadrature q = chi2::make_quadrature(chi2::make_lobe_chart(a, width, lobe_perp(mode, wo, width)));
    double s = 0.0;
    for (double v : chi2::cell_masses(q, pdfs(m, wo, mode, q.dirs))) s += v;
    return s;
}

// (D(m), Lambda(m), ndf_pdf(wo, m), G1(wo, m)) at each direction m.
inline std::vector<cl_float4> ndf_terms(const FcMaterial& m, const Vec3& wo, const std::vector<cl_float4>& dirs) {
    cl::Buffer mat = material_buffer(m), in = upload(dirs);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, dirs.size() * sizeof(cl_float4));
    cl::Kernel k(program(), "mf_ndf_terms");
    k.setArg(0, mat);
    k.setArg(1, f4(wo));
    k.setArg(2, in);
    k.setArg(3, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(dirs.size()));
    return download<cl_float4>(out, dirs.size());
}

// Every FC_G_* term for each (wo[i], wi[i]): FC_G_COUNT values per pair.
inline std::vector<float> geometry_terms(const FcMaterial& m, const std::vector<cl_float4>& wo,
                                         const std::vector<cl_float4>& wi) {
    cl::Buffer mat = material_buffer(m), a = upload(wo), b = upload(wi);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, wo.size() * FC_G_COUNT * sizeof(float));
    cl::Kernel k(program(), "mf_geometry");
    k.setArg(0, mat);
    k.setArg(1, a);
    k.setArg(2, b);
    k.setArg(3, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(wo.size()));
    return download<float>(out, wo.size() * FC_G_COUNT);
}

// mf_consistency's four float4 per material.
inline std::vector<cl_float4> consistency(const std::vector<FcMaterial>& mats, const std::vector<cl_float4>& wo,
                                          const std::vector<cl_float4>& u) {
    cl::Buffer mb = upload(mats), a = upload(wo), b = upload(u);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, 4 * mats.size() * sizeof(cl_float4));
    cl::Kernel k(program(), "mf_consistency");
    k.setArg(0, mb);
    k.setArg(1, a);
    k.setArg(2, b);
    k.setArg(3, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    return download<cl_float4>(out, 4 * mats.size());
}

struct SweepResult {
    std::uint64_t checked = 0;
    unsigned failures = 0;
    std::string report;  // the first failures, one a line
};

// mf_extreme_sweep over `materials` work-items.
inline SweepResult extreme_sweep(unsigned materials, unsigned seed) {
    std::vector<std::uint32_t> zero(2, 0u);
    cl::Buffer counters(context().context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, 2 * sizeof(std::uint32_t),
                        zero.data());
    cl::Buffer fails(context().context(), CL_MEM_WRITE_ONLY, 16 * sizeof(FcMaterial));
    cl::Buffer dirs(context().context(), CL_MEM_WRITE_ONLY, 32 * sizeof(cl_float4));
    cl::Kernel k(program(), "mf_extreme_sweep");
    k.setArg(0, seed);
    k.setArg(1, counters);
    k.setArg(2, fails);
    k.setArg(3, dirs);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(materials));
    auto c = download<std::uint32_t>(counters, 2);
    SweepResult r;
    r.checked = c[0];
    r.failures = c[1];
    auto fm = download<FcMaterial>(fails, 16);
    auto fd = download<cl_float4>(dirs, 32);
    std::ostringstream s;
    for (unsigned i = 0; i < std::min(r.failures, 16u); ++i) {
        const FcMaterial& m = fm[i];
        const cl_float4 &o = fd[2 * i], &w = fd[2 * i + 1];
        s << "code " << o.s[3] << " value " << w.s[3] << ": diffuse " << m.diffuse_model << " specular "
          << m.specular_model << " ndf " << m.ndf << " G " << m.geometry << " F " << m.fresnel << " sampling "
          << m.sampling << " alpha " << m.alpha_x << "," << m.alpha_y << " e " << m.exponent_x << "," << m.exponent_y
          << " ior " << m.ior << " wo " << o.s[0] << "," << o.s[1] << "," << o.s[2] << " wi " << w.s[0] << "," << w.s[1]
          << "," << w.s[2] << "\n";
    }
    r.report = s.str();
    return r;
}

struct Albedo {
    double mean[3], error[3];
    int bad;
};

// The directional albedo of mats[i] seen from wo[i] (albedo_kernels.cl's albedo_furnace), its
// standard error per channel and the count of bad (non-finite or negative) samples.
inline std::vector<Albedo> albedos(const std::vector<FcMaterial>& mats, const std::vector<Vec3>& wo, unsigned samples) {
    std::vector<cl_float4> dirs;
    for (const Vec3& v : wo) dirs.push_back(f4(v));
    cl::Buffer bm = upload(mats), bd = upload(dirs);
    cl::Buffer bo(test::context().context(), CL_MEM_WRITE_ONLY, 2 * mats.size() * sizeof(cl_float4));
    cl::Kernel k(test::program("kernels/test/albedo_kernels.cl"), "albedo_furnace");
    k.setArg(0, bm), k.setArg(1, bd), k.setArg(2, samples), k.setArg(3, bo);
    test::context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<cl_float4> out = download<cl_float4>(bo, 2 * mats.size());
    std::vector<Albedo> r(mats.size());
    for (std::size_t i = 0; i < mats.size(); ++i) {
        for (int c = 0; c < 3; ++c) r[i].mean[c] = out[2 * i].s[c], r[i].error[c] = out[2 * i + 1].s[c];
        r[i].bad = int(out[2 * i + 1].s[3]);
    }
    return r;
}

}  // namespace facet::test::mf
