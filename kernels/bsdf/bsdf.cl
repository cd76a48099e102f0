/* A material's BSDF: its diffuse lobe plus its specular lobe.
 *
 * eval returns f(wo, wi) (1/sr, no cosine); pdf the solid-angle density with which
 * sample() produces wi; sample() picks the specular lobe with probability
 * specular_probability(wo) (the lobes' estimated albedos), samples it, and reports
 * the value and density of the whole BSDF (one-sample MIS over the lobes, Veach
 * 1997 section 9.2.4), so weight = f cos / pdf. Directions in the local frame
 * (n = +z), pointing away from the surface; wo below the surface gives 0.
 *
 * A material with metallic M > 0 mixes in a metal lobe, glTF's metallic-roughness BRDF
 * (metallic.cl): f = (1 - M) (diffuse + specular) + M metal; both specular lobes share one
 * sampling density, so the mixture is sampled as one specular lobe chosen with the
 * mixture's weight.
 *
 * A dielectric (FC_SPECULAR_DIELECTRIC) is the whole BSDF: it alone transmits, so wo
 * and wi may lie on either side (dielectric.cl), and any diffuse lobe is ignored.
 *
 * glTF's layers go over the rest of a non-dielectric material, outermost first: the
 * clearcoat (clearcoat.cl), then the sheen (sheen.cl), each weighting what lies below by
 * one minus its own albedo seen from wo,
 *     f = c f_coat + (1 - c E_coat(mu_o)) (f_sheen + (1 - max(S) E_sheen(mu_o)) f_base).
 * sample() chooses the coat with probability p_c = c E_coat(mu_o), the sheen (cosine
 * sampling) with p_s = (1 - p_c) lum(S) E_sheen(mu_o), else the base (both clamped so the
 * base keeps a share), and the pdf is the same mixture. A coat with a normal of its own is
 * evaluated and sampled in its frame (clearcoat.cl). A material without layers takes
 * the base's code path unchanged, bit for bit. */
#ifndef FACET_BSDF_BSDF_CL
#define FACET_BSDF_BSDF_CL

#include "kernels/bsdf/bsdf_sample.cl"
#include "kernels/bsdf/diffuse.cl"
#include "kernels/bsdf/lambert.cl"
#include "kernels/bsdf/metallic.cl"
#include "kernels/bsdf/specular.cl"
#if FC_HAS_DIELECTRIC
#include "kernels/bsdf/dielectric.cl"
#endif
#include "kernels/bsdf/clearcoat.cl"
#include "kernels/bsdf/sheen.cl"

/* Whether the material is a dielectric (transmits; handled by dielectric.cl). */
inline bool bsdf_is_dielectric(const FcMaterial* m) {
#if FC_HAS_DIELECTRIC
    return m->specular_model == FC_SPECULAR_DIELECTRIC;
#else
    return false;
#endif
}

inline float specular_probability(const FcMaterial* m, float3 wo) {
    if (m->specular_model == FC_SPECULAR_NONE) return 0.0f;
    float s = specular_weight(m, wo);
    float d = diffuse_weight(m);
    if (metallic_mixed(m)) { /* the metal's share of the specular choice; the diffuse's is 1 - M */
        FcMaterial metal = metallic_lobe(m);
        float k = metallic_weight(m);
        if (k >= 1.0f) return 1.0f;
        s = mix(s, specular_weight(&metal, wo), k);
        d *= 1.0f - k;
    }
    if (m->diffuse_model == FC_DIFFUSE_NONE) return 1.0f;
    return (s + d > 0.0f) ? clamp(s / (s + d), 0.05f, 0.95f) : 0.5f;
}

/* Whether the two-lobe base is plain: a Lambertian lobe (or Lambert x (1 - F0), or none) under a
 * rough GGX or Beckmann lobe sampled by visible normals, Smith-masked (separable or
 * height-correlated), with the exact dielectric or conductor Fresnel term, and no energy
 * compensation or metallic mix. Such a base is evaluated and sampled by
 * kernels/bsdf/plain_base_lanes.cl, here at W = 1 and in the packet kernel in lanes: the
 * formulas of the general route below (which serves every other base), one source for both
 * widths. */
