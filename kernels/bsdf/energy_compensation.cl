/* Multiple-scattering energy compensation of the GGX and Beckmann microfacet lobes
 * (FC_MAT_ENERGY_COMPENSATION; docs/brdf.md, "Energy compensation").
 *
 * A single-scattering lobe f_ss reflects E(mu) <= 1 of the light arriving at cos = mu
 * (F = 1): the rest scatters more than once between microfacets. Kulla & Conty 2017
 * ("Revisiting Physically Based Shading at Imageworks", SIGGRAPH course) add the lobe
 *     f_ms(wo, wi) = F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
 *     E_avg = 2 int_0^1 E(mu) mu dmu,
 * which is symmetric in wo and wi (reciprocal) and whose albedo is F_ms (1 - E(mu_o)),
 * so that with F = 1 the total albedo is exactly 1. The Fresnel term of the light
 * that bounces several times is (their eq. for coloured conductors)
 *     F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),  F_avg = 2 int_0^1 F(mu) mu dmu,
 * F_avg by 8-point Gauss-Legendre quadrature of the material's Fresnel term (exact for
 * Schlick's polynomial).
 *
 * The diffuse base under the specular layer (FC_DIFFUSE_LAMBERT_1MF0 with a compensated
 * microfacet lobe) takes the energy the specular lobe leaves, again reciprocally:
 *     f_d = rho/pi (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (1 - E_s,avg),
 * E_s the Fresnel-weighted albedo of the specular lobe (single + multiple scattering),
 * so the diffuse albedo is rho (1 - E_s(mu_o)) and a white rough plastic reflects
 * everything (Kulla & Conty 2017, "energy-conserving layering" without the internal
 * bounces). E_s uses Schlick's form with the material's F0 and F90 (1 unless
 * FC_MAT_SPECULAR_F90): E_ss,F = F0 E + (F90 - F0) E5, E5 the albedo with F = (1 - wo.h)^5
 * (exact for Schlick, an approximation for the exact dielectric Fresnel).
 *
 * E, E5 and their averages are tables of albedo_tables_conductor.cl and
 * albedo_tables_schlick.cl (32 x 32 in mu and in r = sqrt(alpha), bilinear), integrated on
 * these kernels by tests/tools/albedo_tables.cpp.
 * They hold for height-correlated Smith G, the only G compensated; an anisotropic
 * lobe reads them at an effective alpha per direction (ec_r_dir), alpha above 1 at 1. */
#ifndef FACET_BSDF_ENERGY_COMPENSATION_CL
#define FACET_BSDF_ENERGY_COMPENSATION_CL

#include "kernels/shared/material_layout.h"
#include "kernels/bsdf/albedo_tables_conductor.cl"
#include "kernels/bsdf/albedo_tables_dielectric.cl"
#include "kernels/bsdf/albedo_tables_schlick.cl"
#include "kernels/bsdf/fresnel.cl"
#include "kernels/util/math.cl"

/* Whether the material's microfacet terms are compensated (GGX or Beckmann with
 * height-correlated Smith G and the flag set). The caller handles the mirror limit. */
inline bool ec_enabled(const FcMaterial* m) {
    return (m->flags & FC_MAT_ENERGY_COMPENSATION) != 0u && (m->ndf == FC_NDF_GGX || m->ndf == FC_NDF_BECKMANN) &&
           m->geometry == FC_G_SMITH_CORRELATED;
}

/* The table coordinate of the material's roughness: r = sqrt(alpha) in [0, 1]; an
 * anisotropic lobe's alpha is the root mean square sqrt((alpha_x^2 + alpha_y^2) / 2). */
inline float ec_r(const FcMaterial* m) {
    float ax = fmax(m->alpha_x, 0.0f), ay = fmax(m->alpha_y, 0.0f);
    float a = ax == ay ? sqrt(ax * ay) : sqrt(0.5f * (ax * ax + ay * ay));
    return clamp(sqrt(a), 0.0f, 1.0f); /* NaN -> 0 */
}

/* The same seen from unit direction w (local frame). An anisotropic lobe's albedo E(w)
 * leans on the roughness across w's azimuth (measured on these kernels: seen along the rough
 * axis at grazing angles it reflects more than seen along the smooth one), so its alpha^2
 * moves from the mean square at normal incidence to that across w at grazing:
 * alpha^2 = cos^2(theta) (alpha_x^2 + alpha_y^2) / 2 + w.y^2 alpha_x^2 + w.x^2 alpha_y^2
 * (an empirical fit, docs/brdf.md "Anisotropy"). Symmetric in the two directions of f_ms. */
