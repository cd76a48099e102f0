/* Lane-generic body (kernels/lanes/lanes.cl): the exact dielectric reflectance and Schlick's
 * form, whose formulas and policy kernels/bsdf/fresnel.cl gives (its scalar functions are
 * these at W = 1). Needs vec3_lanes.cl of the same width. */
#ifndef FACET_BSDF_FRESNEL_LANES_PASS
#define FACET_BSDF_FRESNEL_LANES_PASS

/* F for light arriving at cosine cos_i on the side the relative index eta (inside over
 * outside) is seen from; a negative cos_i comes from the other side (eta inverted). 1 under
 * total internal reflection and wherever the result is not finite. */
inline LFLOAT LNAME(fresnel_dielectric)(LFLOAT cos_i, LFLOAT eta) {
    const LINT inside = cos_i < 0.0f;
    eta = select(eta, 1.0f / eta, inside);
    cos_i = fmin(select(cos_i, -cos_i, inside), 1.0f);
    const LFLOAT sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    const LFLOAT cos_t = sqrt(fmax(1.0f - sin2_t, 0.0f));
    const LFLOAT rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const LFLOAT rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const LFLOAT f = 0.5f * (rs * rs + rp * rp);
    const LFLOAT r = select((LFLOAT)(1.0f), clamp(f, 0.0f, 1.0f), isfinite(f));
    return select(r, (LFLOAT)(1.0f), sin2_t >= 1.0f);
}

/* Schlick's form f0 + (f90 - f0) (1 - cos)^5, one channel, cos clamped to [0, 1]. */
inline LFLOAT LNAME(fresnel_schlick_channel)(LFLOAT f0, LFLOAT f90, LFLOAT cos_theta) {
    const LFLOAT c = 1.0f - clamp(cos_theta, 0.0f, 1.0f);
    const LFLOAT c2 = c * c;
    return f0 + (f90 - f0) * (c2 * c2 * c);
}

#undef FACET_BSDF_FRESNEL_LANES_PASS
#endif
