/* Lane-generic body (kernels/lanes/lanes.cl): the plain two-lobe base of bsdf.cl, evaluated
 * and sampled in lanes. "Plain" (bsdf_plain, bsdf.cl) is a Lambertian lobe (albedo kd: the
 * diffuse colour, times 1 - F0 for Lambert x (1 - F0)), or none, under a rough microfacet lobe
 * of GGX or Beckmann normals, sampled as visible normals, with Smith's separable or
 * height-correlated masking and the exact Fresnel term of a dielectric (index ior) or a
 * conductor (eta + i k per channel); no energy compensation, metallic mix or layers, and no
 * mirror (alpha >= FC_ALPHA_MIRROR). The formulas are microfacet.cl's and bsdf.cl's
 * (one-sample MIS over the lobes, chosen by their estimated albedos); the scalar kernels run
 * this body at W = 1 for such materials, the packet kernel at W = 8 or 16, so both give the
 * same bits (tests/lanes_test.cpp). Needs vec3_lanes.cl, warp_lanes.cl, fresnel_lanes.cl, ggx_lanes.cl
 * and beckmann_lanes.cl of the same width. */
#ifndef FACET_BSDF_PLAIN_BASE_LANES_PASS
#define FACET_BSDF_PLAIN_BASE_LANES_PASS

/* A plain base per lane. ggx and beckmann are lane masks of the lanes of each NDF (a lane of
 * neither is not evaluated: its results are meaningless), correlated the lanes of
 * height-correlated masking (else separable), conductor those of the conductor's Fresnel term
 * (else the dielectric's), diffuse those with a diffuse lobe (else kd = 0); diffuse_weight is
 * bsdf.cl's estimate of the diffuse lobe's albedo (lum(kd') >= 0). */
typedef struct {
    LVEC3 kd, eta, k;
    LFLOAT ax, ay, ior, diffuse_weight;
    LINT ggx, beckmann, correlated, conductor, diffuse;
} LNAME(PlainBase);

/* The Fresnel term at cosine c: the dielectric's in every channel, or the conductor's. */
inline LVEC3 LNAME(plain_base_fresnel)(const LNAME(PlainBase) * b, LFLOAT c) {
    const LFLOAT fd = LNAME(fresnel_dielectric)(c, b->ior);
    LVEC3 f = LNAME(vec3)(fd, fd, fd);
    if (LNAME(lanes_any)(b->conductor)) {
        const LVEC3 fc = LNAME(vec3)(LNAME(fresnel_conductor_channel)(c, b->eta.x, b->k.x),
                                     LNAME(fresnel_conductor_channel)(c, b->eta.y, b->k.y),
                                     LNAME(fresnel_conductor_channel)(c, b->eta.z, b->k.z));
        f = LNAME(vec3_select)(f, fc, b->conductor);
    }
    return f;
}

/* The probability of choosing the specular lobe from wo (bsdf.cl's specular_probability):
 * the lobes' estimated albedos, lum(F(wo.z)) against diffuse_weight, clamped to [0.05, 0.95];
 * 1 without a diffuse lobe. */
inline LFLOAT LNAME(plain_base_specular_probability)(const LNAME(PlainBase) * b, LFLOAT wo_z) {
    const LVEC3 f = LNAME(plain_base_fresnel)(b, wo_z);
    const LFLOAT s = fmax(0.2126f * f.x + 0.7152f * f.y + 0.0722f * f.z, 0.0f);
    const LFLOAT sum = s + b->diffuse_weight;
    const LFLOAT p = select((LFLOAT)(0.5f), clamp(s / sum, 0.05f, 0.95f), sum > 0.0f);
    return select((LFLOAT)(1.0f), p, b->diffuse);
}

/* The microfacet lobe's projected area seen from w, GGX's or Beckmann's per lane. */
inline LFLOAT LNAME(plain_base_area)(const LNAME(PlainBase) * b, LVEC3 w) {
    LFLOAT a = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ggx)) a = LNAME(ggx_projected_area)(b->ax, b->ay, w);
    if (LNAME(lanes_any)(b->beckmann)) a = select(a, LNAME(beckmann_projected_area)(b->ax, b->ay, w), b->beckmann);
    return a;
}

/* What a plain base's evaluation and sampling share for one wo: the projected area of the
 * microsurface seen from wo, wo.z (1 + Lambda(wo)), and the specular lobe's probability. */
typedef struct {
    LFLOAT area_o, p;
} LNAME(PlainView);

inline void LNAME(plain_base_view)(const LNAME(PlainBase) * b, LVEC3 wo, LNAME(PlainView) * v) {
    v->area_o = LNAME(plain_base_area)(b, wo);
    v->p = LNAME(plain_base_specular_probability)(b, wo.z);
}

/* f(wo, wi) (1/sr) and, in *pdf, the density with which plain_base_sample draws wi; 0 for both
 * where wo or wi is at or below the surface. The microfacet lobe: D G F / (4 cos_o cos_i) at
 * the half vector, its density D / (4 wo.z (1 + Lambda(wo))) (visible normals, microfacet.cl),
 * 0 for a degenerate half vector and where D is 0. */
