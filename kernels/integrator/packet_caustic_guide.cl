/* The packet paths' sampling toward glass (kernels/integrator/caustic_guide.cl): the mixtures of
 * the Lambertian lanes, their density at the light samples' directions, and their directions
 * drawn, per lane by caustic_guide.cl's functions, as path_radiance draws them. Included by
 * kernels/integrator/packet_paths.cl inside its lanes (FC_LW = FC_PACKET_W) in programs with
 * dielectrics, after its lane helpers (l3, l3_load, l3_store, lane3, set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_CAUSTIC_GUIDE_CL
#define FACET_INTEGRATOR_PACKET_CAUSTIC_GUIDE_CL

/* the casters' cones in the packets' lanes */
#include "kernels/integrator/caustic_cones_lanes.cl"

/* Each live lane's mixture in cgs, set in the lanes it guides only (gen: whether the lane's BSDF
 * is more than a Lambertian lobe, mats: the lanes' materials; PP: the points; N: the frames'
 * normals), the casters' cones tested in lanes (caustic_cones); returns the lanes it guides, in
 * *own those of them whose BSDF is their own (glossy: caustic_guide_receiver), and in
 * cone_bits each lane's casters that count (0 where not guided). */
inline uint packet_caustic_guides(const SceneView* sc, LINT live, const int* gen, const FcMaterial* mats, L3 PP, L3 N,
                                  CausticGuide* cgs, uint* own, uint* cone_bits) {
    __constant const FcRenderParams* P = sc->params;
    uint guided = 0u;
    *own = 0u;
    for (int j = 0; j < FC_PACKET_W; ++j) cone_bits[j] = 0u;
    if (P->caster_count == 0u) return 0u;
    LUINT bits, lens_bits;
    const LFLOAT total =
        LNAME(caustic_cones)(sc->casters, P->caster_count, caustic_guide_lenses_draw(P), PP, N, &bits, &lens_bits);
    float pa[3 * FC_PACKET_W], nn[3 * FC_PACKET_W], ta[FC_PACKET_W];
    uint ba[FC_PACKET_W], la_bits[FC_PACKET_W];
    int la[FC_PACKET_W];
    LSTORE(live & (total > 0.0f), la);
    LSTORE(total, ta);
    LSTORE(bits, ba);
    LSTORE(lens_bits, la_bits);
    l3_store(PP, pa);
    l3_store(N, nn);
    for (int j = 0; j < FC_PACKET_W; ++j) {
        if (!la[j]) continue;
        const float share = gen[j] ? caustic_guide_receiver(&mats[j]) : 1.0f;
        if (!(share > 0.0f)) continue;
        const CausticGuide c = caustic_guide_of_cones(P->caster_fraction * share, caustic_guide_glint(share), ta[j],
                                                      ba[j], la_bits[j], lane3(pa, j), lane3(nn, j));
        if (!(c.g > 0.0f)) continue;
        cgs[j] = c;
        cone_bits[j] = ba[j];
        guided |= 1u << j;
        if (gen[j]) *own |= 1u << j;
    }
    return guided;
}

/* The BSDF's choice u2 of the lanes in `own` whose BSDF samples (u2 at or past g), rescaled to
 * [0, 1) past the guide's share (path_radiance's). */
inline LFLOAT packet_guided_bsdf_u(uint own, const CausticGuide* cgs, LFLOAT u2) {
    float u[FC_PACKET_W];
    LSTORE(u2, u);
    for (uint rest = own; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        const float g = cgs[j].g;
        if (u[j] >= g) u[j] = fmin((u[j] - g) / (1.0f - g), FC_ONE_MINUS_EPSILON);
    }
    return LLOAD(u);
}

/* The guided lanes' density of the light samples' directions wi: the mixture's, from the
 * BSDF's bsdf_pdf_l (the lens guide's share left out for lights at infinity), the cones that
 * hold wi tested in lanes (PP: the points, cone_bits: packet_caustic_guides's). */
