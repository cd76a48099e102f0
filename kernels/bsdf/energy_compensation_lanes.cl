/* Lane-generic body (kernels/lanes/lanes.cl): the table lookups and terms of the
 * multiple-scattering energy compensation whose formulas and policy
 * kernels/bsdf/energy_compensation.cl gives (its scalar functions are these at W = 1; the
 * plain base, kernels/bsdf/plain_base_lanes.cl, reads them in lanes). The tables are passed
 * in, so that the body needs none of them declared. Needs vec3_lanes.cl of the same width. */
#ifndef FACET_BSDF_ENERGY_COMPENSATION_LANES_PASS
#define FACET_BSDF_ENERGY_COMPENSATION_LANES_PASS

#ifndef FC_ALBEDO_N_MU
/* the tables' grid, as albedo_tables_conductor.cl defines it (a different one there is a
 * redefinition the compiler reports) */
#define FC_ALBEDO_N_MU 32
#define FC_ALBEDO_N_R 32
#endif

/* Where (mu, r) falls in a [ndf][r][mu] table of FC_ALBEDO_N_MU x FC_ALBEDO_N_R nodes: the
 * offset of its cell's first node in *at and the bilinear fractions in *tx (mu) and *ty (r). */
inline void LNAME(ec_cell)(LINT ndf, LFLOAT mu, LFLOAT r, LINT* at, LFLOAT* tx, LFLOAT* ty) {
    const LFLOAT x = clamp(mu, 0.0f, 1.0f) * (float)(FC_ALBEDO_N_MU - 1);
    const LFLOAT y = r * (float)(FC_ALBEDO_N_R - 1);
    const LINT i = min(LCONVERT_INT(x), (LINT)(FC_ALBEDO_N_MU - 2));
    const LINT j = min(LCONVERT_INT(y), (LINT)(FC_ALBEDO_N_R - 2));
    *at = (ndf * FC_ALBEDO_N_R + j) * FC_ALBEDO_N_MU + i;
    *tx = x - LCONVERT_FLOAT(i);
    *ty = y - LCONVERT_FLOAT(j);
}

/* The bilinear value of `table` in the cells at, tx, ty (ec_cell's), lane by lane. */
inline LFLOAT LNAME(ec_table_at)(__constant const float* table, LINT at, LFLOAT tx, LFLOAT ty) {
#if FC_LW == 1
    __constant const float* row = table + at;
    const float a = mix(row[0], row[1], tx);
    const float b = mix(row[FC_ALBEDO_N_MU], row[FC_ALBEDO_N_MU + 1], tx);
#else
    int o[FC_LW];
    float a0[FC_LW], a1[FC_LW], b0[FC_LW], b1[FC_LW];
    LSTORE(at, o);
    for (int j = 0; j < FC_LW; ++j) {
        __constant const float* row = table + o[j];
        a0[j] = row[0];
        a1[j] = row[1];
        b0[j] = row[FC_ALBEDO_N_MU];
        b1[j] = row[FC_ALBEDO_N_MU + 1];
    }
    const LFLOAT a = mix(LLOAD(a0), LLOAD(a1), tx);
    const LFLOAT b = mix(LLOAD(b0), LLOAD(b1), tx);
#endif
    return mix(a, b, ty);
}

/* The tables' roughness coordinate of an anisotropic lobe (alpha_x ax, alpha_y ay, both at 0
 * at least) seen from unit direction w, energy_compensation.cl's empirical fit (ec_r_dir); r,
 * the isotropic coordinate, where ax = ay. */
inline LFLOAT LNAME(ec_r_dir)(LFLOAT ax, LFLOAT ay, LVEC3 w, LFLOAT r) {
    const LFLOAT ms = 0.5f * (ax * ax + ay * ay), s2 = fmax(1.0f - w.z * w.z, 0.0f);
    const LFLOAT a2 = ms + s2 * (w.y * w.y * ax * ax + w.x * w.x * ay * ay - s2 * ms);
    return select(clamp(sqrt(sqrt(a2)), 0.0f, 1.0f), r, ax == ay);
}

/* f_ms's factor (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)) from E(mu_o), E(mu_i) and
 * loss = 1 - E_avg (above 1e-6: the caller's test); f_ms is F_ms times it. */
inline LFLOAT LNAME(ec_ms_factor)(LFLOAT e_o, LFLOAT e_i, LFLOAT loss) {
    return fmax(1.0f - e_o, 0.0f) * fmax(1.0f - e_i, 0.0f) / (FC_PI * loss);
}

/* E_s, the Fresnel-weighted albedo of the compensated specular lobe in Schlick's form, from
 * F0 (clamped to [0, 1]), F90, the albedos E and E5 (or their averages) and F_ms. */
inline LVEC3 LNAME(ec_specular_albedo_of)(LVEC3 f0, LFLOAT f90, LFLOAT e, LFLOAT e5, LVEC3 f_ms) {
    const LFLOAT ms = 1.0f - e;
    return LNAME(vec3)(f0.x * e + (f90 - f0.x) * e5 + f_ms.x * ms, f0.y * e + (f90 - f0.y) * e5 + f_ms.y * ms,
                       f0.z * e + (f90 - f0.z) * e5 + f_ms.z * ms);
}

/* 1 - E_s clamped at 0: the share the coupled diffuse base takes seen from one side. */
inline LVEC3 LNAME(ec_diffuse_share)(LVEC3 e_s) {
    return LNAME(vec3)(fmax(1.0f - e_s.x, 0.0f), fmax(1.0f - e_s.y, 0.0f), fmax(1.0f - e_s.z, 0.0f));
}

#undef FACET_BSDF_ENERGY_COMPENSATION_LANES_PASS
#endif