inline LVEC3 LNAME(plain_base_eval_pdf)(const LNAME(PlainBase) * b, const LNAME(PlainView) * view, LVEC3 wo, LVEC3 wi,
                                        LFLOAT* pdf) {
    const LINT above = (wo.z > 0.0f) & (wi.z > 0.0f);
    /* the half vector and wo.h = |wo + wi| / 2 */
    const LVEC3 v = LNAME(vec3_add)(wo, wi);
    const LFLOAT len = sqrt(LNAME(vec3_dot)(v, v));
    const LINT hv = above & (len > 0.0f) & isfinite(len);
    const LVEC3 h = LNAME(vec3)(v.x / len, v.y / len, v.z / len);
    LFLOAT d = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ggx)) d = LNAME(ggx_D)(b->ax, b->ay, h);
    if (LNAME(lanes_any)(b->beckmann)) d = select(d, LNAME(beckmann_D)(b->ax, b->ay, h), b->beckmann);
    const LFLOAT area_o = view->area_o;
    const LFLOAT area_i = LNAME(plain_base_area)(b, wi);
    /* Smith's G: the facet seen from both sides (chi+), then separable or height-correlated */
    const LFLOAT wo_h = LNAME(vec3_dot)(wo, h), wi_h = LNAME(vec3_dot)(wi, h);
    const LINT front = (wo_h > 0.0f) & (wi_h > 0.0f);
    const LFLOAT g_sep = wo.z / area_o * (wi.z / area_i);
    const LFLOAT g_cor = 1.0f / (area_o / wo.z + area_i / wi.z - 1.0f);
    const LFLOAT g = select((LFLOAT)(0.0f), select(g_sep, g_cor, b->correlated), front);
    const LFLOAT g_over = g / (4.0f * wo.z * wi.z);
    const LVEC3 fr = LNAME(plain_base_fresnel)(b, wo_h);
    const LFLOAT dg = d * g_over;
    LVEC3 fs = LNAME(vec3)(fr.x * dg, fr.y * dg, fr.z * dg);
    const LINT fok = isfinite(fs.x) & isfinite(fs.y) & isfinite(fs.z) & (d > 0.0f) & hv & above;
    fs = LNAME(vec3_select)(LNAME(vec3)(0.0f, 0.0f, 0.0f),
                            LNAME(vec3)(fmax(fs.x, 0.0f), fmax(fs.y, 0.0f), fmax(fs.z, 0.0f)), fok);
    LFLOAT ps = d / (4.0f * area_o);
    ps = select((LFLOAT)(0.0f), fmax(ps, 0.0f), isfinite(ps) & hv);
    /* the lobes mixed: f = kd / pi + fs, pdf = (1 - p) cos_i / pi + p ps */
    const LFLOAT p = view->p;
    *pdf = select((LFLOAT)(0.0f), (1.0f - p) * LNAME(cosine_hemisphere_pdf)(wo.z, wi.z) + p * ps, above);
    const LFLOAT k = select((LFLOAT)(0.0f), (LFLOAT)(FC_INV_PI), above);
    return LNAME(vec3)(b->kd.x * k + fs.x, b->kd.y * k + fs.y, b->kd.z * k + fs.z);
}

/* A direction wi for wo from u0, u1 (the lobe's sample) and u2 (the lobe's choice), uniform in
 * [0, 1): the lane mask of lanes that made one, with f and pdf at wi (plain_base_eval_pdf's)
 * in *f and *pdf and f cos_i / pdf in *weight. */
inline LINT LNAME(plain_base_sample)(const LNAME(PlainBase) * b, const LNAME(PlainView) * view, LVEC3 wo, LFLOAT u0,
                                     LFLOAT u1, LFLOAT u2, LVEC3* wi, LVEC3* f, LFLOAT* pdf, LVEC3* weight) {
    const LINT specular = u2 < view->p;
    /* the diffuse lobe: a cosine-weighted direction */
    LVEC3 w = LNAME(square_to_cosine_hemisphere)(u0, u1);
    LINT ok = (wo.z > 0.0f) & (w.z > 0.0f);
    if (LNAME(lanes_any)(specular)) {
        /* the microfacet lobe: a visible normal, wo reflected about it (Walter 2007, eq. 39) */
        LVEC3 m = LNAME(vec3)(0.0f, 0.0f, 1.0f);
        const LINT sg = specular & b->ggx, sb = specular & b->beckmann;
        if (LNAME(lanes_any)(sg)) m = LNAME(ggx_sample_visible)(b->ax, b->ay, wo, u0, u1);
        if (LNAME(lanes_any)(sb))
            m = LNAME(vec3_select)(m, LNAME(beckmann_sample_visible)(b->ax, b->ay, wo, u0, u1), sb);
        const LFLOAT wo_m = LNAME(vec3_dot)(wo, m);
        const LVEC3 r = LNAME(vec3_sub)(LNAME(vec3_scale)(m, 2.0f * wo_m), wo);
        const LFLOAT len2 = LNAME(vec3_dot)(r, r);
        const LINT unit = (len2 > 0.0f) & isfinite(len2);
        const LFLOAT il = rsqrt(len2);
        const LVEC3 rn = LNAME(vec3)(r.x * il, r.y * il, r.z * il);
        const LINT rok = (wo.z > 0.0f) & (wo_m > 0.0f) & unit & (rn.z > 0.0f);
        w = LNAME(vec3_select)(w, rn, specular);
        ok = select(ok, rok, specular);
    }
    *wi = w;
    LFLOAT q;
    const LVEC3 v = LNAME(plain_base_eval_pdf)(b, view, wo, w, &q);
    const LFLOAT c = fabs(w.z) / q;
    const LVEC3 g = LNAME(vec3)(v.x * c, v.y * c, v.z * c);
    ok &= (q > 0.0f) & isfinite(q) & isfinite(g.x) & isfinite(g.y) & isfinite(g.z);
    *f = v;
    *pdf = q;
    *weight = g;
    return ok;
}

#undef FACET_BSDF_PLAIN_BASE_LANES_PASS
#endif
