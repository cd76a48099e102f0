/* Unidirectional path tracing with next-event estimation.
 *
 * Each work-item renders samples [sample_begin, sample_begin + sample_count) of one
 * pixel and adds their sum to the accumulation buffer. At every surface vertex the
 * light is estimated twice, by sampling a light (next-event estimation) and by
 * sampling the BSDF and hitting an emitter, and the two are combined by multiple
 * importance sampling with the power heuristic (Veach 1997, ch. 9). Paths end at
 * max_depth bounces or by Russian roulette after rr_depth bounces (survival
 * probability = the largest channel of the path throughput times rr_scale, at most
 * 0.95; pbrt-v4's and Mitsuba 3's rule, rr_scale extending their etaScale). rr_scale is what
 * the throughput understates of the path's worth: the product of etap^2 over the
 * refractions so far (a refraction's weight carries the radiance scaling 1 / etap^2,
 * dielectric.cl, which the way out of the medium undoes; without it roulette would kill
 * most paths inside glass, survival 1 / 2.25 at ior 1.5, 1 / 5.76 in diamond, and the
 * survivors would return as fireflies), and at a vertex that samples the guide's mixture
 * the mixture's density over the BSDF's own at the direction taken (a direction drawn
 * through a lens toward the sun has a weight thousands of times below the BSDF's, and its
 * path's worth is not that much lower): roulette judges each path as the BSDF alone would
 * have weighted it (docs/sampling.md, "Russian roulette").
 *
 * Dielectrics transmit: a sampled or light direction may cross the surface, and the
 * next ray then starts on the far side (offset along -ng); inside or outside is read
 * from the geometric normal's side of wo.
 *
 * Samples whose radiance is NaN, infinite or negative are not added; they are
 * counted in the accumulation buffer's w channel so that tests can demand zero.
 * Finite ones are clamped to FC_MAX_RADIANCE per channel, so the sums stay finite. */
#ifndef FACET_INTEGRATOR_PATH_CL
#define FACET_INTEGRATOR_PATH_CL

#include "kernels/integrator/caustic_guide.cl"
#include "kernels/integrator/glass_choice.cl"
#include "kernels/integrator/surface.cl"
#include "kernels/camera/pixel_sample.cl"
#include "kernels/lights/light.cl"
#include "kernels/bsdf/bsdf.cl"
#include "kernels/util/mis.cl"
#include "kernels/util/sampler.cl"
#if FC_HAS_TEXTURES
#include "kernels/texture/material_textures.cl"
#endif

/* Next-event estimation at surface `s` seen from direction wo: one light sample,
 * weighted against the density of the BSDF sample (with cg, the mixture of
 * caustic_guide.cl) by the power heuristic (delta lights: weight 1).
 * `alpha_seed` is the shadow ray's (kernels/trace/alpha_test.cl). Returns its
 * contribution before throughput. */
