// Helpers of the dielectric tests: materials, the exact Fresnel and Snell's law in
// double, and the kernels of kernels/test/dielectric_kernels.cl run on batches.
#pragma once

#include <cmath>
#include <vector>

#include "tests/microfacet_test_util.hpp"
#include "kernels/shared/material_layout.h"

namespace facet::test::dl {

using mf::Vec3;

// The dielectric alone: clear (transmittance 1), height-correlated Smith, visible normals.
inline FcMaterial glass(int ndf, float eta, float alpha) {
    FcMaterial m = mf::lobe_material(FC_DIFFUSE_NONE, FC_SPECULAR_DIELECTRIC);
    m.ndf = ndf;
    m.ior = eta;
    m.alpha_x = m.alpha_y = alpha;
    m.fresnel = FC_FRESNEL_DIELECTRIC;
    for (int c = 0; c < 3; ++c) m.specular[c] = 1.0f;
    return m;
}

// Exact unpolarised reflectance seen from cos_i (> 0) with relative index eta = n_t / n_i.
inline double fresnel(double cos_i, double eta) {
    double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) return 1.0;
    double cos_t = std::sqrt(1.0 - sin2_t);
    double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// wo (above, +z) refracted into the medium below (index ratio eta); false on TIR.
inline bool refract_down(const Vec3& wo, double eta, Vec3& wt) {
    double sin2_t = (1.0 - wo.z * wo.z) / (eta * eta);
    if (sin2_t >= 1.0) return false;
    double cos_t = std::sqrt(1.0 - sin2_t);
    wt = {-wo.x / eta, -wo.y / eta, -cos_t};
    return true;
}

// (bsdf_eval, bsdf_pdf) for each (mats[i], wo[i], wi[i]).
inline std::vector<cl_float4> eval(const std::vector<FcMaterial>& mats, const std::vector<cl_float4>& wo,
                                   const std::vector<cl_float4>& wi) {
    using namespace mf;
    cl::Buffer mb = upload(mats), a = upload(wo), b = upload(wi);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, mats.size() * sizeof(cl_float4));
    cl::Kernel k(test::program("kernels/test/dielectric_kernels.cl"), "dl_eval");
    k.setArg(0, mb);
    k.setArg(1, a);
    k.setArg(2, b);
    k.setArg(3, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    return download<cl_float4>(out, mats.size());
}

struct Albedo {
    double r, r_err, t, t_err, bad, wmax, reflected, refused;
};

// dl_albedo: energy albedos of reflection and transmission from `samples` draws each.
inline std::vector<Albedo> albedo(const std::vector<FcMaterial>& mats, const std::vector<cl_float4>& wo, int samples) {
    using namespace mf;
    cl::Buffer mb = upload(mats), a = upload(wo);
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, 8 * mats.size() * sizeof(float));
    cl::Kernel k(test::program("kernels/test/dielectric_kernels.cl"), "dl_albedo");
    k.setArg(0, mb);
    k.setArg(1, a);
    k.setArg(2, out);
    k.setArg(3, samples);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(mats.size()));
    std::vector<float> v = download<float>(out, 8 * mats.size());
    std::vector<Albedo> r(mats.size());
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const float* p = &v[8 * i];
        r[i] = {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
    }
    return r;
}

}  // namespace facet::test::dl
