/* Lane-generic body (kernels/lanes/lanes.cl): the plain two-lobe base of bsdf.cl, evaluated
 * and sampled in lanes. "Plain" (bsdf_plain, bsdf.cl) is a Lambertian lobe (albedo kd: the
 * diffuse colour, times 1 - F0 for Lambert x (1 - F0)), or none, under a rough microfacet lobe
 * of GGX or Beckmann normals, sampled as visible normals, with Smith's separable or
 * height-correlated masking and the exact Fresnel term of a dielectric (index ior) or a
 * conductor (eta + i k per channel), or Schlick's (F0, F90). A lobe with height-correlated
 * masking may be energy-compensated (energy_compensation.cl: the cosine lobe f_ms, sampled with
 * probability 1 - E(wo), an anisotropic lobe's E read at the roughness seen from each
 * direction, and a Lambert x (1 - F0) base coupled to the lobe's albedo E_s instead of 1 - F0). glTF's metallic mix
 * (metallic.cl) mixes in a metal lobe: the same microfacet lobe with Schlick's F from the base colour, F90 = 1, and its
 * own F_ms. No layers, and no mirror (alpha >= FC_ALPHA_MIRROR). The formulas are microfacet.cl's,
 * energy_compensation.cl's, metallic.cl's and bsdf.cl's
 * (one-sample MIS over the lobes, chosen by their estimated albedos); the scalar kernels run
 * this body at W = 1 for such materials, the packet kernel at W = 8 or 16, so both give the
 * same bits (tests/lanes_test.cpp). Needs vec3_lanes.cl, warp_lanes.cl, fresnel_lanes.cl,
 * ggx_lanes.cl, beckmann_lanes.cl and energy_compensation_lanes.cl of the same width. */
#ifndef FACET_BSDF_PLAIN_BASE_LANES_PASS
#define FACET_BSDF_PLAIN_BASE_LANES_PASS

/* A plain base per lane. ggx and beckmann are lane masks of the lanes of each NDF (a lane of
 * neither is not evaluated: its results are meaningless), correlated the lanes of
 * height-correlated masking (else separable), conductor those of the conductor's Fresnel term
 * and schlick those of Schlick's (f0, f90; else the dielectric's), diffuse those with a diffuse
 * lobe (else kd = 0); diffuse_weight is bsdf.cl's estimate of the diffuse lobe's albedo
 * (lum(kd') >= 0). The lanes of ec are energy-compensated, with the material's constants:
 * ec_r the tables' roughness coordinate, ec_loss 1 - E_avg, ec_fms F_ms, es_f0 and es_f90 the
 * F0 (clamped) and F90 of the lobe's albedo E_s, es_den max(1 - E_s,avg, 1e-6); coupled those
 * whose diffuse lobe is coupled to E_s (kd then the diffuse colour itself). The lanes of mixed
 * mix in a metal lobe of weight metallic in (0, 1] (diffuse_weight then already times 1 -
 * metallic), Schlick's F0 metal_f0 and F90 = 1, and F_ms metal_fms where compensated. The
 * albedo tables E and E5 (albedo_tables_*.cl) are passed in e_table and e5_table. */
typedef struct {
    LVEC3 kd, eta, k, f0, ec_fms, es_f0, es_den, metal_f0, metal_fms;
    LFLOAT ax, ay, ior, diffuse_weight, f90, ec_r, ec_loss, es_f90, metallic;
    LINT ggx, beckmann, correlated, conductor, schlick, diffuse, ec, coupled, mixed;
    __constant const float* e_table;
    __constant const float* e5_table;
} LNAME(PlainBase);

/* The Fresnel term at cosine c: the dielectric's in every channel, the conductor's or
 * Schlick's. */
inline LVEC3 LNAME(plain_base_fresnel)(const LNAME(PlainBase) * b, LFLOAT c) {
    const LFLOAT fd = LNAME(fresnel_dielectric)(c, b->ior);
    LVEC3 f = LNAME(vec3)(fd, fd, fd);
    if (LNAME(lanes_any)(b->conductor)) {
        const LVEC3 fc = LNAME(vec3)(LNAME(fresnel_conductor_channel)(c, b->eta.x, b->k.x),
                                     LNAME(fresnel_conductor_channel)(c, b->eta.y, b->k.y),
                                     LNAME(fresnel_conductor_channel)(c, b->eta.z, b->k.z));
        f = LNAME(vec3_select)(f, fc, b->conductor);
    }
    if (LNAME(lanes_any)(b->schlick)) {
        const LVEC3 fs = LNAME(vec3)(LNAME(fresnel_schlick_channel)(b->f0.x, b->f90, c),
                                     LNAME(fresnel_schlick_channel)(b->f0.y, b->f90, c),
                                     LNAME(fresnel_schlick_channel)(b->f0.z, b->f90, c));
        f = LNAME(vec3_select)(f, fs, b->schlick);
    }
    return f;
}

