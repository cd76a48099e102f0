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

/* The dielectric transmittance 1 - F of a refraction whose two cosines are known, cos_i on the
 * incident side and cos_t on the far side (both > 0; eta = n_t / n_i), written as fresnel.cl
 * gives it (without cancellation near the critical angle); 0 where a cosine sum is not positive
 * or the result not finite. */
inline LFLOAT LNAME(fresnel_dielectric_transmittance)(LFLOAT cos_i, LFLOAT cos_t, LFLOAT eta) {
    const LFLOAT a = cos_i + eta * cos_t;
    const LFLOAT b = eta * cos_i + cos_t;
    const LFLOAT t = 2.0f * eta * cos_i * cos_t * (1.0f / (a * a) + 1.0f / (b * b));
    return select((LFLOAT)(0.0f), clamp(t, 0.0f, 1.0f), (a > 0.0f) & (b > 0.0f) & isfinite(t));
}

/* The exact conductor reflectance of one channel, index eta + i k, from the outside (cos_i
 * clamped to [0, 1]); 1 wherever the result is not finite. */
inline LFLOAT LNAME(fresnel_conductor_channel)(LFLOAT cos_i, LFLOAT eta, LFLOAT k) {
    const LFLOAT c = clamp(cos_i, 0.0f, 1.0f);
    const LFLOAT cos2 = c * c;
    const LFLOAT sin2 = 1.0f - cos2;
    const LFLOAT eta2 = eta * eta, k2 = k * k;
    const LFLOAT t0 = eta2 - k2 - sin2;
    const LFLOAT a2b2 = sqrt(fmax(t0 * t0 + 4.0f * eta2 * k2, 0.0f));
    const LFLOAT t1 = a2b2 + cos2;
    const LFLOAT a = sqrt(fmax(0.5f * (a2b2 + t0), 0.0f));
    const LFLOAT t2 = 2.0f * c * a;
    const LFLOAT rs = (t1 - t2) / (t1 + t2);
    const LFLOAT t3 = cos2 * a2b2 + sin2 * sin2;
    const LFLOAT t4 = t2 * sin2;
    const LFLOAT rp = select(rs, rs * (t3 - t4) / (t3 + t4), t3 + t4 > 0.0f);
    const LFLOAT f = 0.5f * (rp + rs);
    const LFLOAT r = select((LFLOAT)(1.0f), clamp(f, 0.0f, 1.0f), isfinite(f));
    return select((LFLOAT)(1.0f), r, t1 + t2 > 0.0f); /* t1 + t2 not positive (or NaN): all reflected */
}

/* Schlick's form f0 + (f90 - f0) (1 - cos)^5, one channel, cos clamped to [0, 1]. */
inline LFLOAT LNAME(fresnel_schlick_channel)(LFLOAT f0, LFLOAT f90, LFLOAT cos_theta) {
    const LFLOAT c = 1.0f - clamp(cos_theta, 0.0f, 1.0f);
    const LFLOAT c2 = c * c;
    return f0 + (f90 - f0) * (c2 * c2 * c);
}

#undef FACET_BSDF_FRESNEL_LANES_PASS
#endif