inline float ec_r_dir_from(const FcMaterial* m, float3 w, float r) {
    return ec_r_dir_l1(fmax(m->alpha_x, 0.0f), fmax(m->alpha_y, 0.0f), w, r); /* energy_compensation_lanes.cl */
}

/* ec_r_dir_from with r = ec_r(m), the isotropic lobe's. */
inline float ec_r_dir(const FcMaterial* m, float3 w) { return ec_r_dir_from(m, w, ec_r(m)); }

/* Where (mu, r) falls in a [ndf][r][mu] table (ec_cell of energy_compensation_lanes.cl), found
 * once for the tables read at the same point. */
typedef struct {
    int at;
    float tx, ty;
} EcCell;

inline EcCell ec_cell(int ndf, float mu, float r) {
    EcCell c;
    ec_cell_l1(ndf, mu, r, &c.at, &c.tx, &c.ty);
    return c;
}

/* Bilinear lookup of a [ndf][r][mu] table in cell c. */
inline float ec_at(__constant const float* table, EcCell c) { return ec_table_at_l1(table, c.at, c.tx, c.ty); }

/* Bilinear lookup of a [ndf][r][mu] table at (mu, r). */
inline float ec_lookup(__constant const float* table, int ndf, float mu, float r) {
    return ec_at(table, ec_cell(ndf, mu, r));
}

/* Linear lookup of a [ndf][r] table of averages. */
inline float ec_lookup_avg(__constant const float* table, int ndf, float r) {
    float y = r * (float)(FC_ALBEDO_N_R - 1);
    int j = min((int)y, FC_ALBEDO_N_R - 2);
    __constant const float* row = table + ndf * FC_ALBEDO_N_R + j;
    return mix(row[0], row[1], y - (float)j);
}

inline int ec_ndf(const FcMaterial* m) { return m->ndf == FC_NDF_GGX ? 1 : 0; }

/* E(mu): the single-scattering albedo with F = 1. */
inline float ec_E(const FcMaterial* m, float mu) { return ec_lookup(fc_albedo_E, ec_ndf(m), mu, ec_r(m)); }
inline float ec_E_dir(const FcMaterial* m, float3 w) { return ec_lookup(fc_albedo_E, ec_ndf(m), w.z, ec_r_dir(m, w)); }

/* F_avg = 2 int F(mu) mu dmu. Schlick's F = F0 + (F90 - F0)(1 - mu)^5 has it in closed
 * form, F0 + (F90 - F0) / 21, as 2 int (1 - mu)^5 mu dmu = 2 B(2, 6) = 1/21 (what the
 * quadrature below gives it too, up to rounding, being exact for polynomials of degree 15):
 * ec_schlick_avg. The exact Fresnel terms by 8-point Gauss-Legendre on [0, 1]. */
inline float3 ec_schlick_avg(float3 f0, float f90) { return f0 + ((float3)(f90)-f0) * (1.0f / 21.0f); }

/* F_avg of the material's own Fresnel term. */
inline float3 ec_fresnel_avg(const FcMaterial* m) {
    if (m->fresnel == FC_FRESNEL_ONE) return (float3)(1.0f);
    if (m->fresnel == FC_FRESNEL_SCHLICK) return ec_schlick_avg(load3p(m->specular), fresnel_f90(m));
    if (m->fresnel == FC_FRESNEL_SCHLICK_IOR) return ec_schlick_avg((float3)(f0_from_ior(m->ior)), 1.0f);
    const float t[4] = {0.18343464249564980f, 0.52553240991632899f, 0.79666647741362674f, 0.96028985649753623f};
    const float w[4] = {0.36268378337836198f, 0.31370664587788729f, 0.22238103445337447f, 0.10122853629037626f};
    float3 sum = (float3)(0.0f);
    for (int k = 0; k < 4; ++k) {
        float lo = 0.5f * (1.0f - t[k]), hi = 0.5f * (1.0f + t[k]);
        sum += w[k] * (lo * fresnel_eval(m, lo) + hi * fresnel_eval(m, hi));
    }
    return sum;
}