/* The mixed lanes' metal lobe's Fresnel term at cosine c: Schlick's from metal_f0, F90 = 1. */
inline LVEC3 LNAME(plain_base_metal_fresnel)(const LNAME(PlainBase) * b, LFLOAT c) {
    return LNAME(vec3)(LNAME(fresnel_schlick_channel)(b->metal_f0.x, 1.0f, c),
                       LNAME(fresnel_schlick_channel)(b->metal_f0.y, 1.0f, c),
                       LNAME(fresnel_schlick_channel)(b->metal_f0.z, 1.0f, c));
}

/* The compensated lanes' albedos E and E5 at cosine mu (the tables' cell found once). */
inline void LNAME(plain_base_albedos)(const LNAME(PlainBase) * b, LFLOAT mu, LFLOAT* e, LFLOAT* e5) {
    LINT at;
    LFLOAT tx, ty;
    LNAME(ec_cell)(select((LINT)(0), (LINT)(1), b->ggx), mu, b->ec_r, &at, &tx, &ty);
    *e = LNAME(ec_table_at)(b->e_table, at, tx, ty);
    *e5 = LNAME(ec_table_at)(b->e5_table, at, tx, ty);
}

/* The coupled diffuse base's share seen from a direction of albedos e, e5: 1 - E_s, at 0 at
 * least. */
inline LVEC3 LNAME(plain_base_share)(const LNAME(PlainBase) * b, LFLOAT e, LFLOAT e5) {
    return LNAME(ec_diffuse_share)(LNAME(ec_specular_albedo_of)(b->es_f0, b->es_f90, e, e5, b->ec_fms));
}

/* The probability of choosing the specular lobe from wo (bsdf.cl's specular_probability):
 * the lobes' estimated albedos, lum(F(wo.z)) against diffuse_weight, clamped to [0.05, 0.95];
 * 1 without a diffuse lobe. */
inline LFLOAT LNAME(plain_base_specular_probability)(const LNAME(PlainBase) * b, LFLOAT wo_z) {
    const LVEC3 f = LNAME(plain_base_fresnel)(b, wo_z);
    LFLOAT s = fmax(0.2126f * f.x + 0.7152f * f.y + 0.0722f * f.z, 0.0f);
    LFLOAT p1 = select((LFLOAT)(1.0f), (LFLOAT)(0.0f), b->diffuse); /* 1: no diffuse lobe */
    if (LNAME(lanes_any)(b->mixed)) {
        /* the metal's share of the specular choice (the diffuse's 1 - M is in diffuse_weight);
         * a metal of weight 1 alone */
        const LVEC3 fm = LNAME(plain_base_metal_fresnel)(b, wo_z);
        const LFLOAT sm = fmax(0.2126f * fm.x + 0.7152f * fm.y + 0.0722f * fm.z, 0.0f);
        s = select(s, mix(s, sm, b->metallic), b->mixed);
        p1 = select(p1, (LFLOAT)(1.0f), b->mixed & (b->metallic >= 1.0f));
    }
    const LFLOAT sum = s + b->diffuse_weight;
    const LFLOAT p = select((LFLOAT)(0.5f), clamp(s / sum, 0.05f, 0.95f), sum > 0.0f);
    return select(p, (LFLOAT)(1.0f), p1 > 0.0f);
}

/* The microfacet lobe's projected area seen from w, GGX's or Beckmann's per lane. */
inline LFLOAT LNAME(plain_base_area)(const LNAME(PlainBase) * b, LVEC3 w) {
    LFLOAT a = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ggx)) a = LNAME(ggx_projected_area)(b->ax, b->ay, w);
    if (LNAME(lanes_any)(b->beckmann)) a = select(a, LNAME(beckmann_projected_area)(b->ax, b->ay, w), b->beckmann);
    return a;
}

/* What a plain base's evaluation and sampling share for one wo: the projected area of the
 * microsurface seen from wo, wo.z (1 + Lambda(wo)), and the specular lobe's probability; for
 * the compensated lanes E(wo) at the roughness seen from wo (ec_r_dir: an anisotropic lobe's
 * leans on the azimuth), the probability p_ms of sampling f_ms within the specular lobe, 1 -
 * E(wo) in [0, 1] (0 elsewhere), and the coupled diffuse base's share seen from wo (from E and
 * E5 at the lobe's mean roughness, as energy_compensation.cl reads them). */
