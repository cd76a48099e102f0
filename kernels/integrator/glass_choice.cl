/* Glass's choice toward the light: where a smooth glass surface seen from outside mirrors a
 * bright part of the environment (the sun), its reflection is chosen more often.
 *
 * A smooth dielectric samples one of its two delta lobes, reflection with probability q and
 * refraction with 1 - q, weights F / q and (1 - F) / (1 - q) (kernels/bsdf/dielectric.cl); q
 * may be any function of the vertex and wo in (0, 1) and the estimate stays unbiased. With q =
 * F, or F widened toward [0.25, 0.75] (dielectric_choice), the sun's glint on a glass ball is
 * found by a few of the camera samples that meet the ball there, each carrying 1/4 to all of
 * the sun's radiance times F: a sub-pixel highlight that is nearly all of its pixels' variance
 * on glass_metal_sky, and the glints a rough metal sees on a ball (its lens guide aims there,
 * caustic_guide.cl) go the same way. Here, before the choice, the mirror direction's
 * brightness relative to the environment's mean, rho = 4 pi p_env(w_r) (the environment's
 * sampling density there, which integrates to 1 over the sphere), weighs the reflection's
 * expected share of the light, F rho / (F rho + 1 - F), the refraction's taken at the mean;
 * reflection is chosen with that probability where it exceeds dielectric_choice's, at most
 * FC_GLASS_LIGHT_CHOICE_MAX (rho read only where its row's bound could raise the choice:
 * env_row_pdf_bound). Under a uniform environment rho is 1 and the share is F: nothing
 * changes. From inside the ball the mirror direction stays inside, and the choice is
 * dielectric_choice's. Only for materials whose choice is widened (FC_MAT_WIDE_CHOICE, scenes
 * whose light is not uniform), smooth (the delta lobes have no density to evaluate, so MIS
 * is untouched) and not layered, in programs with an environment. docs/sampling.md, "Glass's
 * own choice of reflection or refraction". */
#ifndef FACET_INTEGRATOR_GLASS_CHOICE_CL
#define FACET_INTEGRATOR_GLASS_CHOICE_CL

#include "kernels/bsdf/bsdf.cl"
#include "kernels/lights/environment.cl"
#include "kernels/util/frame.cl"

/* The most often reflection is chosen toward the light (the refraction's weight then at most
 * ten times its share). */
#ifndef FC_GLASS_LIGHT_CHOICE_MAX
#define FC_GLASS_LIGHT_CHOICE_MAX 0.9f
#endif

#if FC_HAS_DIELECTRIC && FC_HAS_ENVIRONMENT
/* Whether the path samples material m by glass_light_sample. */
inline bool glass_light_choice(const FcMaterial* m) {
    return bsdf_is_dielectric(m) && !bsdf_layered(m) && dielectric_is_smooth(m) && (m->flags & FC_MAT_WIDE_CHOICE);
}

/* The probability of reflection at a smooth dielectric of Fresnel factor fr seen from wo (local
 * to frame f): dielectric_choice's, raised toward the reflection's share of the light. */
inline float glass_light_q(__constant const FcEnvironment* env, __global const float4* texels,
                           __global const float* dist, const FcMaterial* m, const Frame* f, float3 wo, float fr) {
    const float q = dielectric_choice(m, fr);
    if (!(wo.z > 0.0f) || !(fr > 0.0f) || !(q < FC_GLASS_LIGHT_CHOICE_MAX)) return q;
    const float3 wr = frame_to_world(f, (float3)(-wo.x, -wo.y, wo.z));
    float rho;
    if (env->enabled && env->width > 0 && env->filter != FC_ENV_FILTER_BILINEAR) {
        /* a nearest lookup's density (env_pdf's), unless its row's bound already leaves the share
         * below q (with a margin of 0.1 %, far above the share's rounding): then q, as the
         * density would give, without the read of the texel's column */
        float sin_theta;
        float2 uv;
        const int2 t = env_locate(env, wr, &sin_theta, &uv);
        const float bound = 4.0f * FC_PI * env_row_pdf_bound(env, dist, t.y, sin_theta);
        if (fr * bound / (fr * bound + (1.0f - fr)) < 0.999f * q) return q;
        rho = 4.0f * FC_PI * env_texel_pdf(env, dist, t, sin_theta);
    } else {
        rho = 4.0f * FC_PI * env_pdf(env, texels, dist, wr);
    }
    const float share = fr * rho / (fr * rho + (1.0f - fr));
    return share > q ? fmin(share, FC_GLASS_LIGHT_CHOICE_MAX) : q;
}

/* A sample of a smooth dielectric (glass_light_choice) with glass_light_q's choice, u its
 * number (dielectric_sample's, but for the choice). */
inline bool glass_light_sample(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, const FcMaterial* m, const Frame* f, float3 wo, float u,
                               BsdfSample* s) {
    s->delta = 0;
    if (!(fabs(wo.z) > 0.0f)) return false;
    const float fr = fresnel_dielectric(wo.z, m->ior);
    return dielectric_sample_smooth_by(m, wo, u, fr, glass_light_q(env, texels, dist, m, f, wo, fr), s);
}

#endif

/* The path's sample of material m at a vertex of frame f: bsdf_sample's, glass toward the
 * light by glass_light_sample. */
inline bool path_bsdf_sample(__constant const FcEnvironment* env, __global const float4* texels,
                             __global const float* dist, const FcMaterial* m, const Frame* f, float3 wo, float3 u,
                             BsdfSample* s) {
#if FC_HAS_DIELECTRIC && FC_HAS_ENVIRONMENT
    if (glass_light_choice(m)) return glass_light_sample(env, texels, dist, m, f, wo, u.z, s);
#else
    (void)env;
    (void)texels;
    (void)dist;
    (void)f;
#endif
    return bsdf_sample(m, wo, u, s);
}

#endif