inline bool bsdf_plain(const FcMaterial* m) {
#if FC_HAS_MICROFACET
    if (m->specular_model != FC_SPECULAR_MICROFACET) return false;
    if (m->diffuse_model != FC_DIFFUSE_LAMBERT && m->diffuse_model != FC_DIFFUSE_LAMBERT_1MF0 &&
        m->diffuse_model != FC_DIFFUSE_NONE)
        return false;
    if (m->ndf == FC_NDF_GGX) {
        if (m->sampling != FC_SAMPLE_VISIBLE) return false;
    } else if (m->ndf != FC_NDF_BECKMANN || m->sampling == FC_SAMPLE_ALL) {
        return false;
    }
    if (m->geometry != FC_G_SMITH_SEPARABLE && m->geometry != FC_G_SMITH_CORRELATED) return false;
    if (m->fresnel != FC_FRESNEL_DIELECTRIC && m->fresnel != FC_FRESNEL_CONDUCTOR && m->fresnel != FC_FRESNEL_SCHLICK &&
        m->fresnel != FC_FRESNEL_SCHLICK_IOR && m->fresnel != FC_FRESNEL_ONE)
        return false;
    return !microfacet_is_mirror(m);
#else
    return false;
#endif
}

/* A plain base's parameters (bsdf_plain), masks as W = 1 lanes (1 or 0); the compensation's
 * constants (energy_compensation.cl) where it is on, else values that keep its arithmetic
 * finite. */
inline PlainBase_l1 plain_base_of(const FcMaterial* m) {
    PlainBase_l1 b;
    const float3 f0 = fresnel_f0(m);
    b.coupled = diffuse_coupled(m);
    b.kd = m->diffuse_model == FC_DIFFUSE_NONE ? (float3)(0.0f) : material_diffuse(m);
    if (m->diffuse_model == FC_DIFFUSE_LAMBERT_1MF0 && !b.coupled) b.kd *= (float3)(1.0f) - f0;
    b.eta = load3p(m->eta);
    b.k = load3p(m->k);
    b.ax = m->alpha_x;
    b.ay = m->alpha_y;
    b.ior = m->ior;
    b.diffuse_weight = diffuse_weight(m);
    b.ggx = m->ndf == FC_NDF_GGX;
    b.beckmann = !b.ggx;
    b.correlated = m->geometry == FC_G_SMITH_CORRELATED;
    b.conductor = m->fresnel == FC_FRESNEL_CONDUCTOR;
    /* Schlick's forms; F = 1 as Schlick's with F0 = F90 = 1 */
    b.schlick =
        m->fresnel == FC_FRESNEL_SCHLICK || m->fresnel == FC_FRESNEL_SCHLICK_IOR || m->fresnel == FC_FRESNEL_ONE;
    b.f0 = m->fresnel == FC_FRESNEL_SCHLICK       ? load3p(m->specular)
           : m->fresnel == FC_FRESNEL_SCHLICK_IOR ? (float3)(f0_from_ior(m->ior))
                                                  : (float3)(1.0f);
    b.f90 = m->fresnel == FC_FRESNEL_SCHLICK ? fresnel_f90(m) : 1.0f;
    b.diffuse = m->diffuse_model != FC_DIFFUSE_NONE;
    b.ec = ec_enabled(m);
    b.e_table = fc_albedo_E;
    b.e5_table = fc_albedo_E5;
    b.ec_r = 0.0f;
    float e_avg = 0.0f;
    b.ec_loss = 1.0f;
    b.ec_fms = (float3)(0.0f);
    b.es_f0 = (float3)(0.0f);
    b.es_f90 = 1.0f;
    b.es_den = (float3)(1.0f);
    if (b.ec) {
        const int ndf = ec_ndf(m);
        b.ec_r = ec_r(m);
        e_avg = ec_lookup_avg(fc_albedo_E_avg, ndf, b.ec_r);
        b.ec_loss = 1.0f - e_avg;
        b.ec_fms = ec_fresnel_ms(m, e_avg);
        b.es_f0 = clamp(f0, 0.0f, 1.0f);
        b.es_f90 = fresnel_f90(m);
        const float3 s_avg =
            ec_specular_albedo_of_l1(b.es_f0, b.es_f90, e_avg, ec_lookup_avg(fc_albedo_E5_avg, ndf, b.ec_r), b.ec_fms);
        b.es_den = fmax((float3)(1.0f) - s_avg, (float3)(1e-6f));
    }
    /* glTF's metallic mix (metallic.cl): the metal lobe's F0 and F_ms, the diffuse lobe's
     * weight times 1 - M (specular_probability's) */
    b.mixed = metallic_mixed(m);
    b.metallic = 0.0f;
    b.metal_f0 = (float3)(0.0f);
    b.metal_fms = (float3)(0.0f);
    if (b.mixed) {
        /* metallic_lobe's F0 (the base colour) and F90 = 1, without copying the material */
        b.metallic = metallic_weight(m);
        b.metal_f0 = clamp(material_diffuse(m), 0.0f, 1.0f);
        if (b.ec) b.metal_fms = ec_fresnel_ms_of(ec_schlick_avg(b.metal_f0, 1.0f), e_avg);
        if (b.metallic < 1.0f) b.diffuse_weight *= 1.0f - b.metallic;
    }
    return b;
}

