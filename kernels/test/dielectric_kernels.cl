/* Test kernels of the dielectric BSDF (tests/dielectric_test.cpp,
 * tests/dielectric_chi2_test.cpp): eval/pdf batches, sample-against-eval consistency
 * and directional albedos split into reflection and transmission. The chi-square
 * histograms use kernels/test/microfacet_kernels.cl (bsdf_sample / bsdf_pdf). */
#include "kernels/bsdf/bsdf.cl"
#include "kernels/util/rng.cl"

/* out[i] = (bsdf_eval(mats[i], wo[i], wi[i]), bsdf_pdf(...)). */
__kernel void dl_eval(__global const FcMaterial* mats, __global const float4* wo, __global const float4* wi,
                      __global float4* out) {
    size_t i = get_global_id(0);
    FcMaterial m = mats[i];
    out[i] = (float4)(bsdf_eval(&m, wo[i].xyz, wi[i].xyz), bsdf_pdf(&m, wo[i].xyz, wi[i].xyz));
}

/* `samples` bsdf_sample draws of mats[i] from wo[i]. The energy albedos (the
 * transported power, i.e. the weight times etap^2 for a refraction, undoing the
 * radiance scaling): out[8i] = reflection mean, out[8i+1] its standard error,
 * out[8i+2] = transmission mean, out[8i+3] its standard error, out[8i+4] = samples
 * with a non-finite or negative value, or whose f / pdf differ from bsdf_eval /
 * bsdf_pdf by more than 1e-5 relative, out[8i+5] = the largest energy weight,
 * out[8i+6] = the fraction of samples reflected, out[8i+7] = the fraction refused. */
__kernel void dl_albedo(__global const FcMaterial* mats, __global const float4* wos, __global float* out, int samples) {
    int i = (int)get_global_id(0);
    FcMaterial m = mats[i];
    float3 wo = wos[i].xyz;
    Rng rng = rng_init(4321u, (uint)i, 0u);
    float sum[2] = {0.0f, 0.0f}, sum2[2] = {0.0f, 0.0f};
    float bad = 0.0f, wmax = 0.0f, reflected = 0.0f, refused = 0.0f;
    for (int k = 0; k < samples; ++k) {
        float3 u = (float3)(rng_float(&rng), rng_float(&rng), rng_float(&rng));
        BsdfSample s;
        if (!bsdf_sample(&m, wo, u, &s)) {
            refused += 1.0f;
            continue;
        }
        bool reflect = s.wi.z * wo.z > 0.0f;
        float etap = reflect ? 1.0f : relative_eta(m.ior, wo.z);
        float w = s.weight.x * etap * etap;
        bool ok = isfinite(w) && w >= 0.0f && all_finite(s.wi);
        if (ok && !s.delta) {
            float3 f = bsdf_eval(&m, wo, s.wi);
            float p = bsdf_pdf(&m, wo, s.wi);
            ok = fabs(f.x - s.f.x) <= 1e-5f * f.x && fabs(p - s.pdf) <= 1e-5f * p && s.pdf > 0.0f;
        }
        if (!ok) {
            bad += 1.0f;
            continue;
        }
        int lobe = reflect ? 0 : 1;
        sum[lobe] += w;
        sum2[lobe] += w * w;
        wmax = fmax(wmax, w);
        reflected += reflect ? 1.0f : 0.0f;
    }
    float n = (float)samples;
    for (int lobe = 0; lobe < 2; ++lobe) {
        float mean = sum[lobe] / n;
        out[8 * i + 2 * lobe] = mean;
        out[8 * i + 2 * lobe + 1] = sqrt(fmax(sum2[lobe] / n - mean * mean, 0.0f) / (n - 1.0f));
    }
    out[8 * i + 4] = bad;
    out[8 * i + 5] = wmax;
    out[8 * i + 6] = reflected / n;
    out[8 * i + 7] = refused / n;
}
