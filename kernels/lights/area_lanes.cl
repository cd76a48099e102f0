/* Lane-generic body (kernels/lanes/lanes.cl): an area light's density and the side it
 * emits on (kernels/lights/area.cl). */
#ifndef FACET_LIGHTS_AREA_LANES_PASS
#define FACET_LIGHTS_AREA_LANES_PASS

/* Solid-angle density of reaching a light of area `area`, picked with probability
 * pick_pdf and sampled uniformly by area, at distance `dist` with cosine `cos_light` at
 * the light; 0 edge-on. */
inline LFLOAT LNAME(area_light_pdf_solid_angle)(LFLOAT pick_pdf, LFLOAT area, LFLOAT dist, LFLOAT cos_light) {
    LFLOAT c = fabs(cos_light);
    return select((LFLOAT)(0.0f), pick_pdf * (dist * dist) / (area * c), c > 0.0f);
}

/* The lanes where a light emits toward a direction whose cosine with its normal is c:
 * c > 0, or c != 0 for a two-sided emitter (two_sided a mask). */
inline LINT LNAME(area_light_lit)(LINT two_sided, LFLOAT c) { return select(c > 0.0f, c != 0.0f, two_sided); }

#undef FACET_LIGHTS_AREA_LANES_PASS
#endif
