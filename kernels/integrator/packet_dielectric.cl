/* The packet paths' rough dielectrics (issue 29): the parameters of the lanes whose BSDF is a
 * rough dielectric of GGX or Beckmann visible normals (dielectric.cl's rough_dielectric_in_lanes
 * and rough_dielectric_of), stored lane by lane at each vertex and loaded in lanes for
 * kernels/bsdf/dielectric_lanes.cl, and their evaluation and sample merged into the packet's
 * (packet_bsdf_merge.cl). Included by kernels/integrator/packet_paths.cl inside its lanes
 * (FC_LW = FC_PACKET_W), after its lane helpers (l3, l3_load, set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_DIELECTRIC_CL
#define FACET_INTEGRATOR_PACKET_DIELECTRIC_CL

#if FC_PACKET_BSDF_PER_LANE && FC_HAS_DIELECTRIC
/* the fewest lanes with a rough dielectric that evaluate and sample it in lanes: fewer are
 * cheaper one by one (glass_metal_sky at 16 lanes: 2.72 s with 1, 2.65 with 3, 2.63 with 4,
 * 2.64 with 7; at 8, 3.04 with 1, 2.99 with 2; docs/performance.md) */
#ifndef FC_PACKET_ROUGH_MIN
#define FC_PACKET_ROUGH_MIN (FC_PACKET_W / 4)
#endif
/* The lanes' rough-dielectric parameters (lane j at [j], the tint as the lane arrays; the masks
 * stored as -1 or 0). */
typedef struct {
    float tint[3 * FC_PACKET_W], ax[FC_PACKET_W], ay[FC_PACKET_W], ior[FC_PACKET_W], ec_e[FC_PACKET_W];
    int ggx[FC_PACKET_W], beckmann[FC_PACKET_W], cor[FC_PACKET_W], wide[FC_PACKET_W], ec[FC_PACKET_W];
} PacketRough;

/* Lane j's parameters from a rough dielectric's. */
inline void packet_rough_set(PacketRough* q, int j, const RoughDielectric_l1* b) {
    set_lane3(q->tint, j, b->tint);
    q->ax[j] = b->ax;
    q->ay[j] = b->ay;
    q->ior[j] = b->ior;
    q->ec_e[j] = b->ec_e;
    q->ggx[j] = b->ggx ? -1 : 0;
    q->beckmann[j] = b->beckmann ? -1 : 0;
    q->cor[j] = b->correlated ? -1 : 0;
    q->wide[j] = b->wide ? -1 : 0;
    q->ec[j] = b->ec ? -1 : 0;
}

/* Parameters every lane can evaluate, for a lane before its first rough dielectric: a clear
 * GGX interface of alpha 1 and index 1.5, no compensation (read, never used). */
inline void packet_rough_clear(PacketRough* q, int j) {
    RoughDielectric_l1 b;
    b.tint = (float3)(1.0f);
    b.ax = b.ay = b.ec_e = b.area_o = 1.0f;
    b.ior = 1.5f;
    b.ggx = b.beckmann = b.correlated = b.wide = b.ec = 0;
    packet_rough_set(q, j, &b);
}

/* The rough dielectrics of the lanes `lanes` seen from wo (the others' parameters are read, not
 * used): the projected area seen from wo made in lanes. */
inline void packet_rough(LINT lanes, const PacketRough* q, L3 wo, LNAME(RoughDielectric) * b) {
    b->tint = l3_load(q->tint);
    b->ax = LLOAD(q->ax);
    b->ay = LLOAD(q->ay);
    b->ior = LLOAD(q->ior);
    b->ec_e = LLOAD(q->ec_e);
    b->ggx = lanes & LLOAD(q->ggx);
    b->beckmann = lanes & LLOAD(q->beckmann);
    b->correlated = LLOAD(q->cor);
    b->wide = LLOAD(q->wide);
    b->ec = lanes & LLOAD(q->ec);
    b->area_o = LNAME(rough_dielectric_area)(b, wo);
}

/* Whether lane j's material m (wo local to its frame) is a rough dielectric of the lanes
 * (rough_dielectric_in_lanes); its parameters then in lane j of q. */
inline int packet_rough_at(PacketRough* q, int j, const FcMaterial* m, float3 wo) {
    if (!rough_dielectric_in_lanes(m)) return 0;
    const RoughDielectric_l1 b = rough_dielectric_of(m, wo);
    packet_rough_set(q, j, &b);
    return 1;
}

/* The lanes of G whose BSDF is a rough dielectric (rough[j]), with their parameters seen from wo
 * in *b, where FC_PACKET_ROUGH_MIN lanes or more have one; else none (0, *b not set): those
 * few are cheaper evaluated and sampled one by one. */
inline LINT packet_rough_lanes(LINT G, const int* rough, const PacketRough* q, L3 wo, LNAME(RoughDielectric) * b) {
    const LINT lanes = G & (LLOAD(rough) != 0);
    int at[FC_PACKET_W], count = 0;
    LSTORE(lanes, at);
    for (int j = 0; j < FC_PACKET_W; ++j) count += at[j] != 0;
    if (count < FC_PACKET_ROUGH_MIN) return (LINT)(0);
    packet_rough(lanes, q, wo, b);
    return lanes;
}

/* The rough dielectrics' f and density at the light's direction wi (local) on the lanes `lanes`
 * (bsdf_eval_pdf's, per lane), merged into the light sample's *ok, *F and *pdf. */
inline void packet_rough_eval(const LNAME(RoughDielectric) * b, LINT lanes, bool mis, L3 wo, L3 wi, LINT* ok, L3* F,
                              LFLOAT* pdf) {
    if (!LNAME(lanes_any)(lanes)) return;
    LFLOAT p;
    const L3 f = LNAME(rough_dielectric_eval_pdf)(b, wo, wi, &p);
    packet_bsdf_merge_eval(lanes, f, p, mis, ok, F, pdf);
}

/* The rough dielectrics' samples on the lanes `lanes` (path_bsdf_sample's, per lane; u the
 * BSDF's numbers, wo local to the frame S, T, N, NG the geometric normal): the next ray's
 * direction, *cont, *next_pdf and its weight in *A, a refraction's origin on the far side (*so
 * from orgb) and roulette's scale times eta^2 (rr_scale, with the lanes' materials mats). */
inline void packet_rough_sample(const LNAME(RoughDielectric) * b, LINT lanes, L3 wo, const LFLOAT* u, L3 S, L3 T, L3 N,
                                L3 NG, const float* orgb, const FcMaterial* mats, float* rr_scale, L3* nwi, LINT* cont,
                                LFLOAT* next_pdf, L3* A, L3* so) {
    L3 wl, fl, wt;
    LFLOAT pl, side;
    const LINT ok = LNAME(rough_dielectric_sample)(b, wo, u[0], u[1], u[2], &wl, &fl, &pl, &wt);
    const LINT kept = packet_bsdf_merge_sample(lanes, ok, wl, pl, wt, S, T, N, NG, nwi, cont, next_pdf, A, &side);
    *so = LNAME(vec3_select)(*so, l3_load(orgb), kept & (side < 0.0f));
    int across[FC_PACKET_W];
    LSTORE(kept & (wl.z < 0.0f), across);
    for (int j = 0; j < FC_PACKET_W; ++j)
        if (across[j]) rr_scale[j] = roulette_scale_times(rr_scale[j], mats[j].ior * mats[j].ior);
}
#endif

#endif