/* F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), per channel, in [0, 1]. */
inline float3 ec_fresnel_ms_of(float3 f_avg, float e_avg) {
    float3 fa = clamp(f_avg, 0.0f, 1.0f);
    return fa * fa * e_avg / ((float3)(1.0f) - fa * (1.0f - e_avg));
}

/* The same from the material's own F_avg. */
inline float3 ec_fresnel_ms(const FcMaterial* m, float e_avg) { return ec_fresnel_ms_of(ec_fresnel_avg(m), e_avg); }

/* f_ms(wo, wi) for wo.z, wi.z > 0 (no cosine). */
inline float3 ec_ms_eval(const FcMaterial* m, float3 wo, float3 wi) {
    const int ndf = ec_ndf(m);
    const float r = ec_r(m);
    float e_avg = ec_lookup_avg(fc_albedo_E_avg, ndf, r);
    float loss = 1.0f - e_avg;
    if (!(loss > 1e-6f)) return (float3)(0.0f);
    const float eo = ec_lookup(fc_albedo_E, ndf, wo.z, ec_r_dir_from(m, wo, r));
    const float ei = ec_lookup(fc_albedo_E, ndf, wi.z, ec_r_dir_from(m, wi, r));
    float k = ec_ms_factor_l1(eo, ei, loss);
    return ec_fresnel_ms(m, e_avg) * k;
}

/* The probability with which the compensated lobe samples f_ms (cosine-weighted)
 * rather than f_ss: f_ms's share of the albedo at F = 1. */
inline float ec_ms_probability(const FcMaterial* m, float3 wo) { return clamp(1.0f - ec_E_dir(m, wo), 0.0f, 1.0f); }

/* E_s at the cosine of cell c (ec_cell's): the Fresnel-weighted albedo of the compensated
 * specular lobe, Schlick form (F0 clamped to [0, 1], F90), from the albedos E and E5 there
 * (ec_specular_albedo_of, energy_compensation_lanes.cl) and F_ms. */
inline float3 ec_specular_albedo_in(float3 f0, float f90, EcCell c, float3 f_ms) {
    return ec_specular_albedo_of_l1(f0, f90, ec_at(fc_albedo_E, c), ec_at(fc_albedo_E5, c), f_ms);
}

/* The coupled diffuse base's factor (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (1 - E_s,avg).
 * Over a mirror (alpha below FC_ALPHA_MIRROR) E_s is the mirror's reflectance F(mu) itself
 * and E_s,avg = F_avg: the diffuse base takes exactly what the delta lobe leaves, the smooth
 * limit of the same coupling (Kulla & Conty 2017 with E = 1), where the rough lobe's
 * tables would differ from the delta's exact F by their interpolation. */
inline float3 ec_diffuse_coupling(const FcMaterial* m, float3 wo, float3 wi) {
    if (!(fmax(m->alpha_x, m->alpha_y) >= FC_ALPHA_MIRROR)) {
        float3 lo = (float3)(1.0f) - clamp(fresnel_eval(m, wo.z), 0.0f, 1.0f);
        float3 li = (float3)(1.0f) - clamp(fresnel_eval(m, wi.z), 0.0f, 1.0f);
        float3 den = fmax((float3)(1.0f) - clamp(ec_fresnel_avg(m), 0.0f, 1.0f), (float3)(1e-6f));
        return lo * li / den;
    }
    const int ndf = ec_ndf(m);
    const float r = ec_r(m);
    float e_avg = ec_lookup_avg(fc_albedo_E_avg, ndf, r);
    float3 f_ms = ec_fresnel_ms(m, e_avg);
    float3 f0 = clamp(fresnel_f0(m), 0.0f, 1.0f);
    const float f90 = fresnel_f90(m);
    float e5_avg = ec_lookup_avg(fc_albedo_E5_avg, ndf, r);
    float3 s_avg = ec_specular_albedo_of_l1(f0, f90, e_avg, e5_avg, f_ms);
    float3 lo = ec_diffuse_share_l1(ec_specular_albedo_in(f0, f90, ec_cell(ndf, wo.z, r), f_ms));
    float3 li = ec_diffuse_share_l1(ec_specular_albedo_in(f0, f90, ec_cell(ndf, wi.z, r), f_ms));
    float3 den = fmax((float3)(1.0f) - s_avg, (float3)(1e-6f));
    return lo * li / den;
}