inline float3 sample_direct(const SceneView* sc, const Surface* s, const Frame* frame, const FcMaterial* m,
                            const CausticGuide* cg, float3 wo_local, float3 u_light, uint alpha_seed) {
    float u_pick = u_light.x;
    float2 u = u_light.yz;
    LightSample ls;
    if (!sample_light(sc, s->p, u_pick, u, &ls)) return (float3)(0.0f);
    /* Lights behind the surface count only through a dielectric; the shading frame
     * must put them on the same side as the geometric normal does. */
    float side = dot(s->ng, ls.wi);
    if (!(side > 0.0f) && !(side < 0.0f && bsdf_is_dielectric(m))) return (float3)(0.0f);
    float3 wi_local = frame_to_local(frame, ls.wi);
    if (!(wi_local.z * side > 0.0f)) return (float3)(0.0f);
    float3 f = bsdf_eval(m, wo_local, wi_local);
    if (is_black(f)) return (float3)(0.0f);
    float cos_i = fabs(wi_local.z);

    /* Shadow ray from the side of wi: to the offset point on an area light, else to
     * the light's distance. */
    float3 o = surface_offset(s, side > 0.0f ? s->ng : -s->ng);
    float3 dir = ls.wi;
    float tmax = ls.dist;
    if (isfinite(ls.dist) && !ls.delta) {
        float3 target = offset_ray_origin(ls.point, dot(ls.normal, ls.wi) < 0.0f ? ls.normal : -ls.normal);
        float3 seg = target - o;
        tmax = length(seg);
        if (!(tmax > 0.0f)) return (float3)(0.0f);
        dir = seg / tmax;
    } else if (isfinite(ls.dist)) {
        tmax = ls.dist * (1.0f - 1e-5f); /* stop short of a point light */
    }
    if (scene_trace_any(sc, o, dir, tmax, alpha_seed)) return (float3)(0.0f);

    if (ls.delta) return f * ls.li * (cos_i / ls.pdf);
    uint strategy = sc->params->strategy;
    if (strategy == FC_STRATEGY_BSDF) return (float3)(0.0f);
    /* (path_lanes.cl; BSDF sampling alone left above, before the BSDF's density) */
    float w = light_strategy_weight_l1(
        strategy, ls.pdf,
        strategy == FC_STRATEGY_MIS ? caustic_guide_pdf(&sc->params->environment, sc->env_texels, sc->env_dist,
                                                        sc->casters, sc->params->caster_count, cg,
                                                        bsdf_pdf(m, wo_local, wi_local), ls.wi, isfinite(ls.dist), 0)
                                    : 0.0f);
    return f * ls.li * (cos_i * w / ls.pdf);
}

/* roulette's rr_scale times a factor, at most 1e20: finite however many guided vertices a path
 * has (any survival probability drawn from the path so far keeps roulette unbiased). */
inline float roulette_scale_times(float rr_scale, float factor) { return fmin(rr_scale * factor, 1e20f); }

/* The weight of light found by BSDF sampling, against light sampling's density
 * (kernels/integrator/path_lanes.cl). */
inline float bsdf_strategy_weight(uint strategy, float bsdf_pdf, float light_pdf) {
    return bsdf_strategy_weight_l1(strategy, bsdf_pdf, light_pdf);
}

