/* Lane-generic body (kernels/lanes/lanes.cl): the rough dielectric of kernels/bsdf/dielectric.cl
 * (Walter et al. 2007), whose formulas, sources and numerical policy are given there: a pair of
 * directions and its half vector, the lobes' Fresnel factors and their choice, the BSDF and the
 * density from the NDF's values at the half vector, and the direction scattered about a sampled
 * normal. dielectric.cl's scalar functions are these at W = 1, with any NDF of ndf.cl; here the
 * whole evaluation and sample are also composed for GGX and Beckmann visible normals
 * (rough_dielectric_eval_pdf, rough_dielectric_sample), which the packet paths run in lanes
 * (kernels/integrator/packet_paths.cl): the same operations in the same order as the scalar
 * route, so the same bits (tests/lanes_test.cpp). Needs vec3_lanes.cl, fresnel_lanes.cl,
 * refraction_lanes.cl, ggx_lanes.cl and beckmann_lanes.cl of the same width. */
#ifndef FACET_BSDF_DIELECTRIC_LANES_PASS
#define FACET_BSDF_DIELECTRIC_LANES_PASS

/* The smallest probability the widened choice gives a lobe that carries light
 * (dielectric_choice, dielectric.cl). */
#ifndef FC_DIELECTRIC_MIN_CHOICE
#define FC_DIELECTRIC_MIN_CHOICE 0.25f
#endif

/* A rough dielectric per lane: roughness ax, ay, index ior (below over above), the refraction's
 * tint (the material's transmittance); the lanes of GGX and of Beckmann normals (a lane of
 * neither is not evaluated), of height-correlated masking (else separable), of the widened
 * choice (FC_MAT_WIDE_CHOICE), and the energy-compensated ones, whose f is divided by ec_e, the
 * single-scattering albedo seen from wo (energy_compensation.cl's ec_dielectric_albedo); and
 * area_o, the microsurface's projected area seen from wo turned up (ndf.cl's
 * ndf_projected_area), found once for the vertex's evaluation and sample. */
typedef struct {
    LVEC3 tint;
    LFLOAT ax, ay, ior, ec_e, area_o;
    LINT ggx, beckmann, correlated, wide, ec;
} LNAME(RoughDielectric);

/* A pair of directions wo, wi (either side): in ok whether it scatters (wo.z and wi.z not 0,
 * a half vector, neither direction on the back of it), in reflect whether both lie on one side;
 * etap = n_i / n_o (1 for a reflection), len = |wo + etap wi|, the (generalised) half vector h
 * turned to +z, oh = wo.h, ih = wi.h, and fl, the Fresnel factor of the pair's lobe: F(oh) for
 * a reflection, for a refraction 1 - F from the pair's two cosines (well conditioned near the
 * critical angle, and reciprocal); in refract the lanes on two sides. A lane that does not
 * scatter holds meaningless values. Each lobe's formulas below run where some lane takes it (at
 * W = 1, the one lobe the pair takes). */
typedef struct {
    LVEC3 h;
    LFLOAT etap, len, oh, ih, fl;
    LINT ok, reflect, refract;
} LNAME(DielectricPair);