/* The two-lobe base's f at wi from its specular lobe's own value fs there. */
inline float3 bsdf_base_f(const FcMaterial* m, float3 wo, float3 wi, float3 fs) {
    float3 f = diffuse_eval(m, wo, wi) + fs;
    if (metallic_mixed(m)) {
        FcMaterial metal = metallic_lobe(m);
        f = mix(f, specular_eval(&metal, wo, wi), metallic_weight(m));
    }
    return f;
}

/* The two-lobe base's density of wi from its specular lobe's own density ps there. */
inline float bsdf_base_density(const FcMaterial* m, float3 wo, float3 wi, float ps) {
    float p = specular_probability(m, wo);
    float pdf = 0.0f;
    if (p < 1.0f) pdf += (1.0f - p) * diffuse_pdf(m, wo, wi);
    if (p > 0.0f) pdf += p * ps;
    return pdf;
}

inline float3 bsdf_base_eval(const FcMaterial* m, float3 wo, float3 wi) {
#if FC_HAS_DIELECTRIC
    if (bsdf_is_dielectric(m)) return dielectric_eval(m, wo, wi);
#endif
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    if (bsdf_plain(m)) {
        const PlainBase_l1 b = plain_base_of(m);
        PlainView_l1 v;
        plain_base_view_l1(&b, wo, &v);
        float pdf;
        return plain_base_eval_pdf_l1(&b, &v, wo, wi, &pdf);
    }
    return bsdf_base_f(m, wo, wi, specular_eval(m, wo, wi));
}

inline float bsdf_base_pdf(const FcMaterial* m, float3 wo, float3 wi) {
#if FC_HAS_DIELECTRIC
    if (bsdf_is_dielectric(m)) return dielectric_pdf(m, wo, wi);
#endif
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    if (bsdf_plain(m)) {
        const PlainBase_l1 b = plain_base_of(m);
        PlainView_l1 v;
        plain_base_view_l1(&b, wo, &v);
        float pdf;
        plain_base_eval_pdf_l1(&b, &v, wo, wi, &pdf);
        return pdf;
    }
    return bsdf_base_density(m, wo, wi, specular_pdf(m, wo, wi));
}

/* bsdf_base_eval's value and bsdf_base_pdf's in *pdf at once, each lobe's shared work done
 * once (the same bits as the two calls). */
inline float3 bsdf_base_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
#if FC_HAS_DIELECTRIC
    if (bsdf_is_dielectric(m)) return dielectric_eval_pdf(m, wo, wi, pdf);
#endif
    *pdf = 0.0f;
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    if (bsdf_plain(m)) {
        const PlainBase_l1 b = plain_base_of(m);
        PlainView_l1 v;
        plain_base_view_l1(&b, wo, &v);
        return plain_base_eval_pdf_l1(&b, &v, wo, wi, pdf);
    }
    float ps;
    const float3 fs = specular_eval_pdf(m, wo, wi, &ps);
    *pdf = bsdf_base_density(m, wo, wi, ps);
    return bsdf_base_f(m, wo, wi, fs);
}

/* Whether every lobe of the BSDF is a delta (next-event estimation is useless). */
inline bool bsdf_base_is_delta(const FcMaterial* m) {
#if FC_HAS_DIELECTRIC
    if (bsdf_is_dielectric(m)) return dielectric_is_smooth(m);
#endif
    return m->diffuse_model == FC_DIFFUSE_NONE && specular_is_delta(m);
}

/* A Lambertian lobe alone, cosine-sampled: f = albedo / pi and pdf = cos / pi, so the
 * weight f cos / pdf is the albedo itself, without evaluating the BSDF and its density
 * (finish_sample's general route, which gives the same values to rounding). */