inline float3 path_radiance(const SceneView* sc, float3 o, float3 d, Sampler* sampler) {
    __constant const FcRenderParams* P = sc->params;
    float3 radiance = (float3)(0.0f);
    float3 throughput = (float3)(1.0f);
    float rr_scale = 1.0f;          /* roulette's scale of the throughput (above) */
    float prev_bsdf_pdf = INFINITY; /* density of the sampled direction; camera rays: a delta */
#if FC_HAS_TEXTURES
    float path_length = 0.0f; /* from the camera, for the ray cone of texture filtering */
#endif
    for (uint depth = 0;; ++depth) {
        Hit hit;
        if (!scene_trace_closest(sc, o, d, INFINITY, alpha_ray_seed(sampler->seed, sampler->index_reversed, depth, 0u),
                                 &hit)) {
#if FC_HAS_ENVIRONMENT
            /* The ray escapes: the environment, MIS-weighted against light sampling. */
            float env_pdf_d;
            float3 le = env_radiance_pdf(&P->environment, sc->env_texels, sc->env_dist, d, &env_pdf_d);
            if (!is_black(le)) {
                float light_pdf = environment_pick_pdf(sc) * env_pdf_d;
                float w = depth > 0u ? bsdf_strategy_weight(P->strategy, prev_bsdf_pdf, light_pdf) : 1.0f;
                radiance += throughput * le * w;
            }
#endif
            break;
        }
        Surface s = scene_surface_at(sc, &hit, o, d);
        FcMaterial mat = sc->materials[s.material];
#if FC_HAS_VOLUME
        /* Met from behind: the segment ran inside the closed mesh this surface bounds, which
         * absorbs by Beer-Lambert, exp(-sigma t) per channel (KHR_materials_volume; its
         * thickness is for rasterisers and not needed here). Shadow rays never run inside a
         * dielectric (it blocks them), so only this path is attenuated. */
        if (mat.specular_model == FC_SPECULAR_DIELECTRIC && dot(s.ng, d) > 0.0f)
            throughput *= exp(-load3p(mat.attenuation) * hit.t);
#endif
#if FC_HAS_TEXTURES
        path_length += hit.t;
        apply_textures(sc, &hit, s.material, d, ray_cone_width(P, path_length), &s.ns, &mat);
#endif
        const FcMaterial* m = &mat;
        float3 wo = -d;

#if FC_HAS_AREA_LIGHTS
        /* Emission reached by the camera ray or by BSDF sampling (MIS-weighted). */
        float3 le = area_light_radiance(load3p(m->emission), m->flags, s.ng, wo);
        if (!is_black(le) && s.light >= 0) {
            float w = 1.0f;
            if (depth > 0u) {
                float light_pdf = light_pdf_hit(sc, s.light, o, hit.t, dot(s.ng, wo));
                w = bsdf_strategy_weight(P->strategy, prev_bsdf_pdf, light_pdf);
            }
            radiance += throughput * le * w;
        }
#endif
        if (depth >= P->max_depth) break;

        /* Two-sided shading: work on the side the ray arrived from. */
        float3 wo_local;
        Frame frame = surface_orient(&s, &mat, wo, &wo_local);

        /* a Lambertian vertex's directions: partly toward glass (caustic_guide.cl) */
#if FC_HAS_DIELECTRIC
        const CausticGuide cg = caustic_guide_at(P, sc->casters, m, s.p, frame.n);
#else
        const CausticGuide cg = caustic_guide_none();
#endif

        if (!bsdf_is_delta(m)) {
            float4 ul = sampler_get4(sampler, sampler_set_light(depth));
            radiance += throughput * sample_direct(sc, &s, &frame, m, &cg, wo_local, ul.xyz,
                                                   alpha_ray_seed(sampler->seed, sampler->index_reversed, depth, 1u));
        }

        float4 ub = sampler_get4(sampler, sampler_set_bsdf(depth));
        float3 u = ub.xyz;
        BsdfSample bs;
        float3 wi;
        if (cg.g > 0.0f) {
            /* u.z picks the guide (then, rescaled, its cone) or the BSDF; the weight divides by
             * the mixture's density */
            GuideDraw drawn = {-1, 0.0f};
            if (u.z < cg.g) {
                if (!caustic_guide_sample(&P->environment, sc->env_texels, sc->env_dist, sc->casters, &cg, u.z / cg.g,
                                          u.xy, &wi, &drawn))
                    break;
                bs.wi = frame_to_local(&frame, wi);
                if (!(bs.wi.z > 0.0f)) break;
                bs.f = bsdf_eval_pdf(m, wo_local, bs.wi, &bs.pdf);
                bs.delta = 0;
            } else {
                u.z = fmin((u.z - cg.g) / (1.0f - cg.g), FC_ONE_MINUS_EPSILON);
                if (!bsdf_sample(m, wo_local, u, &bs)) break;
                wi = frame_to_world(&frame, bs.wi);
            }
            const float pdf_own = bs.pdf; /* the BSDF's own density at wi */
            bs.pdf = caustic_guide_pdf(&P->environment, sc->env_texels, sc->env_dist, sc->casters, P->caster_count, &cg,
                                       bs.pdf, wi, true, &drawn);
            if (!(bs.pdf > 0.0f)) break;
            bs.weight = bs.f * (fabs(bs.wi.z) / bs.pdf);
            rr_scale = roulette_scale_times(rr_scale, roulette_guide_scale(bs.pdf, pdf_own));
        } else {
            if (!path_bsdf_sample(&P->environment, sc->env_texels, sc->env_dist, m, &frame, wo_local, u, &bs)) break;
            wi = frame_to_world(&frame, bs.wi);
        }
        /* The shading frame and the geometric normal must agree on wi's side (a
         * reflection stays on wo's side, a refraction crosses). */
        float side = dot(s.ng, wi);
        if (!(side * bs.wi.z > 0.0f)) break;
        throughput *= bs.weight;
        prev_bsdf_pdf = bs.delta ? INFINITY : bs.pdf;
        /* A refraction (wi below, wo above) from the side of relative index mat.ior. */
        if (bs.wi.z < 0.0f) rr_scale = roulette_scale_times(rr_scale, mat.ior * mat.ior);

        if (depth + 1u >= P->rr_depth) {
            float survive = roulette_survival_l1(throughput, rr_scale, P->roulette_gain);
            if (ub.w >= survive) break;
            throughput /= survive;
        }
        o = surface_offset(&s, side > 0.0f ? s.ng : -s.ng);
        d = wi;
    }
    return radiance;
}

