/* Lane-generic body (kernels/lanes/lanes.cl): the path tracer's per-bounce weights
 * (kernels/integrator/path.cl). `strategy` (FC_STRATEGY_*) is the render's, the same in
 * every lane. Needs mis_lanes.cl of the same width and kernels/shared/render_layout.h. */
#ifndef FACET_INTEGRATOR_PATH_LANES_PASS
#define FACET_INTEGRATOR_PATH_LANES_PASS

/* The weight of a light sample whose solid-angle density is light_pdf, against BSDF
 * sampling's density bsdf_pdf of the same direction: 1 with light sampling alone, 0 with
 * BSDF sampling alone, else the power heuristic. */
inline LFLOAT LNAME(light_strategy_weight)(uint strategy, LFLOAT light_pdf, LFLOAT bsdf_pdf) {
    if (strategy == FC_STRATEGY_LIGHT) return (LFLOAT)(1.0f);
    if (strategy == FC_STRATEGY_BSDF) return (LFLOAT)(0.0f);
    return LNAME(power_heuristic)(light_pdf, bsdf_pdf);
}

/* The weight of light found by BSDF sampling with density bsdf_pdf, against light
 * sampling's density light_pdf. After a delta lobe (bsdf_pdf infinite) light sampling could
 * not have found it: weight 1. */
inline LFLOAT LNAME(bsdf_strategy_weight)(uint strategy, LFLOAT bsdf_pdf, LFLOAT light_pdf) {
    if (strategy == FC_STRATEGY_BSDF) return (LFLOAT)(1.0f);
    LFLOAT w = strategy == FC_STRATEGY_LIGHT ? (LFLOAT)(0.0f) : LNAME(power_heuristic)(bsdf_pdf, light_pdf);
    return select(w, (LFLOAT)(1.0f), isinf(bsdf_pdf));
}

/* Russian roulette's survival probability for a path of this throughput (rr_scale: what the
 * throughput understates of the path's worth, path.cl's): the largest channel times rr_scale
 * times the render's gain (FcRenderParams.roulette_gain, 2 by default), at most 0.95. pbrt-v4
 * and Mitsuba 3 take gain 1; on the demo scenes gain 2 gave 1.08-1.25 times the inverse of
 * MSE times time (docs/sampling.md, "Russian roulette"). */
inline LFLOAT LNAME(roulette_survival)(LVEC3 throughput, LFLOAT rr_scale, float gain) {
    return fmin(fmax(throughput.x, fmax(throughput.y, throughput.z)) * rr_scale * gain, 0.95f);
}

#undef FACET_INTEGRATOR_PATH_LANES_PASS
#endif