inline bool lambert_only_sample(const FcMaterial* m, float2 u, BsdfSample* s) {
    s->wi = square_to_cosine_hemisphere(u);
    if (s->wi.z <= 0.0f) return false;
    const float3 albedo = material_diffuse(m);
    s->f = albedo * FC_INV_PI;
    s->pdf = s->wi.z * FC_INV_PI;
    s->weight = albedo;
    return all_finite(s->weight);
}

/* u.z chooses the lobe, u.xy sample it. Returns false when no direction was made. */
inline bool bsdf_base_sample(const FcMaterial* m, float3 wo, float3 u, BsdfSample* s) {
    s->delta = 0;
#if FC_HAS_DIELECTRIC
    if (bsdf_is_dielectric(m)) return dielectric_sample(m, wo, u, s);
#endif
    if (wo.z <= 0.0f) return false;
    if (m->diffuse_model == FC_DIFFUSE_LAMBERT && m->specular_model == FC_SPECULAR_NONE)
        return lambert_only_sample(m, u.xy, s);
    if (bsdf_plain(m)) {
        const PlainBase_l1 b = plain_base_of(m);
        PlainView_l1 v;
        plain_base_view_l1(&b, wo, &v);
        return plain_base_sample_l1(&b, &v, wo, u.x, u.y, u.z, &s->wi, &s->f, &s->pdf, &s->weight);
    }
    float p = specular_probability(m, wo);
    const bool specular = u.z < p;
    if (specular) {
        if (!specular_sample(m, wo, u.xy, s)) return false;
        if (s->delta) {
            if (metallic_mixed(m)) { /* the mirror's reflectance, (1 - M) F_dielectric + M F_metal */
                FcMaterial metal = metallic_lobe(m);
                s->weight = mix(s->weight, fresnel_eval(&metal, wo.z), metallic_weight(m));
            }
            s->weight /= p; /* the mirror was chosen with probability p */
            return all_finite(s->weight);
        }
    } else if (!diffuse_sample(m, wo, u.xy, &s->wi)) {
        return false;
    }
    if (s->wi.z <= 0.0f) return false;
    /* the microfacet lobe's sample carries its own f and density at wi (microfacet_eval_pdf's):
     * the base's follow from them */
    if (specular && m->specular_model == FC_SPECULAR_MICROFACET)
        return finish_sample(s, bsdf_base_f(m, wo, s->wi, s->f), bsdf_base_density(m, wo, s->wi, s->pdf));
    float pdf;
    const float3 f = bsdf_base_eval_pdf(m, wo, s->wi, &pdf);
    return finish_sample(s, f, pdf);
}

/* The layers' weights seen from wo: the coat's albedo share c E_coat (x), the sheen's weight
 * over the base 1 - max(S) E_sheen (y), the layer below the coat 1 - c E_coat (z), and the
 * sheen's albedo share lum(S) E_sheen (w). */
inline float4 bsdf_layer_weights(const FcMaterial* m, float3 wo) {
    float4 w = (float4)(0.0f, 1.0f, 1.0f, 0.0f);
    if (clearcoat_present(m)) {
        FcMaterial coat = clearcoat_lobe(m);
        w.x = clearcoat_weight(m) * clearcoat_albedo(&coat, fmax(clearcoat_local(m, wo).z, 0.0f));
        w.z = clamp(1.0f - w.x, 0.0f, 1.0f);
    }
    if (sheen_present(m)) {
        w.y = sheen_below_weight(m, wo.z);
        w.w = luminance(sheen_color(m)) * sheen_albedo(m->sheen_roughness, wo.z);
    }
    return w;
}

/* Whether the material has a clearcoat or sheen layer. */
inline bool bsdf_layered(const FcMaterial* m) {
    if (bsdf_is_dielectric(m)) return false;
    if (clearcoat_present(m)) return true;
    if (sheen_present(m)) return true;
    return false;
}

/* The lobe choice of a layered material: (p_coat, p_sheen), p_base = 1 - both. */
inline float2 bsdf_layer_probabilities(const FcMaterial* m, float4 w) {
    float pc = clearcoat_present(m) ? clamp(w.x, 0.02f, 0.9f) : 0.0f;
    float ps = sheen_present(m) ? (1.0f - pc) * clamp(w.w, 0.02f, 0.9f) : 0.0f;
    return (float2)(pc, ps);
}