typedef struct {
    LFLOAT area_o, p, e_o, p_ms;
    LVEC3 share_o;
} LNAME(PlainView);

/* The compensated lanes' E at cosine w.z and the roughness seen from w, where the lobe is
 * anisotropic; e, E at the mean roughness, elsewhere. */
inline LFLOAT LNAME(plain_base_e_dir)(const LNAME(PlainBase) * b, LVEC3 w, LFLOAT e) {
    const LINT aniso = b->ec & (b->ax != b->ay);
    if (!LNAME(lanes_any)(aniso)) return e;
    LINT at;
    LFLOAT tx, ty;
    LNAME(ec_cell)
    (select((LINT)(0), (LINT)(1), b->ggx), w.z, LNAME(ec_r_dir)(fmax(b->ax, 0.0f), fmax(b->ay, 0.0f), w, b->ec_r), &at,
     &tx, &ty);
    return select(e, LNAME(ec_table_at)(b->e_table, at, tx, ty), aniso);
}

inline void LNAME(plain_base_view)(const LNAME(PlainBase) * b, LVEC3 wo, LNAME(PlainView) * v) {
    v->area_o = LNAME(plain_base_area)(b, wo);
    v->p = LNAME(plain_base_specular_probability)(b, wo.z);
    v->e_o = (LFLOAT)(1.0f);
    v->p_ms = (LFLOAT)(0.0f);
    v->share_o = LNAME(vec3)(0.0f, 0.0f, 0.0f);
    if (LNAME(lanes_any)(b->ec)) {
        LFLOAT e, e5;
        LNAME(plain_base_albedos)(b, wo.z, &e, &e5);
        v->share_o = LNAME(plain_base_share)(b, e, e5);
        v->e_o = LNAME(plain_base_e_dir)(b, wo, e);
        v->p_ms = select((LFLOAT)(0.0f), clamp(1.0f - v->e_o, 0.0f, 1.0f), b->ec);
    }
}

/* One microfacet lobe's f (no cosine) from its Fresnel term fr at the half vector and dg = D G
 * / (4 cos_o cos_i): fr dg where ss (D > 0, a half vector, both directions above), plus f_ms =
 * fms ms on the compensated lanes, where D may be 0 (ok: a half vector, both above); 0 where
 * not finite, at 0 at least (microfacet_eval_at's checks). */
inline LVEC3 LNAME(plain_base_lobe)(const LNAME(PlainBase) * b, LVEC3 fr, LFLOAT dg, LVEC3 fms, LFLOAT ms, LINT ss,
                                    LINT ok) {
    LVEC3 f = LNAME(vec3)(fr.x * dg, fr.y * dg, fr.z * dg);
    if (LNAME(lanes_any)(b->ec)) {
        const LVEC3 fss = LNAME(vec3_select)(LNAME(vec3)(0.0f, 0.0f, 0.0f), f, ss);
        f = LNAME(vec3_select)(f, LNAME(vec3)(fms.x * ms + fss.x, fms.y * ms + fss.y, fms.z * ms + fss.z), b->ec);
    }
    const LINT fok = isfinite(f.x) & isfinite(f.y) & isfinite(f.z) & select(ss, ok, b->ec);
    return LNAME(vec3_select)(LNAME(vec3)(0.0f, 0.0f, 0.0f),
                              LNAME(vec3)(fmax(f.x, 0.0f), fmax(f.y, 0.0f), fmax(f.z, 0.0f)), fok);
}