inline void LNAME(dielectric_pair)(LFLOAT ior, LVEC3 wo, LVEC3 wi, LNAME(DielectricPair) * p) {
    const LFLOAT co = wo.z, ci = wi.z;
    const LINT reflect = co * ci > 0.0f, refract = co * ci <= 0.0f;
    const LFLOAT etap = select(LNAME(relative_eta)(ior, co), (LFLOAT)(1.0f), reflect);
    const LVEC3 v = LNAME(vec3)(wo.x + etap * wi.x, wo.y + etap * wi.y, wo.z + etap * wi.z);
    const LFLOAT len = sqrt(LNAME(vec3_dot)(v, v));
    LVEC3 h = LNAME(vec3)(v.x / len, v.y / len, v.z / len);
    h = LNAME(vec3_select)(h, LNAME(vec3_neg)(h), h.z < 0.0f);
    const LFLOAT oh = LNAME(vec3_dot)(wo, h), ih = LNAME(vec3_dot)(wi, h);
    p->ok = (fabs(co) > 0.0f) & (fabs(ci) > 0.0f) & (len > 0.0f) & isfinite(len) & (ih * ci > 0.0f) & (oh * co > 0.0f);
    p->reflect = reflect;
    p->refract = refract;
    p->etap = etap;
    p->len = len;
    p->h = h;
    p->oh = oh;
    p->ih = ih;
    LFLOAT fl = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(refract)) fl = LNAME(fresnel_dielectric_transmittance)(fabs(oh), fabs(ih), etap);
    if (LNAME(lanes_any)(reflect)) fl = select(fl, LNAME(fresnel_dielectric)(oh, ior), reflect);
    p->fl = fl;
}

/* The probability of choosing the lobe whose Fresnel factor is fl: fl itself, or on the wide
 * lanes fl moved toward [FC_DIELECTRIC_MIN_CHOICE, 1 - FC_DIELECTRIC_MIN_CHOICE] by at most a
 * factor of 4 either way (dielectric.cl's dielectric_choice). */
inline LFLOAT LNAME(dielectric_choice)(LINT wide, LFLOAT fl) {
    fl = clamp(fl, 0.0f, 1.0f);
    const LFLOAT q =
        clamp(fl, fmin(FC_DIELECTRIC_MIN_CHOICE, 4.0f * fl), 1.0f - fmin(FC_DIELECTRIC_MIN_CHOICE, 4.0f * (1.0f - fl)));
    return select(fl, q, wide);
}

/* w turned to the +z side. */
inline LVEC3 LNAME(dielectric_upper)(LVEC3 w) { return LNAME(vec3_select)(w, LNAME(vec3_neg)(w), w.z < 0.0f); }

/* The density of the visible normal h seen from wo turned up, where D(h) = d and the projected
 * area seen from there is area_o: d max(0, wo.h) / area_o. */
inline LFLOAT LNAME(dielectric_visible_pdf_h)(LVEC3 wo, LVEC3 h, LFLOAT d, LFLOAT area_o) {
    return d * fmax(LNAME(vec3_dot)(LNAME(dielectric_upper)(wo), h), 0.0f) / area_o;
}

/* The density of wi for the pair p, its lobe chosen with probability q and its half vector of
 * density pdf_h: q pdf_h / (4 |oh|) for the reflection, q pdf_h etap^2 |ih| / len^2 for the
 * refraction (Walter 2007, eqs. 14 and 17); 0 where not finite or the pair does not scatter. */
inline LFLOAT LNAME(dielectric_pdf_at)(const LNAME(DielectricPair) * p, LFLOAT q, LFLOAT pdf_h) {
    LFLOAT pdf = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(p->reflect)) pdf = q * pdf_h / (4.0f * fabs(p->oh));
    if (LNAME(lanes_any)(p->refract))
        pdf = select(pdf, q * pdf_h * (p->etap * p->etap) * fabs(p->ih) / (p->len * p->len), p->refract);
    return select((LFLOAT)(0.0f), fmax(pdf, 0.0f), isfinite(pdf) & p->ok);
}

/* The BSDF of the pair p where D(h) = d, from the microsurface's projected areas seen from wo
 * and wi turned up (b->area_o, area_i; 1 + Lambda(w) = area / |w.z|): Smith's G of both sides,
 * separable or height-correlated; D G F / (4 |cos_o| |cos_i|) for the reflection (eq. 20), eq.
 * 21 times the radiance scaling 1 / etap^2 and the tint for the refraction; divided by ec_e on
 * the compensated lanes (Turquin 2019's albedo scaling, energy_compensation.cl); 0 where d is
 * not positive, where not finite and where the pair does not scatter, at 0 at least. */