inline LFLOAT packet_guided_light_pdf(const SceneView* sc, uint guided, const CausticGuide* cgs, const uint* cone_bits,
                                      L3 PP, uint at_infinity, LFLOAT bsdf_pdf_l, L3 wi) {
    __constant const FcRenderParams* P = sc->params;
    LUINT inside;
    const LUINT held = LNAME(caustic_cones_holding)(sc->casters, P->caster_count, LLOAD(cone_bits), PP, wi, &inside);
    float pdf_b[FC_PACKET_W], wia[3 * FC_PACKET_W];
    uint ha[FC_PACKET_W], ia[FC_PACKET_W];
    LSTORE(bsdf_pdf_l, pdf_b);
    LSTORE(held, ha);
    LSTORE(inside, ia);
    l3_store(wi, wia);
    for (uint rest = guided; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        const CausticGuide* c = &cgs[j];
        pdf_b[j] =
            caustic_guide_mix(c, pdf_b[j],
                              caustic_guide_density_held(&P->environment, sc->env_texels, sc->env_dist, sc->casters, c,
                                                         lane3(wia, j), !((at_infinity >> j) & 1u), 0, ha[j], ia[j]));
    }
    return LLOAD(pdf_b);
}

/* The BSDF sample's state of a packet's lanes, spilled to arrays for the guided lanes' per-lane
 * draws: the sample's numbers, the direction, weight and density, whether the path goes on. */
typedef struct {
    float u0[FC_PACKET_W], u1[FC_PACKET_W], u2[FC_PACKET_W];
    float wi[3 * FC_PACKET_W], w[3 * FC_PACKET_W], pdf[FC_PACKET_W];
    int go[FC_PACKET_W];
} GuidedLanes;

inline void guided_lanes_load(GuidedLanes* g, const LFLOAT* ub, L3 nwi, L3 A, LFLOAT next_pdf, LINT cont) {
    LSTORE(ub[0], g->u0);
    LSTORE(ub[1], g->u1);
    LSTORE(ub[2], g->u2);
    l3_store(nwi, g->wi);
    l3_store(A, g->w);
    LSTORE(next_pdf, g->pdf);
    LSTORE(cont, g->go);
}

inline void guided_lanes_store(const GuidedLanes* g, L3* nwi, L3* A, LFLOAT* next_pdf, LINT* cont) {
    *nwi = l3_load(g->wi);
    *A = l3_load(g->w);
    *next_pdf = LLOAD(g->pdf);
    *cont = LLOAD(g->go);
}

/* The guided lanes' directions (path_radiance's): ub[2] picks the guide or the cosine lobe
 * (whose direction *nwi already holds); the weight albedo cos / (pi density of the mixture) in
 * *A, the density in *next_pdf, whether the path goes on in *cont, roulette's scale times the
 * mixture's density over the cosine lobe's in rr_scale. The guide draws per lane, then the
 * cones holding each lane's direction are tested in lanes (PP: the points, cone_bits:
 * packet_caustic_guides's), then the mixture's density is made per lane. */
inline void packet_guided_directions(const SceneView* sc, uint guided, const CausticGuide* cgs, const uint* cone_bits,
                                     const LFLOAT* ub, LFLOAT wo_z, L3 PP, L3 N, L3 NG, const float* alb, L3* nwi,
                                     L3* A, LFLOAT* next_pdf, LINT* cont, float* rr_scale) {
    __constant const FcRenderParams* P = sc->params;
    GuidedLanes g;
    guided_lanes_load(&g, ub, *nwi, *A, *next_pdf, *cont);
    float nn[3 * FC_PACKET_W], nga[3 * FC_PACKET_W], woz[FC_PACKET_W];
    LSTORE(wo_z, woz);
    l3_store(N, nn);
    l3_store(NG, nga);
    GuideDraw drawn[FC_PACKET_W];
    uint bits[FC_PACKET_W];
    for (int j = 0; j < FC_PACKET_W; ++j) bits[j] = 0u;
    for (uint rest = guided; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        const CausticGuide* cg = &cgs[j];
        drawn[j].lens = -1;
        drawn[j].density = 0.0f;
        if (g.u2[j] < cg->g) {
            /* toward glass: the direction must be above both normals, wo above the shading one */
            float3 wg;
            g.go[j] = 0;
            if (!(woz[j] > 0.0f) ||
                !caustic_guide_sample(&P->environment, sc->env_texels, sc->env_dist, sc->casters, cg, g.u2[j] / cg->g,
                                      (float2)(g.u0[j], g.u1[j]), &wg, &drawn[j]) ||
                !(dot(wg, lane3(nn, j)) > 0.0f) || !(dot(lane3(nga, j), wg) > 0.0f))
                continue;
            g.go[j] = -1;
            set_lane3(g.wi, j, wg);
        }
        if (g.go[j]) bits[j] = cone_bits[j];
    }
    LUINT inside;
    const LUINT held =
        LNAME(caustic_cones_holding)(sc->casters, P->caster_count, LLOAD(bits), PP, l3_load(g.wi), &inside);
    uint ha[FC_PACKET_W], ia[FC_PACKET_W];
    LSTORE(held, ha);
    LSTORE(inside, ia);
    for (uint rest = guided; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        if (!g.go[j]) continue;
        const CausticGuide* cg = &cgs[j];
        const float3 wg = lane3(g.wi, j);
        const float cos_i = dot(wg, lane3(nn, j));
        const float pdf_own = cos_i * FC_INV_PI;
        const float pdf =
            caustic_guide_mix(cg, pdf_own,
                              caustic_guide_density_held(&P->environment, sc->env_texels, sc->env_dist, sc->casters, cg,
                                                         wg, true, &drawn[j], ha[j], ia[j]));
        if (!(pdf > 0.0f)) {
            g.go[j] = 0;
            continue;
        }
        set_lane3(g.w, j, lane3(alb, j) * (FC_INV_PI * cos_i / pdf));
        g.pdf[j] = pdf;
        rr_scale[j] = roulette_scale_times(rr_scale[j], roulette_guide_scale(pdf, pdf_own));
    }
    guided_lanes_store(&g, nwi, A, next_pdf, cont);
}

