/* The packet paths' plain bases (issue 29): the parameters of the lanes whose BSDF is a plain
 * base (bsdf.cl's plain_base_of), stored lane by lane and loaded in lanes for
 * kernels/bsdf/plain_base_lanes.cl. Included by kernels/integrator/packet_paths.cl inside its
 * lanes (FC_LW = FC_PACKET_W), after its lane helpers (l3, l3_load, l3_store, lane3,
 * set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_PLAIN_CL
#define FACET_INTEGRATOR_PACKET_PLAIN_CL

#if FC_PACKET_BSDF_PER_LANE
/* The lanes' plain-base parameters (bsdf.cl's plain_base_of, lane j at [j], 3-vectors as the
 * lane arrays; the masks stored as -1 or 0). */
typedef struct {
    float kd[3 * FC_PACKET_W], eta[3 * FC_PACKET_W], k[3 * FC_PACKET_W], f0[3 * FC_PACKET_W], fms[3 * FC_PACKET_W],
        es_f0[3 * FC_PACKET_W], es_den[3 * FC_PACKET_W], mf0[3 * FC_PACKET_W], mfms[3 * FC_PACKET_W],
        metallic[FC_PACKET_W], ax[FC_PACKET_W], ay[FC_PACKET_W], ior[FC_PACKET_W], dw[FC_PACKET_W], f90[FC_PACKET_W],
        ec_r[FC_PACKET_W], ec_loss[FC_PACKET_W], es_f90[FC_PACKET_W];
    int ggx[FC_PACKET_W], cor[FC_PACKET_W], cond[FC_PACKET_W], schlick[FC_PACKET_W], diff[FC_PACKET_W], ec[FC_PACKET_W],
        coupled[FC_PACKET_W], mixed[FC_PACKET_W];
} PacketPlain;

/* Lane j's parameters from a plain base's. */
inline void packet_plain_set(PacketPlain* q, int j, const PlainBase_l1* b) {
    set_lane3(q->kd, j, b->kd);
    set_lane3(q->eta, j, b->eta);
    set_lane3(q->k, j, b->k);
    q->ax[j] = b->ax;
    q->ay[j] = b->ay;
    q->ior[j] = b->ior;
    q->dw[j] = b->diffuse_weight;
    set_lane3(q->f0, j, b->f0);
    set_lane3(q->fms, j, b->ec_fms);
    set_lane3(q->es_f0, j, b->es_f0);
    set_lane3(q->es_den, j, b->es_den);
    q->f90[j] = b->f90;
    q->ec_r[j] = b->ec_r;
    q->ec_loss[j] = b->ec_loss;
    q->es_f90[j] = b->es_f90;
    q->ggx[j] = b->ggx ? -1 : 0;
    q->cor[j] = b->correlated ? -1 : 0;
    q->cond[j] = b->conductor ? -1 : 0;
    q->schlick[j] = b->schlick ? -1 : 0;
    q->diff[j] = b->diffuse ? -1 : 0;
    q->ec[j] = b->ec ? -1 : 0;
    q->coupled[j] = b->coupled ? -1 : 0;
    set_lane3(q->mf0, j, b->metal_f0);
    set_lane3(q->mfms, j, b->metal_fms);
    q->metallic[j] = b->metallic;
    q->mixed[j] = b->mixed ? -1 : 0;
}

/* Parameters every lane can evaluate, for a lane before its first plain surface: a
 * dielectric Beckmann base of alpha 1, no diffuse lobe, no compensation. */
inline PlainBase_l1 packet_unplain(void) {
    PlainBase_l1 b;
    b.kd = b.k = b.f0 = b.ec_fms = b.es_f0 = b.metal_f0 = b.metal_fms = (float3)(0.0f);
    b.eta = b.es_den = (float3)(1.0f);
    b.ax = b.ay = b.f90 = b.ec_loss = b.es_f90 = 1.0f;
    b.ior = 1.5f;
    b.diffuse_weight = b.ec_r = b.metallic = 0.0f;
    b.ggx = b.correlated = b.conductor = b.schlick = b.diffuse = b.ec = b.coupled = b.mixed = 0;
    b.beckmann = 1;
    b.e_table = fc_albedo_E;
    b.e5_table = fc_albedo_E5;
    return b;
}

/* The plain bases of the lanes `lanes` (the others' parameters are read, not used). */
inline void packet_plain_base(LINT lanes, const PacketPlain* q, LNAME(PlainBase) * b) {
    b->kd = l3_load(q->kd);
    b->eta = l3_load(q->eta);
    b->k = l3_load(q->k);
    b->ax = LLOAD(q->ax);
    b->ay = LLOAD(q->ay);
    b->ior = LLOAD(q->ior);
    b->diffuse_weight = LLOAD(q->dw);
    b->ggx = lanes & LLOAD(q->ggx);
    b->beckmann = lanes & ~LLOAD(q->ggx);
    b->correlated = LLOAD(q->cor);
    b->conductor = lanes & LLOAD(q->cond);
    b->schlick = lanes & LLOAD(q->schlick);
    b->diffuse = LLOAD(q->diff);
    b->f0 = l3_load(q->f0);
    b->f90 = LLOAD(q->f90);
    b->ec = lanes & LLOAD(q->ec);
    b->coupled = lanes & LLOAD(q->coupled);
    b->ec_r = LLOAD(q->ec_r);
    b->ec_loss = LLOAD(q->ec_loss);
    b->ec_fms = l3_load(q->fms);
    b->es_f0 = l3_load(q->es_f0);
    b->es_f90 = LLOAD(q->es_f90);
    b->es_den = l3_load(q->es_den);
    b->mixed = lanes & LLOAD(q->mixed);
    b->metallic = LLOAD(q->metallic);
    b->metal_f0 = l3_load(q->mf0);
    b->metal_fms = l3_load(q->mfms);
    b->e_table = fc_albedo_E;
    b->e5_table = fc_albedo_E5;
}
#endif

#endif