inline LVEC3 LNAME(dielectric_eval_at)(const LNAME(RoughDielectric) * b, LVEC3 wo, LVEC3 wi,
                                       const LNAME(DielectricPair) * p, LFLOAT d, LFLOAT area_i) {
    const LFLOAT lo = b->area_o / fabs(wo.z), li = area_i / fabs(wi.z);
    const LFLOAT g = 1.0f / select(lo * li, lo + li - 1.0f, b->correlated);
    LVEC3 f = LNAME(vec3)(0.0f, 0.0f, 0.0f);
    if (LNAME(lanes_any)(p->reflect)) {
        const LFLOAT fr = d * g * p->fl / (4.0f * fabs(wo.z) * fabs(wi.z));
        f = LNAME(vec3)(fr, fr, fr);
    }
    if (LNAME(lanes_any)(p->refract)) {
        /* eq. 21 as the BTDF of importance (pbrt-v4's Importance mode), (1 - F) D G |wi.h| |wo.h|
         * etap^2 / (|cos_i| |cos_o| |wo + etap wi|^2), |wo + etap wi| = |n_i wi.h + n_o wo.h| /
         * n_o, times the radiance scaling 1 / etap^2 */
        const LFLOAT importance =
            p->fl * d * g * fabs(p->ih * p->oh) / (fabs(wi.z) * fabs(wo.z)) * (p->etap * p->etap) / (p->len * p->len);
        const LFLOAT ft = importance / (p->etap * p->etap);
        f = LNAME(vec3_select)(f, LNAME(vec3)(b->tint.x * ft, b->tint.y * ft, b->tint.z * ft), p->refract);
    }
    if (LNAME(lanes_any)(b->ec))
        f = LNAME(vec3_select)(f, LNAME(vec3)(f.x / b->ec_e, f.y / b->ec_e, f.z / b->ec_e), b->ec);
    const LINT fok = p->ok & (d > 0.0f) & isfinite(f.x) & isfinite(f.y) & isfinite(f.z);
    return LNAME(vec3_select)(LNAME(vec3)(0.0f, 0.0f, 0.0f),
                              LNAME(vec3)(fmax(f.x, 0.0f), fmax(f.y, 0.0f), fmax(f.z, 0.0f)), fok);
}

/* The direction scattered from wo about the microfacet normal h (h.z > 0) in *wi: wo reflected
 * (Walter 2007, eq. 39) where u is below the choice of reflection (dielectric_choice of F(wo.h)),
 * else refracted (eq. 40). The mask of lanes whose direction leaves on its lobe's side (a
 * reflection on wo's, a refraction across). */
inline LINT LNAME(dielectric_scatter)(LFLOAT ior, LINT wide, LVEC3 wo, LVEC3 h, LFLOAT u, LVEC3* wi) {
    const LFLOAT oh = LNAME(vec3_dot)(wo, h);
    const LFLOAT q = LNAME(dielectric_choice)(wide, LNAME(fresnel_dielectric)(oh, ior));
    const LINT reflect = u < q;
    const LFLOAT k = 2.0f * oh;
    LVEC3 w = LNAME(vec3)(k * h.x - wo.x, k * h.y - wo.y, k * h.z - wo.z);
    LINT ok = reflect & (w.z * wo.z > 0.0f);
    const LINT refract = u >= q;
    if (LNAME(lanes_any)(refract)) {
        LVEC3 t;
        const LINT tok = LNAME(refract_about)(wo, h, ior, &t) & (t.z * wo.z < 0.0f);
        w = LNAME(vec3_select)(w, t, refract);
        ok = select(ok, tok, refract);
    }
    *wi = w;
    return ok;
}