/* The glossy guided lanes' directions (path_radiance's), after their plain bases sampled the
 * BSDF with packet_guided_bsdf_u's choice: where ub[2] picks the guide, its direction, f and
 * the BSDF's density there (bsdf_eval_pdf, per lane, in the lane's frame fs, ft, ns); else the
 * BSDF's sample (its f in pf, cos in pcos, density in *next_pdf). The weight f cos / (density
 * of the mixture) in *A, that density in *next_pdf, whether the path goes on in *cont,
 * roulette's scale times the mixture's density over the BSDF's in rr_scale. */
inline void packet_guided_own_directions(const SceneView* sc, uint own, const CausticGuide* cgs, const LFLOAT* ub,
                                         const FcMaterial* mats, const float* wol, const float* fs, const float* ft,
                                         const float* ns, const float* ng, L3 pf, LFLOAT pcos, L3* nwi, L3* A,
                                         LFLOAT* next_pdf, LINT* cont, float* rr_scale) {
    __constant const FcRenderParams* P = sc->params;
    GuidedLanes g;
    guided_lanes_load(&g, ub, *nwi, *A, *next_pdf, *cont);
    float fa[3 * FC_PACKET_W], ca[FC_PACKET_W];
    l3_store(pf, fa);
    LSTORE(pcos, ca);
    for (uint rest = own; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        const CausticGuide* cg = &cgs[j];
        float3 wg = lane3(g.wi, j), f = lane3(fa, j);
        float cos_l = ca[j], pdf_b = g.pdf[j];
        GuideDraw drawn = {-1, 0.0f};
        if (g.u2[j] < cg->g) {
            g.go[j] = 0;
            if (!caustic_guide_sample(&P->environment, sc->env_texels, sc->env_dist, sc->casters, cg, g.u2[j] / cg->g,
                                      (float2)(g.u0[j], g.u1[j]), &wg, &drawn))
                continue;
            const Frame fr = {lane3(fs, j), lane3(ft, j), lane3(ns, j)};
            const float3 wl = frame_to_local(&fr, wg);
            if (!(wl.z > 0.0f)) continue;
            f = bsdf_eval_pdf(&mats[j], lane3(wol, j), wl, &pdf_b);
            cos_l = wl.z;
            /* the shading frame and the geometric normal agree on wi's side */
            if (!(dot(lane3(ng, j), wg) * wl.z > 0.0f)) continue;
            g.go[j] = -1;
        }
        if (!g.go[j]) continue;
        const float pdf = caustic_guide_pdf(&P->environment, sc->env_texels, sc->env_dist, sc->casters, P->caster_count,
                                            cg, pdf_b, wg, true, &drawn);
        if (!(pdf > 0.0f)) {
            g.go[j] = 0;
            continue;
        }
        set_lane3(g.wi, j, wg);
        set_lane3(g.w, j, f * (fabs(cos_l) / pdf));
        g.pdf[j] = pdf;
        rr_scale[j] = roulette_scale_times(rr_scale[j], roulette_guide_scale(pdf, pdf_b));
    }
    guided_lanes_store(&g, nwi, A, next_pdf, cont);
}

#endif