/* Adds sample radiance l, of filter weight filter_weight, to its half's sum (rgb, and in w
 * the count of rejected samples) and second moment. A sample with a NaN, infinite or
 * negative channel is rejected (counted, not added); others are capped at FC_MAX_RADIANCE
 * and, with --clamp, scaled down to its limit on their largest channel (hue kept). */
inline void film_add_sample(float3 l, float filter_weight, float clamp, float4* sum, float* square) {
    if (all_finite(l) && l.x >= 0.0f && l.y >= 0.0f && l.z >= 0.0f) {
        l = fmin(l, (float3)(FC_MAX_RADIANCE));
        float peak = max3(l);
        if (peak > clamp) l *= clamp / peak;
        float3 weighted = filter_weight * l;
        sum->xyz += weighted;
        *square += fmin(dot(weighted, weighted), FC_MAX_SQUARE);
    } else sum->w += 1.0f;
}

/* Adds samples [sample_begin, sample_begin + sample_count) of each pixel of rows
 * [row_begin, row_begin + row_count). The accumulation buffer holds two images:
 * accum[pixel] sums the even-numbered samples, accum[width * height + pixel] the odd
 * ones, so the host can estimate the error from the two independent halves; after them,
 * one float a pixel and half, the sums of each sample's r^2 + g^2 + b^2 (the second
 * moments, from which a half's own variance follows: host/film/film_layout.hpp). */
__kernel void render_pass(FC_SCENE_KERNEL_PARAMS, __global float4* accum) {
    uint gid = get_global_id(0);
    uint x = gid % params->width;
    uint y = params->row_begin + gid / params->width;
    if (gid / params->width >= params->row_count || y >= params->height) return;
    SceneView sc = FC_SCENE_VIEW_INIT;
    uint pixel = y * params->width + x;
    float4 sum[2] = {(float4)(0.0f), (float4)(0.0f)};
    float square[2] = {0.0f, 0.0f};
    for (uint i = 0; i < params->sample_count; ++i) {
        uint index = params->sample_begin + i;
        Sampler sampler = sampler_init(params->sampler, params->seed, pixel, index);
        float3 o, d;
        float filter_weight = pixel_sample_ray(params, x, y, &sampler, &o, &d);
        film_add_sample(path_radiance(&sc, o, d, &sampler), filter_weight, params->clamp, &sum[index & 1u],
                        &square[index & 1u]);
    }
    accum[pixel] += sum[0];
    uint pixels = params->width * params->height;
    accum[pixels + pixel] += sum[1];
    __global float* squares = (__global float*)(accum + 2u * pixels);
    squares[pixel] += square[0];
    squares[pixels + pixel] += square[1];
}

/* Paths in packets of eight, for the programs the host picks them for
 * (host/render/packet_paths.hpp). */
#ifndef FC_PACKET_PATHS
#define FC_PACKET_PATHS 0
#endif
#if FC_PACKET_PATHS
#include "kernels/integrator/packet_paths.cl"
#endif

#endif