/* Rough dielectrics (Turquin 2019, "Practical multiple scattering compensation for
 * microfacet models", albedo scaling): f = f_ss / E(mu_o), E = E_R + E_T the energy albedo
 * of the single-scattering dielectric seen from wo (albedo_tables_dielectric.cl, by the
 * relative index seen from wo's side). The missing energy is returned in proportion to
 * the single-scattering lobes, reflection and transmission alike. Unlike f_ms above this is
 * not reciprocal (a known limit of albedo scaling; docs/brdf.md). */
/* The dielectric table's bilinear (r, mu) value in the x slice whose node (j, i) is t[0]
 * (half floats). */
inline float ec_dielectric_slice(__constant const half* t, float ty, float tz) {
    const int sr = FC_ALBEDO_D_N_MU;
    float a = mix(vload_half(0, t), vload_half(1, t), tz);
    float b = mix(vload_half(sr, t), vload_half(sr + 1, t), tz);
    return mix(a, b, ty);
}

inline float ec_dielectric_albedo(const FcMaterial* m, float3 wo) {
    float e = wo.z > 0.0f ? m->ior : 1.0f / m->ior;
    int side = e >= 1.0f ? 0 : 1;
    float ee = side == 0 ? e : 1.0f / e;
    float mu = clamp(fabs(wo.z), 0.0f, 1.0f);
    /* the index axis is uniform in sqrt(x), x = (eta - 1) / (eta + 1), up to eta = 100 */
    float x = sqrt(clamp((ee - 1.0f) / (ee + 1.0f), 0.0f, FC_ALBEDO_D_X_MAX) / FC_ALBEDO_D_X_MAX) *
              (float)(FC_ALBEDO_D_N_X - 1);
    float y = ec_r(m) * (float)(FC_ALBEDO_D_N_R - 1);
    float z = mu * (float)(FC_ALBEDO_D_N_MU - 1);
    int k = min((int)x, FC_ALBEDO_D_N_X - 2), j = min((int)y, FC_ALBEDO_D_N_R - 2),
        i = min((int)z, FC_ALBEDO_D_N_MU - 2);
    float tx = x - (float)k, ty = y - (float)j, tz = z - (float)i;
    __constant const half* t =
        (__constant const half*)fc_albedo_dielectric +
        (((ec_ndf(m) * 2 + side) * FC_ALBEDO_D_N_X + k) * FC_ALBEDO_D_N_R + j) * FC_ALBEDO_D_N_MU + i;
    const int sx = FC_ALBEDO_D_N_MU * FC_ALBEDO_D_N_R;
    float p1 = ec_dielectric_slice(t, ty, tz), p2 = ec_dielectric_slice(t + sx, ty, tz);
    /* Across the index, Catmull-Rom through the slices k - 1 .. k + 2: E bends strongly with
     * the index, most from inside, where linear interpolation between slices left up to
     * 2.3% in the furnace at ior 1.5 (docs/brdf.md). A neighbour beyond either end of the
     * table is extrapolated linearly. Slice 0 is the limit eta -> 1 of a rough interface
     * (below 1: light refracted straight on is still masked), not the exact E = 1 of an
     * index-matched one, which dielectric.cl treats as smooth. */
    float p0 = k >= 1 ? ec_dielectric_slice(t - sx, ty, tz) : 2.0f * p1 - p2;
    float p3 = k + 2 < FC_ALBEDO_D_N_X ? ec_dielectric_slice(t + 2 * sx, ty, tz) : 2.0f * p2 - p1;
    float v =
        p1 +
        0.5f * tx * ((p2 - p0) + tx * ((2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) + tx * (3.0f * (p1 - p2) + p3 - p0)));
    /* From inside the table holds E / E_c, E_c the F = 1 conductor's albedo (32 x 32 nodes):
     * beyond the critical angle every microfacet reflects totally, so near grazing, where
     * E_c falls steeply at small alpha (masking), E follows it, and the 16 x 12 nodes of E
     * alone missed that fall by 1.1% (Beckmann, alpha 0.05, 80 degrees); the quotient is
     * smooth there. From outside the transmission dominates and E does not follow E_c. */
    if (side == 1) v *= ec_E(m, mu);
    return clamp(v, 0.05f, 1.0f);
}

#endif