/* The layered BSDF's f at wi from the layers' weights w seen from wo and the base's value fb. */
inline float3 bsdf_layered_f(const FcMaterial* m, float3 wo, float3 wi, float4 w, float3 fb) {
    float3 f = fb * w.y;
    if (sheen_present(m)) f += sheen_eval(m, wo, wi);
    f *= w.z;
    if (clearcoat_present(m)) {
        FcMaterial coat = clearcoat_lobe(m);
        f += clearcoat_eval(m, &coat, wo, wi);
    }
    return f;
}

/* The layered BSDF's density of wi from the layers' weights w and the base's density pb. */
inline float bsdf_layered_density(const FcMaterial* m, float3 wo, float3 wi, float4 w, float pb) {
    float2 p = bsdf_layer_probabilities(m, w);
    float pdf = (1.0f - p.x - p.y) * pb;
    if (p.y > 0.0f) pdf += p.y * cosine_hemisphere_pdf(wo, wi);
    if (p.x > 0.0f) {
        FcMaterial coat = clearcoat_lobe(m);
        pdf += p.x * clearcoat_pdf(m, &coat, wo, wi);
    }
    return pdf;
}

inline float3 bsdf_eval(const FcMaterial* m, float3 wo, float3 wi) {
    if (!bsdf_layered(m)) return bsdf_base_eval(m, wo, wi);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    return bsdf_layered_f(m, wo, wi, bsdf_layer_weights(m, wo), bsdf_base_eval(m, wo, wi));
}

inline float bsdf_pdf(const FcMaterial* m, float3 wo, float3 wi) {
    if (!bsdf_layered(m)) return bsdf_base_pdf(m, wo, wi);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    return bsdf_layered_density(m, wo, wi, bsdf_layer_weights(m, wo), bsdf_base_pdf(m, wo, wi));
}

/* bsdf_eval's value and bsdf_pdf's in *pdf at once (the same bits as the two calls), for
 * next-event estimation and a sample's weight, which need both: each lobe's work shared. */
inline float3 bsdf_eval_pdf(const FcMaterial* m, float3 wo, float3 wi, float* pdf) {
    if (!bsdf_layered(m)) return bsdf_base_eval_pdf(m, wo, wi, pdf);
    *pdf = 0.0f;
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    const float4 w = bsdf_layer_weights(m, wo);
    float pb;
    const float3 fb = bsdf_base_eval_pdf(m, wo, wi, &pb);
    *pdf = bsdf_layered_density(m, wo, wi, w, pb);
    return bsdf_layered_f(m, wo, wi, w, fb);
}

/* Whether every lobe of the BSDF is a delta (next-event estimation is useless). */
inline bool bsdf_is_delta(const FcMaterial* m) {
    if (!bsdf_layered(m)) return bsdf_base_is_delta(m);
    if (sheen_present(m)) return false;
    FcMaterial coat = clearcoat_lobe(m);
    return bsdf_base_is_delta(m) && microfacet_is_mirror(&coat);
}

/* u.z chooses the layer (and, rescaled, the base's lobe), u.xy sample it. */
inline bool bsdf_sample(const FcMaterial* m, float3 wo, float3 u, BsdfSample* s) {
    if (!bsdf_layered(m)) return bsdf_base_sample(m, wo, u, s);
    s->delta = 0;
    if (wo.z <= 0.0f) return false;
    float4 w = bsdf_layer_weights(m, wo);
    float2 p = bsdf_layer_probabilities(m, w);
    float pb = 1.0f - p.x - p.y;
    if (u.z < p.x) {
        FcMaterial coat = clearcoat_lobe(m);
        if (!microfacet_sample(&coat, clearcoat_local(m, wo), u.xy, s)) return false;
        s->wi = clearcoat_to_shading(m, s->wi);
        if (s->delta) { /* the coat's mirror: c F(mu_o), chosen with probability p_c */
            s->weight *= clearcoat_weight(m) / p.x;
            return s->wi.z > 0.0f && all_finite(s->weight);
        }
    } else if (u.z < p.x + p.y) {
        s->wi = square_to_cosine_hemisphere(u.xy);
    } else {
        u.z = fmin((u.z - p.x - p.y) / pb, FC_ONE_MINUS_EPSILON);
        if (!bsdf_base_sample(m, wo, u, s)) return false;
        if (s->delta) { /* the base's mirror under the layers */
            s->weight *= w.y * w.z / pb;
            return all_finite(s->weight);
        }
    }
    if (!(s->wi.z > 0.0f)) return false;
    float pdf;
    const float3 f = bsdf_eval_pdf(m, wo, s->wi, &pdf);
    return finish_sample(s, f, pdf);
}

#endif
