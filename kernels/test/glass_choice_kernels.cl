/* Test kernels for tests/glass_choice_test.cpp: a smooth dielectric sampled with the choice
 * toward the light (kernels/integrator/glass_choice.cl). */
#include "kernels/integrator/glass_choice.cl"
#include "kernels/util/rng.cl"

/* The material *mat at a surface of normal n seen from wo_world, sampled per_item times by
 * glass_light_sample. Per work-item: (sum of the reflections' weights in red, how many
 * reflected, sum of the refractions' weights in red, the probability of reflection chosen). */
__kernel void glass_choice_estimate(__constant const FcEnvironment* env, __global const float4* texels,
                                    __global const float* dist, __global const FcMaterial* mat, float4 n,
                                    float4 wo_world, uint seed, uint per_item, __global float4* out) {
    const uint i = (uint)get_global_id(0);
    Rng rng = rng_init(seed, i, 0x6763u);
    const FcMaterial m = *mat;
    const Frame f = frame_from_normal(normalize(n.xyz));
    const float3 wo = frame_to_local(&f, normalize(wo_world.xyz));
    const float q = glass_light_q(env, texels, dist, &m, &f, wo, fresnel_dielectric(wo.z, m.ior));
    float reflected = 0.0f, reflections = 0.0f, refracted = 0.0f;
    for (uint k = 0; k < per_item; ++k) {
        BsdfSample s;
        if (!glass_light_sample(env, texels, dist, &m, &f, wo, rng_float(&rng), &s)) continue;
        if (s.wi.z * wo.z > 0.0f) {
            reflected += s.weight.x;
            reflections += 1.0f;
        } else refracted += s.weight.x;
    }
    out[i] = (float4)(reflected, reflections, refracted, q);
}

/* glass_light_q at the surface of normal n seen from each wo_world of `wos` (xyz), and the q of
 * env_pdf's density read at every mirror direction (the choice's own formula without the rows'
 * bound): (q, the density's q). */
__kernel void glass_choice_q(__constant const FcEnvironment* env, __global const float4* texels,
                             __global const float* dist, __global const FcMaterial* mat, float4 n,
                             __global const float4* wos, __global float2* out) {
    const uint i = (uint)get_global_id(0);
    const FcMaterial m = *mat;
    const Frame f = frame_from_normal(normalize(n.xyz));
    const float3 wo = frame_to_local(&f, normalize(wos[i].xyz));
    const float fr = fresnel_dielectric(wo.z, m.ior);
    float q = dielectric_choice(&m, fr);
    if (wo.z > 0.0f && fr > 0.0f && q < FC_GLASS_LIGHT_CHOICE_MAX) {
        const float rho = 4.0f * FC_PI * env_pdf(env, texels, dist, frame_to_world(&f, (float3)(-wo.x, -wo.y, wo.z)));
        const float share = fr * rho / (fr * rho + (1.0f - fr));
        q = share > q ? fmin(share, FC_GLASS_LIGHT_CHOICE_MAX) : q;
    }
    out[i] = (float2)(glass_light_q(env, texels, dist, &m, &f, wo, fr), q);
}
