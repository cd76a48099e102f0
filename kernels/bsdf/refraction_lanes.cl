/* Lane-generic body (kernels/lanes/lanes.cl): refraction at an interface and the relative index
 * seen from a direction, whose conventions and sources kernels/bsdf/refraction.cl gives (its
 * scalar functions are these at W = 1). Needs vec3_lanes.cl of the same width. */
#ifndef FACET_BSDF_REFRACTION_LANES_PASS
#define FACET_BSDF_REFRACTION_LANES_PASS

/* The relative index n_far / n_near for a direction on the side of cos_w: eta above the
 * surface (cos_w > 0), 1 / eta below it. */
inline LFLOAT LNAME(relative_eta)(LFLOAT eta, LFLOAT cos_w) {
    const LINT below = (cos_w <= 0.0f) | isnan(cos_w); /* not above (no vector NOT: lanes.cl) */
    return LNAME(lanes_any)(below) ? select(eta, 1.0f / eta, below) : eta;
}

/* The direction refracted from w through the interface of unit normal h and relative index eta
 * (refraction.cl's refract_about), in *wt: -w / e + (cos_i / e - cos_t) h, normalised (-h where
 * that fails), turned to the side w does not see when w meets h's back. The mask of lanes that
 * refract; under total internal reflection (sin_t >= 1) *wt is meaningless. */
inline LINT LNAME(refract_about)(LVEC3 w, LVEC3 h, LFLOAT eta, LVEC3* wt) {
    LFLOAT cos_i = LNAME(vec3_dot)(w, h);
    const LINT back = cos_i < 0.0f;
    if (LNAME(lanes_any)(back)) eta = select(eta, 1.0f / eta, back);
    cos_i = select(cos_i, -cos_i, back);
    h = LNAME(vec3_select)(h, LNAME(vec3_neg)(h), back);
    const LFLOAT sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    const LFLOAT k = cos_i / eta - sqrt(1.0f - sin2_t);
    const LVEC3 t = LNAME(vec3)(-w.x / eta + k * h.x, -w.y / eta + k * h.y, -w.z / eta + k * h.z);
    const LFLOAT len2 = LNAME(vec3_dot)(t, t);
    const LFLOAT il = rsqrt(len2);
    *wt = LNAME(vec3_select)(LNAME(vec3_neg)(h), LNAME(vec3)(t.x * il, t.y * il, t.z * il),
                             (len2 > 0.0f) & isfinite(len2));
    return sin2_t < 1.0f;
}

#undef FACET_BSDF_REFRACTION_LANES_PASS
#endif
