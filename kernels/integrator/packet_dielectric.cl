/* The packet paths' rough dielectrics (issue 29): the parameters of the lanes whose BSDF is a
 * rough dielectric of GGX or Beckmann visible normals (dielectric.cl's rough_dielectric_in_lanes
 * and rough_dielectric_of), stored lane by lane at each vertex and loaded in lanes for
 * kernels/bsdf/dielectric_lanes.cl. Included by kernels/integrator/packet_paths.cl inside its
 * lanes (FC_LW = FC_PACKET_W), after its lane helpers (l3_load, set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_DIELECTRIC_CL
#define FACET_INTEGRATOR_PACKET_DIELECTRIC_CL

#if FC_PACKET_BSDF_PER_LANE && FC_HAS_DIELECTRIC
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
#endif

#endif