/* f(wo, wi) (1/sr) and, in *pdf, the density with which plain_base_sample draws wi; 0 for both
 * where wo or wi is at or below the surface. The microfacet lobe: D G F / (4 cos_o cos_i) at
 * the half vector, its density D / (4 wo.z (1 + Lambda(wo))) (visible normals, microfacet.cl),
 * 0 for a degenerate half vector and where D is 0; compensated, f_ms added and its cosine
 * density mixed in with p_ms. A mixed lane's f is mix(f, f_metal, M), at the same density. */
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
    const LFLOAT dg = d * g_over;
    LFLOAT ps = d / (4.0f * area_o);
    ps = select((LFLOAT)(0.0f), fmax(ps, 0.0f), isfinite(ps) & hv);
    const LFLOAT cos_pdf = LNAME(cosine_hemisphere_pdf)(wo.z, wi.z);
    const LINT ok = hv & above, ss = (d > 0.0f) & ok;
    LVEC3 kd = b->kd;
    LFLOAT ms = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ec)) {
        /* f_ms's factor (1 - E(wo)) (1 - E(wi)) / (pi (1 - E_avg)), the lobe sampled by the
         * cosine with probability p_ms, and the coupled base's albedo kd (1 - E_s(wo)) (1 -
         * E_s(wi)) / (1 - E_s,avg) */
        LFLOAT e_i, e5_i;
        LNAME(plain_base_albedos)(b, wi.z, &e_i, &e5_i);
        ms = select((LFLOAT)(0.0f), LNAME(ec_ms_factor)(view->e_o, LNAME(plain_base_e_dir)(b, wi, e_i), b->ec_loss),
                    b->ec & (b->ec_loss > 1e-6f));
        const LFLOAT q = view->p_ms * cos_pdf + (1.0f - view->p_ms) * ps;
        ps = select(ps, select((LFLOAT)(0.0f), fmax(q, 0.0f), isfinite(q)), b->ec);
        const LVEC3 share_i = LNAME(plain_base_share)(b, e_i, e5_i);
        const LVEC3 c =
            LNAME(vec3)(view->share_o.x * share_i.x / b->es_den.x, view->share_o.y * share_i.y / b->es_den.y,
                        view->share_o.z * share_i.z / b->es_den.z);
        kd = LNAME(vec3_select)(kd, LNAME(vec3)(kd.x * c.x, kd.y * c.y, kd.z * c.z), b->coupled);
    }
    const LVEC3 fs = LNAME(plain_base_lobe)(b, LNAME(plain_base_fresnel)(b, wo_h), dg, b->ec_fms, ms, ss, ok);
    /* the lobes mixed: f = kd / pi + fs, pdf = (1 - p) cos_i / pi + p ps */
    const LFLOAT p = view->p;
    *pdf = select((LFLOAT)(0.0f), (1.0f - p) * cos_pdf + p * ps, above);
    const LFLOAT k = select((LFLOAT)(0.0f), (LFLOAT)(FC_INV_PI), above);
    LVEC3 f = LNAME(vec3)(kd.x * k + fs.x, kd.y * k + fs.y, kd.z * k + fs.z);
    if (LNAME(lanes_any)(b->mixed)) {
        /* glTF's mix, f = mix(f, f_metal, M): the metal's lobe is this one with its own F and
         * F_ms, so it has the same density */
        const LVEC3 fm =
            LNAME(plain_base_lobe)(b, LNAME(plain_base_metal_fresnel)(b, wo_h), dg, b->metal_fms, ms, ss, ok);
        const LFLOAT m = b->metallic;
        f = LNAME(vec3_select)(f, LNAME(vec3)(mix(f.x, fm.x, m), mix(f.y, fm.y, m), mix(f.z, fm.z, m)), b->mixed);
    }
    return f;
}

/* A direction wi for wo from u0, u1 (the lobe's sample) and u2 (the lobe's choice), uniform in
 * [0, 1): the lane mask of lanes that made one, with f and pdf at wi (plain_base_eval_pdf's)
 * in *f and *pdf and f cos_i / pdf in *weight. */
inline LINT LNAME(plain_base_sample)(const LNAME(PlainBase) * b, const LNAME(PlainView) * view, LVEC3 wo, LFLOAT u0,
                                     LFLOAT u1, LFLOAT u2, LVEC3* wi, LVEC3* f, LFLOAT* pdf, LVEC3* weight) {
    const LINT specular = u2 < view->p;
    /* the diffuse lobe, and a compensated lobe's f_ms (chosen by u0 below p_ms, rescaled): a
     * cosine-weighted direction */
    const LINT ms = specular & (u0 < view->p_ms);
    LVEC3 w = LNAME(square_to_cosine_hemisphere)(select(u0, u0 / view->p_ms, ms), u1);
    LINT ok = (wo.z > 0.0f) & (w.z > 0.0f);
    const LINT ss = specular & (u0 >= view->p_ms);
    if (LNAME(lanes_any)(ss)) {
        /* the microfacet lobe: a visible normal, wo reflected about it (Walter 2007, eq. 39),
         * u0 rescaled past p_ms where the lobe is compensated */
        u0 = select(u0, fmin((u0 - view->p_ms) / (1.0f - view->p_ms), FC_ONE_MINUS_EPSILON), b->ec);
        LVEC3 m = LNAME(vec3)(0.0f, 0.0f, 1.0f);
        const LINT sg = ss & b->ggx, sb = ss & b->beckmann;
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
        w = LNAME(vec3_select)(w, rn, ss);
        ok = select(ok, rok, ss);
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
