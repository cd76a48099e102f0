/* The packet paths' BSDFs made in lanes (issue 29): a plain base's (packet_plain.cl) or a rough
 * dielectric's (packet_dielectric.cl) value and density at the light's direction, and its
 * sample, merged into the packet's light sample and next ray on the lanes that made them, as the
 * per-lane route (bsdf_eval_pdf, path_bsdf_sample) merges its own. Included by
 * kernels/integrator/packet_paths.cl inside its lanes (FC_LW = FC_PACKET_W), after its lane
 * helpers (l3, l3_dot). */
#ifndef FACET_INTEGRATOR_PACKET_BSDF_MERGE_CL
#define FACET_INTEGRATOR_PACKET_BSDF_MERGE_CL

/* f and its density p at the light's direction on the lanes `lanes`: *ok where f is not black,
 * *F = f there (else 0), and *pdf = p under MIS (else 0: bsdf_eval's route, without the
 * density). */
inline void packet_bsdf_merge_eval(LINT lanes, L3 f, LFLOAT p, bool mis, LINT* ok, L3* F, LFLOAT* pdf) {
    const LINT nonzero = (f.x != 0.0f) | (f.y != 0.0f) | (f.z != 0.0f);
    *ok = select(*ok, nonzero, lanes);
    *F = LNAME(vec3_select)(*F, LNAME(vec3_select)(l3(0.0f, 0.0f, 0.0f), f, nonzero), lanes);
    *pdf = select(*pdf, select((LFLOAT)(0.0f), p, nonzero & (LINT)(mis ? -1 : 0)), lanes);
}

/* A sample on the lanes `lanes` (made where ok: the local direction wl, its density pl and
 * weight wt): the next ray's direction in the world (the frame S, T, N), kept where it leaves on
 * the side of NG that wl.z says (a reflection on wo's, a refraction across); *cont, *next_pdf
 * and *A as the lanes' own route sets them. Returns the lanes that keep it, and their
 * direction's side of NG in *side. */
inline LINT packet_bsdf_merge_sample(LINT lanes, LINT ok, L3 wl, LFLOAT pl, L3 wt, L3 S, L3 T, L3 N, L3 NG, L3* nwi,
                                     LINT* cont, LFLOAT* next_pdf, L3* A, LFLOAT* side) {
    const L3 ww = LNAME(vec3_combine)(wl.x, S, wl.y, T, wl.z, N);
    *side = l3_dot(NG, ww);
    ok &= lanes & (*side * wl.z > 0.0f);
    *nwi = LNAME(vec3_select)(*nwi, LNAME(vec3_select)(l3(0.0f, 0.0f, 1.0f), ww, ok), lanes);
    *cont = select(*cont, ok, lanes);
    *next_pdf = select(*next_pdf, select((LFLOAT)(0.0f), pl, ok), lanes);
    *A = LNAME(vec3_select)(*A, LNAME(vec3_select)(l3(0.0f, 0.0f, 0.0f), wt, ok), lanes);
    return ok;
}

#endif