/* D(h), GGX's or Beckmann's per lane. */
inline LFLOAT LNAME(rough_dielectric_D)(const LNAME(RoughDielectric) * b, LVEC3 h) {
    LFLOAT d = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ggx)) d = LNAME(ggx_D)(b->ax, b->ay, h);
    if (LNAME(lanes_any)(b->beckmann)) d = select(d, LNAME(beckmann_D)(b->ax, b->ay, h), b->beckmann);
    return d;
}

/* The projected area seen from w turned up, GGX's or Beckmann's per lane. */
inline LFLOAT LNAME(rough_dielectric_area)(const LNAME(RoughDielectric) * b, LVEC3 w) {
    const LVEC3 wu = LNAME(dielectric_upper)(w);
    LFLOAT a = (LFLOAT)(0.0f);
    if (LNAME(lanes_any)(b->ggx)) a = LNAME(ggx_projected_area)(b->ax, b->ay, wu);
    if (LNAME(lanes_any)(b->beckmann)) a = select(a, LNAME(beckmann_projected_area)(b->ax, b->ay, wu), b->beckmann);
    return a;
}

/* f(wo, wi) and, in *pdf, the density with which rough_dielectric_sample draws wi (visible
 * normals): dielectric.cl's dielectric_eval_pdf; b->area_o seen from this wo. */
inline LVEC3 LNAME(rough_dielectric_eval_pdf)(const LNAME(RoughDielectric) * b, LVEC3 wo, LVEC3 wi, LFLOAT* pdf) {
    LNAME(DielectricPair) p;
    LNAME(dielectric_pair)(b->ior, wo, wi, &p);
    const LFLOAT d = LNAME(rough_dielectric_D)(b, p.h);
    *pdf = LNAME(dielectric_pdf_at)(&p, LNAME(dielectric_choice)(b->wide, p.fl),
                                    LNAME(dielectric_visible_pdf_h)(wo, p.h, d, b->area_o));
    return LNAME(dielectric_eval_at)(b, wo, wi, &p, d, LNAME(rough_dielectric_area)(b, wi));
}

/* A direction wi for wo (either side) from u0, u1 (a visible normal seen from wo turned up) and
 * u2 (the lobe's choice): the mask of lanes that made one, with f and pdf at wi
 * (rough_dielectric_eval_pdf's) in *f and *pdf and f |cos_i| / pdf in *weight (dielectric.cl's
 * dielectric_sample for a rough interface). */
inline LINT LNAME(rough_dielectric_sample)(const LNAME(RoughDielectric) * b, LVEC3 wo, LFLOAT u0, LFLOAT u1, LFLOAT u2,
                                           LVEC3* wi, LVEC3* f, LFLOAT* pdf, LVEC3* weight) {
    const LVEC3 wv = LNAME(dielectric_upper)(wo);
    LVEC3 h = LNAME(vec3)(0.0f, 0.0f, 1.0f);
    if (LNAME(lanes_any)(b->ggx)) h = LNAME(ggx_sample_visible)(b->ax, b->ay, wv, u0, u1);
    if (LNAME(lanes_any)(b->beckmann))
        h = LNAME(vec3_select)(h, LNAME(beckmann_sample_visible)(b->ax, b->ay, wv, u0, u1), b->beckmann);
    LINT ok = (fabs(wo.z) > 0.0f) & LNAME(dielectric_scatter)(b->ior, b->wide, wo, h, u2, wi);
    LFLOAT q;
    const LVEC3 v = LNAME(rough_dielectric_eval_pdf)(b, wo, *wi, &q);
    const LFLOAT c = fabs(wi->z) / q;
    const LVEC3 g = LNAME(vec3)(v.x * c, v.y * c, v.z * c);
    ok &= (q > 0.0f) & isfinite(q) & isfinite(g.x) & isfinite(g.y) & isfinite(g.z);
    *f = v;
    *pdf = q;
    *weight = g;
    return ok;
}

#undef FACET_BSDF_DIELECTRIC_LANES_PASS
#endif
