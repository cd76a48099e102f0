/* Auxiliary images (AOVs) for denoisers (Intel Open Image Denoise, OptiX) and
 * compositors, at the first non-specular hit of each camera sample: the albedo, the
 * shading normal and the depth. Camera samples are drawn as the path tracer draws them
 * (pixel filter, thin lens; kernels/integrator/path.cl), so the AOVs are filtered as the
 * image is. Delta (mirror, smooth glass) surfaces are passed through along a sampled
 * direction, their weight carried into the albedo, as OIDN asks for.
 *   albedo  the diffuse reflectance plus the specular lobe's Fresnel reflectance at the
 *           viewing angle, clamped to [0, 1] per channel (Cycles' denoising albedo),
 *           with the material's textures applied as the path tracer applies them
 *           (apply_textures); 0 where the sample escapes
 *   normal  the world-space shading normal (normal-mapped), facing the incoming ray; 0
 *           where it escapes
 *   depth   the length of the path from the camera to the hit (through mirrors: the
 *           depth of the reflection); averaged over the samples that hit
 * The accumulation buffer holds two float4 a pixel: (albedo sum, sum of |weight| over the
 * samples that hit) then (normal sum, sum of |weight| x depth); samples are weighted as
 * kernels/camera/filter.cl says. */
#ifndef FACET_AOV_AOV_CL
#define FACET_AOV_AOV_CL

#include "kernels/integrator/surface.cl"
#include "kernels/camera/pixel_sample.cl"
#include "kernels/bsdf/bsdf.cl"
#include "kernels/util/sampler.cl"
#include "kernels/texture/material_textures.cl"

/* Delta surfaces followed at most this many times before a sample counts as escaped. */
#define FC_AOV_MAX_DELTA_BOUNCES 16u

/* The reflectance a denoiser sees at a non-delta surface, seen from wo_local. A metallic
 * material's is the mix of its dielectric's (diffuse base plus F at 0.04) and its metal's
 * (F from the base colour) by M, as the BRDF mixes them (metallic.cl). The clearcoat and
 * sheen layers weigh it as the BRDF does (bsdf.cl): c E_coat + (1 - c E_coat) (S E_sheen +
 * (1 - max(S) E_sheen) a). */
inline float3 aov_albedo(const FcMaterial* m, float3 wo_local) {
    float3 a = (float3)(0.0f);
    if (m->diffuse_model != FC_DIFFUSE_NONE) a += load3p(m->diffuse);
    if (m->specular_model == FC_SPECULAR_BLINN_PHONG || m->specular_model == FC_SPECULAR_BLINN_PHONG_NORMALIZED)
        a += load3p(m->specular);
    else if (m->specular_model != FC_SPECULAR_NONE) a += fresnel_eval(m, fabs(wo_local.z));
    if (metallic_mixed(m)) {
        FcMaterial metal = metallic_lobe(m);
        a = mix(a, fresnel_eval(&metal, fabs(wo_local.z)), metallic_weight(m));
    }
    if (bsdf_layered(m)) {
        float3 wo = (float3)(wo_local.xy, fabs(wo_local.z));
        float4 w = bsdf_layer_weights(m, wo);
        a *= w.y;
        if (sheen_present(m)) a += sheen_color(m) * sheen_albedo(m->sheen_roughness, wo.z);
        a = w.x + w.z * a;
    }
    return clamp(a, 0.0f, 1.0f);
}

__kernel void aov_pass(FC_SCENE_KERNEL_PARAMS, __global float4* accum) {
    uint gid = get_global_id(0);
    uint x = gid % params->width;
    uint y = params->row_begin + gid / params->width;
    if (gid / params->width >= params->row_count || y >= params->height) return;
    uint pixel = y * params->width + x;
    SceneView sc = FC_SCENE_VIEW_INIT;
    float4 albedo_sum = (float4)(0.0f), normal_sum = (float4)(0.0f);
    for (uint i = 0; i < params->sample_count; ++i) {
        uint index = params->sample_begin + i;
        Sampler sampler = sampler_init(params->sampler, params->seed, pixel, index);
        float3 o, d;
        float weight = pixel_sample_ray(params, x, y, &sampler, &o, &d);
        float3 throughput = (float3)(1.0f);
        float distance = 0.0f;
        for (uint bounce = 0; bounce <= FC_AOV_MAX_DELTA_BOUNCES; ++bounce) {
            Hit hit;
            if (!scene_trace_closest(&sc, o, d, INFINITY,
                                     alpha_ray_seed(sampler.seed, sampler.index_reversed, bounce, 0u), &hit))
                break;
            distance += hit.t;
            Surface s = scene_surface_at(&sc, &hit, o, d);
            FcMaterial mat = materials[s.material];
#if FC_HAS_TEXTURES
            apply_textures(&sc, &hit, s.material, d, ray_cone_width(params, distance), &s.ns, &mat);
#endif
            const FcMaterial* m = &mat;
            float3 wo = -d;
            float3 wo_local; /* the side the ray arrived from (as path.cl) */
            Frame frame = surface_orient(&s, &mat, wo, &wo_local);
            if (!bsdf_is_delta(m)) {
                /* Albedo and normal filtered as the image is; the depth averaged with |weight| */
                albedo_sum += (float4)(weight * throughput * aov_albedo(m, wo_local), fabs(weight));
                normal_sum += (float4)(weight * s.ns, fabs(weight) * distance);
                break;
            }
            BsdfSample bs;
            if (!bsdf_sample(m, wo_local, sampler_get4(&sampler, sampler_set_bsdf(bounce)).xyz, &bs)) break;
            float3 wi = frame_to_world(&frame, bs.wi);
            float side = dot(s.ng, wi);
            if (!(side * bs.wi.z > 0.0f)) break;
            throughput = fmin(throughput * bs.weight, (float3)(1.0f));
            o = surface_offset(&s, side > 0.0f ? s.ng : -s.ng);
            d = wi;
        }
    }
    accum[pixel] += albedo_sum;
    accum[params->width * params->height + pixel] += normal_sum;
}

#endif
