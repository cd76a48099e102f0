/* Test entry points for the lane-generic bodies (tests/lanes_test.cpp): each work-item
 * runs eight elements through the W = 1 form, one at a time, and through the W = 8 form in
 * float8 lanes, and writes both, up to four values an element. */
#include "kernels/bsdf/albedo_tables_schlick.cl"
#include "kernels/bsdf/dielectric.cl"
#include "kernels/bsdf/lambert.cl"
#include "kernels/lanes/packet.cl"
#include "kernels/lights/area.cl"
#include "kernels/trace/ray.cl"
#include "kernels/trace/sphere.cl"
#include "kernels/util/frame.cl"
#include "kernels/util/mis.cl"
#include "kernels/util/sampler.cl"
#include "kernels/util/trig.cl"
#include "kernels/util/warp.cl"

typedef struct {
    float a[8], b[8], c[8], d[8];
    uint k[8], m[8], n[8];
} LanesIn;

typedef struct {
    float one[4][8];   /* value v of element j at W = 1 */
    float eight[4][8]; /* the same at W = 8 */
} LanesOut;

#define IN8(f) vload8(0, in[i].f)
#define INU8(f) vload8(0, in[i].f)
#define OUT8(v, x) vstore8(x, 0, out[i].eight[v])

/* Clears both sides, so that unused values compare equal. */
inline void lanes_clear(__global LanesOut* o) {
    for (int v = 0; v < 4; ++v)
        for (int j = 0; j < 8; ++j) o->one[v][j] = o->eight[v][j] = 0.0f;
}

__kernel void lanes_sincos_turns(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float2 sc = sincos_turns_l1(in[i].a[j]);
        out[i].one[0][j] = sc.x;
        out[i].one[1][j] = sc.y;
    }
    FcVec2x8 sc = sincos_turns_l8(IN8(a));
    OUT8(0, sc.x);
    OUT8(1, sc.y);
}

__kernel void lanes_cosine_hemisphere(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float3 w = square_to_cosine_hemisphere_l1(in[i].a[j], in[i].b[j]);
        out[i].one[0][j] = w.x;
        out[i].one[1][j] = w.y;
        out[i].one[2][j] = w.z;
        out[i].one[3][j] = cosine_hemisphere_pdf_l1(in[i].c[j], w.z);
    }
    FcVec3x8 w = square_to_cosine_hemisphere_l8(IN8(a), IN8(b));
    OUT8(0, w.x);
    OUT8(1, w.y);
    OUT8(2, w.z);
    OUT8(3, cosine_hemisphere_pdf_l8(IN8(c), w.z));
}

__kernel void lanes_triangle_and_light(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float2 b = square_to_triangle_l1(in[i].a[j], in[i].b[j]);
        out[i].one[0][j] = b.x;
        out[i].one[1][j] = b.y;
        out[i].one[2][j] = area_light_pdf_solid_angle_l1(in[i].a[j], in[i].b[j], in[i].c[j], in[i].d[j]);
        out[i].one[3][j] = (float)area_light_lit_l1((in[i].k[j] & 1u) != 0u, in[i].d[j]);
    }
    FcVec2x8 b = square_to_triangle_l8(IN8(a), IN8(b));
    OUT8(0, b.x);
    OUT8(1, b.y);
    OUT8(2, area_light_pdf_solid_angle_l8(IN8(a), IN8(b), IN8(c), IN8(d)));
    /* a W = 8 mask lane is -1 where a W = 1 one is 1 */
    OUT8(3, 0.0f - convert_float8(area_light_lit_l8((INU8(k) & 1u) != 0u, IN8(d))));
}

__kernel void lanes_frame_and_offset(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float3 n = (float3)(in[i].a[j], in[i].b[j], in[i].c[j]);
        float3 s, t;
        frame_from_normal_l1(n, &s, &t);
        float3 p = offset_ray_origin_l1(s * in[i].d[j], n);
        out[i].one[0][j] = s.x + 2.0f * t.y; /* every component reaches an output */
        out[i].one[1][j] = s.y + 2.0f * t.z;
        out[i].one[2][j] = s.z + 2.0f * t.x;
        out[i].one[3][j] = p.x + p.y + p.z;
    }
    FcVec3x8 n = vec3_l8(IN8(a), IN8(b), IN8(c));
    FcVec3x8 s, t;
    frame_from_normal_l8(n, &s, &t);
    FcVec3x8 p = offset_ray_origin_l8(vec3_scale_l8(s, IN8(d)), n);
    OUT8(0, s.x + 2.0f * t.y);
    OUT8(1, s.y + 2.0f * t.z);
    OUT8(2, s.z + 2.0f * t.x);
    OUT8(3, p.x + p.y + p.z);
}

__kernel void lanes_power_heuristic(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) out[i].one[0][j] = power_heuristic_l1(in[i].a[j], in[i].b[j]);
    OUT8(0, power_heuristic_l8(IN8(a), IN8(b)));
}

/* A ray from 3 (a, b, c), toward the origin bent by (b, c, a), against the sphere of centre
 * (0.1, -0.2, 0.3) and radius 1.2 + d, out to t = 4 + a: the roots and the hit where the
 * line meets it (zero elsewhere), and the mask. */
__kernel void lanes_sphere(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        const float a = in[i].a[j], b = in[i].b[j], c = in[i].c[j], d = in[i].d[j];
        float t0, t1, t;
        const int meets =
            sphere_roots_l1(0.1f, -0.2f, 0.3f, 1.2f + d, 3.0f * a, 3.0f * b, 3.0f * c, b - a, c - b, a - c, &t0, &t1);
        const int hit =
            sphere_hit_l1(0.1f, -0.2f, 0.3f, 1.2f + d, 3.0f * a, 3.0f * b, 3.0f * c, b - a, c - b, a - c, 4.0f + a, &t);
        out[i].one[0][j] = meets ? t0 : 0.0f;
        out[i].one[1][j] = meets ? t1 : 0.0f;
        out[i].one[2][j] = hit ? t : 0.0f;
        out[i].one[3][j] = (float)meets + 2.0f * (float)hit;
    }
    const float8 a = IN8(a), b = IN8(b), c = IN8(c), d = IN8(d);
    float8 t0, t1, t;
    const int8 meets =
        sphere_roots_l8(0.1f, -0.2f, 0.3f, 1.2f + d, 3.0f * a, 3.0f * b, 3.0f * c, b - a, c - b, a - c, &t0, &t1);
    const int8 hit =
        sphere_hit_l8(0.1f, -0.2f, 0.3f, 1.2f + d, 3.0f * a, 3.0f * b, 3.0f * c, b - a, c - b, a - c, 4.0f + a, &t);
    OUT8(0, select((float8)(0.0f), t0, meets));
    OUT8(1, select((float8)(0.0f), t1, meets));
    OUT8(2, select((float8)(0.0f), t, hit));
    /* a W = 8 mask lane is -1 where a W = 1 one is 1 */
    OUT8(3, 0.0f - convert_float8(meets) - 2.0f * convert_float8(hit));
}

/* A rotation for the environment's to_map (rows), about the axis (1, 2, 2) / 3 by 0.7 rad. */
#define LANES_ENV_ROWS                                                                \
    (float3)(0.79097f, -0.37722f, 0.48174f), (float3)(0.48174f, 0.86936f, -0.11022f), \
        (float3)(-0.37722f, 0.31925f, 0.86936f)

/* The world direction (a, b, c) located on the map: u, v, sin(theta); and atan2_fast(a, b). */
__kernel void lanes_env_locate(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float st;
        const float2 uv =
            env_map_dir_to_uv_l1(env_dir_to_map_l1(LANES_ENV_ROWS, (float3)(in[i].a[j], in[i].b[j], in[i].c[j])), &st);
        out[i].one[0][j] = uv.x;
        out[i].one[1][j] = uv.y;
        out[i].one[2][j] = st;
        out[i].one[3][j] = atan2_fast_l1(in[i].a[j], in[i].b[j]);
    }
    float8 st;
    const FcVec2x8 uv = env_map_dir_to_uv_l8(env_dir_to_map_l8(LANES_ENV_ROWS, vec3_l8(IN8(a), IN8(b), IN8(c))), &st);
    OUT8(0, uv.x);
    OUT8(1, uv.y);
    OUT8(2, st);
    OUT8(3, atan2_fast_l8(IN8(a), IN8(b)));
}

/* The map's point (a, b) to its world direction. */
__kernel void lanes_env_uv_to_dir(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        const float3 w = env_uv_to_dir_l1(LANES_ENV_ROWS, (float2)(in[i].a[j], in[i].b[j]));
        out[i].one[0][j] = w.x;
        out[i].one[1][j] = w.y;
        out[i].one[2][j] = w.z;
    }
    const FcVec3x8 w = env_uv_to_dir_l8(LANES_ENV_ROWS, vec2_l8(IN8(a), IN8(b)));
    OUT8(0, w.x);
    OUT8(1, w.y);
    OUT8(2, w.z);
}

/* Each filter (the work-item's index mod 4) at radius 0.5 + 2 c of the first element: the
 * offsets and weights drawn at a and at b. */
__kernel void lanes_filter(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    const uint filter = i % 4u;
    const float radius = 0.5f + 2.0f * in[i].c[0];
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float oa, ob;
        out[i].one[1][j] = filter_sample_1d_l1(filter, radius, in[i].a[j], &oa);
        out[i].one[3][j] = filter_sample_1d_l1(filter, radius, in[i].b[j], &ob);
        out[i].one[0][j] = oa;
        out[i].one[2][j] = ob;
    }
    float8 oa, ob;
    OUT8(1, filter_sample_1d_l8(filter, radius, IN8(a), &oa));
    OUT8(3, filter_sample_1d_l8(filter, radius, IN8(b), &ob));
    OUT8(0, oa);
    OUT8(2, ob);
}

/* A pinhole, a thin lens and an orthographic camera, at one eye, looking along (0.3, -0.2, -1)
 * roughly: FcCamera's fields in order (eye, projection, forward, lens radius, right, focus
 * distance, up, padding). */
#define LANES_EYE \
    { 0.5f, 1.0f, 4.0f }
#define LANES_FORWARD \
    { 0.28f, -0.19f, -0.94f }
#define LANES_CAMERA(projection, lens, right, focus, up) \
    { LANES_EYE, projection, LANES_FORWARD, lens, right, focus, up, 0.0f }
#define LANES_RIGHT \
    { 0.7f, 0.0f, 0.2f }
#define LANES_UP \
    { 0.05f, 0.52f, -0.09f }
#define LANES_ORTHO_RIGHT \
    { 2.1f, 0.0f, 0.6f }
#define LANES_ORTHO_UP \
    { 0.15f, 1.56f, -0.27f }
__constant FcCamera lanes_cameras[3] = {
    LANES_CAMERA(FC_PROJECTION_PERSPECTIVE, 0.0f, LANES_RIGHT, 1.0f, LANES_UP),
    LANES_CAMERA(FC_PROJECTION_PERSPECTIVE, 0.08f, LANES_RIGHT, 3.5f, LANES_UP),
    LANES_CAMERA(FC_PROJECTION_ORTHOGRAPHIC, 0.0f, LANES_ORTHO_RIGHT, 1.0f, LANES_ORTHO_UP)};

/* Camera (the work-item's index mod 3) at image position (64 a, 48 b) of a 64 x 48 image, the
 * lens at (c, d): the ray's direction, and in value 3 its origin's components summed with
 * weights 1, 2, 4 (bit-exact inputs give bit-exact sums). */
__kernel void lanes_camera(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    __constant const FcCamera* cam = &lanes_cameras[i % 3u];
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        float3 o, w;
        camera_ray_l1(cam, 64.0f * in[i].a[j], 48.0f * in[i].b[j], 64u, 48u, in[i].c[j], in[i].d[j], &o, &w);
        out[i].one[0][j] = w.x;
        out[i].one[1][j] = w.y;
        out[i].one[2][j] = w.z;
        out[i].one[3][j] = o.x + 2.0f * o.y + 4.0f * o.z;
    }
    FcVec3x8 o, w;
    camera_ray_l8(cam, 64.0f * IN8(a), 48.0f * IN8(b), 64u, 48u, IN8(c), IN8(d), &o, &w);
    OUT8(0, w.x);
    OUT8(1, w.y);
    OUT8(2, w.z);
    OUT8(3, o.x + 2.0f * o.y + 4.0f * o.z);
}

/* The path's weights; the strategy (uniform across a work-item's lanes) is the work-item's
 * index mod 3. */
__kernel void lanes_path_weights(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    uint strategy = i % 3u;
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        out[i].one[0][j] = light_strategy_weight_l1(strategy, in[i].a[j], in[i].b[j]);
        out[i].one[1][j] = bsdf_strategy_weight_l1(strategy, in[i].a[j], in[i].b[j]);
        out[i].one[2][j] =
            roulette_survival_l1((float3)(in[i].a[j], in[i].b[j], in[i].c[j]), in[i].d[j], 1.0f + (float)(i % 4u));
    }
    OUT8(0, light_strategy_weight_l8(strategy, IN8(a), IN8(b)));
    OUT8(1, bsdf_strategy_weight_l8(strategy, IN8(a), IN8(b)));
    OUT8(2, roulette_survival_l8(vec3_l8(IN8(a), IN8(b), IN8(c)), IN8(d), 1.0f + (float)(i % 4u)));
}

/* GGX (kernels/bsdf/ggx_lanes.cl): a: alpha_x - 1e-4, b: alpha_y - 1e-4, c: wo's cosine (from
 * -0.1: some below the horizon), d: wo's azimuth in turns; k, m: the sample's (u.x, u.y). The
 * visible normal, its density, Lambda(wo) and the projected area. */
inline float3 lanes_ggx_wo(float c, float d) {
    const float2 sc = sincos_turns_l1(d);
    const float z = c - 0.1f, s = sqrt(fmax(1.0f - z * z, 0.0f));
    return (float3)(s * sc.y, s * sc.x, z);
}

/* The kernel lanes_NDF for NDF's lane bodies (NDF##_sample_visible, _pdf_visible, _lambda,
 * _projected_area at W = 1 and 8) on the inputs above. */
#define LANES_NDF_KERNEL(ndf)                                                                            \
    __kernel void lanes_##ndf(__global const LanesIn* in, __global LanesOut* out) {                      \
        uint i = get_global_id(0);                                                                       \
        lanes_clear(out + i);                                                                            \
        float wx[8], wy[8], wz[8], ux[8], uy[8];                                                         \
        for (int j = 0; j < 8; ++j) {                                                                    \
            const float ax = in[i].a[j] + 1e-4f, ay = in[i].b[j] + 1e-4f;                                \
            const float3 wo = lanes_ggx_wo(in[i].c[j], in[i].d[j]);                                      \
            wx[j] = wo.x;                                                                                \
            wy[j] = wo.y;                                                                                \
            wz[j] = wo.z;                                                                                \
            ux[j] = (float)(in[i].k[j] >> 8) * 0x1p-24f;                                                 \
            uy[j] = (float)(in[i].m[j] >> 8) * 0x1p-24f;                                                 \
            const float3 m = ndf##_sample_visible_l1(ax, ay, wo, ux[j], uy[j]);                          \
            out[i].one[0][j] = m.x + 2.0f * m.y;                                                         \
            out[i].one[1][j] = m.z;                                                                      \
            out[i].one[2][j] = ndf##_pdf_visible_l1(ax, ay, wo, m);                                      \
            out[i].one[3][j] = ndf##_lambda_l1(ax, ay, wo) + 3.0f * ndf##_projected_area_l1(ax, ay, wo); \
        }                                                                                                \
        const float8 ax = IN8(a) + 1e-4f, ay = IN8(b) + 1e-4f;                                           \
        const FcVec3x8 wo = vec3_l8(vload8(0, wx), vload8(0, wy), vload8(0, wz));                        \
        const FcVec3x8 m = ndf##_sample_visible_l8(ax, ay, wo, vload8(0, ux), vload8(0, uy));            \
        OUT8(0, m.x + 2.0f * m.y);                                                                       \
        OUT8(1, m.z);                                                                                    \
        OUT8(2, ndf##_pdf_visible_l8(ax, ay, wo, m));                                                    \
        OUT8(3, ndf##_lambda_l8(ax, ay, wo) + 3.0f * ndf##_projected_area_l8(ax, ay, wo));               \
    }

LANES_NDF_KERNEL(ggx)

/* Beckmann (kernels/bsdf/beckmann_lanes.cl), on lanes_ggx's inputs. */
LANES_NDF_KERNEL(beckmann)

/* Fresnel (kernels/bsdf/fresnel_lanes.cl): a: the cosine (2a - 1, either side), b: the
 * relative index (0.25 to 4.25), c, d: Schlick's f0 and f90; the conductor's index is b + i 5c. */
__kernel void lanes_fresnel(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        const float c = 2.0f * in[i].a[j] - 1.0f;
        out[i].one[0][j] = fresnel_dielectric_l1(c, 0.25f + 4.0f * in[i].b[j]);
        out[i].one[1][j] = fresnel_schlick_channel_l1(in[i].c[j], in[i].d[j], c);
        out[i].one[2][j] = fresnel_conductor_channel_l1(c, 0.25f + 4.0f * in[i].b[j], 5.0f * in[i].c[j]);
    }
    const float8 c = 2.0f * IN8(a) - 1.0f;
    OUT8(0, fresnel_dielectric_l8(c, 0.25f + 4.0f * IN8(b)));
    OUT8(1, fresnel_schlick_channel_l8(IN8(c), IN8(d), c));
    OUT8(2, fresnel_conductor_channel_l8(c, 0.25f + 4.0f * IN8(b), 5.0f * IN8(c)));
}

/* The plain two-lobe base (kernels/bsdf/plain_base_lanes.cl), lanes of GGX and Beckmann,
 * separable and height-correlated masking, dielectric and conductor Fresnel, with and without
 * the diffuse lobe mixed in one vector: a, b: alpha_x, alpha_y - 1e-4; c, d: wo as
 * lanes_ggx's; k, m: the sample's (u0, u1) and the albedo, n: its u2, the NDF (bit 0), the
 * masking (bit 1), the conductor (bit 2), no diffuse lobe (bit 3) and the indices. The sample's direction, density and
 * weight (-1 where none was made), and f and the density at a second direction. */
inline void lanes_plain_element(__global const LanesIn* in, int j, float* ax, float* ay, float3* wo, float3* wl,
                                float* u, float3* kd, float* ior) {
    *ax = in->a[j] + 1e-4f;
    *ay = in->b[j] + 1e-4f;
    *wo = lanes_ggx_wo(in->c[j], in->d[j]);
    *wl = lanes_ggx_wo(1.1f - in->c[j], in->d[j] + 0.37f);
    u[0] = (float)(in->k[j] >> 8) * 0x1p-24f;
    u[1] = (float)(in->m[j] >> 8) * 0x1p-24f;
    u[2] = (float)(in->n[j] % 1000u) * 1e-3f;
    *kd = (float3)((float)(in->m[j] & 255u), (float)(in->k[j] & 255u), 128.0f) / 255.0f;
    *ior = 1.05f + (float)((in->n[j] >> 4) % 100u) * 0.03f;
}

/* The conductor's index eta + i k of element j. */
inline void lanes_plain_conductor(__global const LanesIn* in, int j, float3* eta, float3* k) {
    const float f = (float)((in->n[j] >> 4) % 97u) / 97.0f;
    *eta = (float3)(0.2f + f, 0.9f - 0.5f * f, 1.4f);
    *k = (float3)(3.0f, 2.5f * f, 2.0f + f);
}

/* Lane j of a group of eight 3-vectors stored as x[0..7], y[8..15], z[16..23]. */
inline void set_lane3_8(float* a, int j, float3 v) {
    a[j] = v.x;
    a[8 + j] = v.y;
    a[16 + j] = v.z;
}

/* Element j's Schlick term (n / 1024 % 3 == 0, where not a conductor) and energy compensation
 * (bit 12 of n, with height-correlated masking; isotropic), its diffuse lobe coupled (bit 13);
 * the compensation's constants drawn from n, not derived from a material: the same bits at
 * both widths is all that is asked. */
inline void lanes_plain_extras(__global const LanesIn* in, int j, PlainBase_l1* b) {
    const uint n = in->n[j];
    const float f = (float)((n >> 4) % 89u) / 89.0f, g = (float)((n >> 6) % 83u) / 83.0f;
    b->schlick = !b->conductor && (n >> 10) % 3u == 0u;
    b->f0 = (float3)(0.02f + 0.9f * f, 0.5f * g, 0.04f);
    b->f90 = (n >> 11) & 1u ? 1.0f : 0.3f + 0.6f * g;
    b->ec = b->correlated && ((n >> 12) & 1u);
    b->coupled = b->ec && b->diffuse && ((n >> 13) & 1u);
    if (b->ec && ((n >> 16) & 1u)) b->ay = b->ax; /* half the compensated lanes isotropic */
    b->ec_r = sqrt(sqrt(b->ax));
    b->ec_loss = 0.02f + 0.5f * g;
    b->ec_fms = (float3)(0.3f + 0.6f * f, 0.9f * g, 0.5f);
    b->es_f0 = clamp(b->f0, 0.0f, 1.0f);
    b->es_f90 = b->f90;
    b->es_den = (float3)(0.4f + 0.5f * f, 0.9f, 0.3f + 0.6f * g);
    b->e_table = fc_albedo_E;
    b->e5_table = fc_albedo_E5;
    b->mixed = (n >> 14) % 3u != 0u;
    b->metallic = (n >> 14) % 3u == 1u ? 1.0f : 0.1f + 0.8f * f;
    b->metal_f0 = (float3)(0.9f * g, 0.7f, 0.2f + 0.5f * f);
    b->metal_fms = (float3)(0.5f * f, 0.8f, 0.3f + 0.6f * g);
}

__kernel void lanes_plain_base(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    float pax[8], pay[8], pior[8], pdw[8], kx[8], ky[8], kz[8], wx[8], wy[8], wz[8], lx[8], ly[8], lz[8], u0[8], u1[8],
        u2[8];
    float ex[8], ey[8], ez[8], qx[8], qy[8], qz[8];
    int ggx[8], cor[8], cond[8], diff[8];
    float f0[24], fms[24], ef0[24], eden[24], f90[8], ecr[8], ecl[8], ef90[8];
    int sch[8], ec[8], cpl[8], mix8[8];
    float mf0[24], mfms[24], met[8];
    for (int j = 0; j < 8; ++j) {
        PlainBase_l1 b;
        float3 wo, wl, kd;
        float u[3];
        lanes_plain_element(in + i, j, &b.ax, &b.ay, &wo, &wl, u, &kd, &b.ior);
        b.kd = kd;
        b.diffuse_weight = luminance(kd);
        b.ggx = (int)(in[i].n[j] & 1u);
        b.beckmann = !b.ggx;
        b.correlated = (int)((in[i].n[j] >> 1) & 1u);
        b.conductor = (int)((in[i].n[j] >> 2) & 1u);
        b.diffuse = !((in[i].n[j] >> 3) & 1u);
        lanes_plain_conductor(in + i, j, &b.eta, &b.k);
        if (!b.diffuse) b.kd = kd = (float3)(0.0f), b.diffuse_weight = 0.0f;
        lanes_plain_extras(in + i, j, &b);
        set_lane3_8(f0, j, b.f0), set_lane3_8(fms, j, b.ec_fms), set_lane3_8(ef0, j, b.es_f0);
        set_lane3_8(eden, j, b.es_den);
        f90[j] = b.f90, ecr[j] = b.ec_r, ecl[j] = b.ec_loss, ef90[j] = b.es_f90;
        sch[j] = b.schlick ? -1 : 0, ec[j] = b.ec ? -1 : 0, cpl[j] = b.coupled ? -1 : 0;
        set_lane3_8(mf0, j, b.metal_f0), set_lane3_8(mfms, j, b.metal_fms);
        met[j] = b.metallic, mix8[j] = b.mixed ? -1 : 0;
        PlainView_l1 v;
        plain_base_view_l1(&b, wo, &v);
        float3 wi, f, weight;
        float pdf, pl;
        const int ok = plain_base_sample_l1(&b, &v, wo, u[0], u[1], u[2], &wi, &f, &pdf, &weight);
        const float3 fl = plain_base_eval_pdf_l1(&b, &v, wo, wl, &pl);
        out[i].one[0][j] = ok ? wi.x + 2.0f * wi.y + 4.0f * wi.z : -1.0f;
        out[i].one[1][j] = ok ? pdf + f.x + 2.0f * f.y + 4.0f * f.z : -1.0f;
        out[i].one[2][j] = ok ? weight.x + 2.0f * weight.y + 4.0f * weight.z : -1.0f;
        out[i].one[3][j] = fl.x + 2.0f * fl.y + 4.0f * fl.z + 8.0f * pl;
        pax[j] = b.ax, pay[j] = b.ay, pior[j] = b.ior, pdw[j] = b.diffuse_weight;
        kx[j] = kd.x, ky[j] = kd.y, kz[j] = kd.z;
        wx[j] = wo.x, wy[j] = wo.y, wz[j] = wo.z, lx[j] = wl.x, ly[j] = wl.y, lz[j] = wl.z;
        u0[j] = u[0], u1[j] = u[1], u2[j] = u[2];
        ggx[j] = b.ggx ? -1 : 0;
        cor[j] = b.correlated ? -1 : 0;
        cond[j] = b.conductor ? -1 : 0;
        diff[j] = b.diffuse ? -1 : 0;
        ex[j] = b.eta.x, ey[j] = b.eta.y, ez[j] = b.eta.z, qx[j] = b.k.x, qy[j] = b.k.y, qz[j] = b.k.z;
    }
    PlainBase_l8 b;
    b.kd = vec3_l8(vload8(0, kx), vload8(0, ky), vload8(0, kz));
    b.ax = vload8(0, pax);
    b.ay = vload8(0, pay);
    b.ior = vload8(0, pior);
    b.diffuse_weight = vload8(0, pdw);
    b.ggx = vload8(0, ggx);
    b.beckmann = ~b.ggx;
    b.correlated = vload8(0, cor);
    b.conductor = vload8(0, cond);
    b.diffuse = vload8(0, diff);
    b.eta = vec3_l8(vload8(0, ex), vload8(0, ey), vload8(0, ez));
    b.k = vec3_l8(vload8(0, qx), vload8(0, qy), vload8(0, qz));
    b.f0 = vec3_l8(vload8(0, f0), vload8(1, f0), vload8(2, f0));
    b.ec_fms = vec3_l8(vload8(0, fms), vload8(1, fms), vload8(2, fms));
    b.es_f0 = vec3_l8(vload8(0, ef0), vload8(1, ef0), vload8(2, ef0));
    b.es_den = vec3_l8(vload8(0, eden), vload8(1, eden), vload8(2, eden));
    b.f90 = vload8(0, f90);
    b.ec_r = vload8(0, ecr);
    b.ec_loss = vload8(0, ecl);
    b.es_f90 = vload8(0, ef90);
    b.schlick = vload8(0, sch);
    b.ec = vload8(0, ec);
    b.coupled = vload8(0, cpl);
    b.e_table = fc_albedo_E;
    b.e5_table = fc_albedo_E5;
    b.metal_f0 = vec3_l8(vload8(0, mf0), vload8(1, mf0), vload8(2, mf0));
    b.metal_fms = vec3_l8(vload8(0, mfms), vload8(1, mfms), vload8(2, mfms));
    b.metallic = vload8(0, met);
    b.mixed = vload8(0, mix8);
    const FcVec3x8 wo = vec3_l8(vload8(0, wx), vload8(0, wy), vload8(0, wz));
    PlainView_l8 v;
    plain_base_view_l8(&b, wo, &v);
    FcVec3x8 wi, f, weight;
    float8 pdf, pl;
    const int8 ok =
        plain_base_sample_l8(&b, &v, wo, vload8(0, u0), vload8(0, u1), vload8(0, u2), &wi, &f, &pdf, &weight);
    const FcVec3x8 fl = plain_base_eval_pdf_l8(&b, &v, wo, vec3_l8(vload8(0, lx), vload8(0, ly), vload8(0, lz)), &pl);
    OUT8(0, select((float8)(-1.0f), wi.x + 2.0f * wi.y + 4.0f * wi.z, ok));
    OUT8(1, select((float8)(-1.0f), pdf + f.x + 2.0f * f.y + 4.0f * f.z, ok));
    OUT8(2, select((float8)(-1.0f), weight.x + 2.0f * weight.y + 4.0f * weight.z, ok));
    OUT8(3, fl.x + 2.0f * fl.y + 4.0f * fl.z + 8.0f * pl);
}

/* The rough dielectric (kernels/bsdf/dielectric_lanes.cl): dielectric.cl's material functions
 * (dielectric_sample, dielectric_eval_pdf) at W = 1 against rough_dielectric_sample and
 * rough_dielectric_eval_pdf at W = 8, lanes of GGX and Beckmann normals, separable and
 * height-correlated masking, F's own choice and the widened one, compensated or not, from above
 * and below, in one vector: a, b: alpha_x, alpha_y - 2e-4; c, d: wo as lanes_ggx's, turned below
 * by bit 4 of n; k, m: the sample's (u0, u1) and the tint, n: its u2, the NDF (bit 0), the
 * masking (bit 1), the wide choice (bit 2), the compensation (bit 3), the second direction below
 * (bit 5), an index below 1 (bit 6) and the index. The sample's direction, density and weight
 * (-1 where none was made), and f and the density at the second direction. */
__kernel void lanes_rough_dielectric(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    float pax[8], pay[8], pior[8], ece[8], tx[8], ty[8], tz[8], wx[8], wy[8], wz[8], lx[8], ly[8], lz[8], u0[8], u1[8],
        u2[8];
    int ggx[8], beck[8], cor[8], wide[8], ec[8];
    for (int j = 0; j < 8; ++j) {
        const uint n = in[i].n[j];
        FcMaterial m;
        m.diffuse_model = FC_DIFFUSE_NONE;
        m.specular_model = FC_SPECULAR_DIELECTRIC;
        m.ndf = (n & 1u) ? FC_NDF_GGX : FC_NDF_BECKMANN;
        m.geometry = (n & 2u) ? FC_G_SMITH_CORRELATED : FC_G_SMITH_SEPARABLE;
        m.sampling = FC_SAMPLE_VISIBLE;
        m.flags = ((n & 4u) ? FC_MAT_WIDE_CHOICE : 0u) | ((n & 8u) ? FC_MAT_ENERGY_COMPENSATION : 0u);
        m.alpha_x = in[i].a[j] + 2e-4f;
        m.alpha_y = in[i].b[j] + 2e-4f;
        const float eta = 1.05f + (float)((n >> 7) % 100u) * 0.03f;
        m.ior = (n & 64u) ? 1.0f / eta : eta;
        const float3 tint = (float3)((float)(in[i].m[j] & 255u), (float)(in[i].k[j] & 255u), 200.0f) / 255.0f;
        m.specular[0] = tint.x;
        m.specular[1] = tint.y;
        m.specular[2] = tint.z;
        float3 wo = lanes_ggx_wo(in[i].c[j], in[i].d[j]);
        if (n & 16u) wo = -wo;
        float3 wl = lanes_ggx_wo(1.1f - in[i].c[j], in[i].d[j] + 0.37f);
        if (n & 32u) wl = -wl;
        const float3 u = (float3)((float)(in[i].k[j] >> 8) * 0x1p-24f, (float)(in[i].m[j] >> 8) * 0x1p-24f,
                                  (float)(n % 1000u) * 1e-3f);
        BsdfSample bs;
        const bool ok = dielectric_sample(&m, wo, u, &bs);
        float pl;
        const float3 fl = dielectric_eval_pdf(&m, wo, wl, &pl);
        out[i].one[0][j] = ok ? bs.wi.x + 2.0f * bs.wi.y + 4.0f * bs.wi.z : -1.0f;
        out[i].one[1][j] = ok ? bs.pdf + bs.f.x + 2.0f * bs.f.y + 4.0f * bs.f.z : -1.0f;
        out[i].one[2][j] = ok ? bs.weight.x + 2.0f * bs.weight.y + 4.0f * bs.weight.z : -1.0f;
        out[i].one[3][j] = fl.x + 2.0f * fl.y + 4.0f * fl.z + 8.0f * pl;
        const RoughDielectric_l1 b = rough_dielectric_of(&m, wo);
        pax[j] = b.ax, pay[j] = b.ay, pior[j] = b.ior, ece[j] = b.ec_e;
        tx[j] = b.tint.x, ty[j] = b.tint.y, tz[j] = b.tint.z;
        ggx[j] = b.ggx ? -1 : 0, beck[j] = b.beckmann ? -1 : 0, cor[j] = b.correlated ? -1 : 0;
        wide[j] = b.wide ? -1 : 0, ec[j] = b.ec ? -1 : 0;
        wx[j] = wo.x, wy[j] = wo.y, wz[j] = wo.z, lx[j] = wl.x, ly[j] = wl.y, lz[j] = wl.z;
        u0[j] = u.x, u1[j] = u.y, u2[j] = u.z;
    }
    RoughDielectric_l8 b;
    b.tint = vec3_l8(vload8(0, tx), vload8(0, ty), vload8(0, tz));
    b.ax = vload8(0, pax);
    b.ay = vload8(0, pay);
    b.ior = vload8(0, pior);
    b.ec_e = vload8(0, ece);
    b.ggx = vload8(0, ggx);
    b.beckmann = vload8(0, beck);
    b.correlated = vload8(0, cor);
    b.wide = vload8(0, wide);
    b.ec = vload8(0, ec);
    const FcVec3x8 wo = vec3_l8(vload8(0, wx), vload8(0, wy), vload8(0, wz));
    b.area_o = rough_dielectric_area_l8(&b, wo);
    FcVec3x8 wi, f, weight;
    float8 pdf, pl;
    const int8 ok =
        rough_dielectric_sample_l8(&b, wo, vload8(0, u0), vload8(0, u1), vload8(0, u2), &wi, &f, &pdf, &weight);
    const FcVec3x8 fl = rough_dielectric_eval_pdf_l8(&b, wo, vec3_l8(vload8(0, lx), vload8(0, ly), vload8(0, lz)), &pl);
    OUT8(0, select((float8)(-1.0f), wi.x + 2.0f * wi.y + 4.0f * wi.z, ok));
    OUT8(1, select((float8)(-1.0f), pdf + f.x + 2.0f * f.y + 4.0f * f.z, ok));
    OUT8(2, select((float8)(-1.0f), weight.x + 2.0f * weight.y + 4.0f * weight.z, ok));
    OUT8(3, fl.x + 2.0f * fl.y + 4.0f * fl.z + 8.0f * pl);
}

/* Element j of group i through the scalar sampler_get4 (coordinates in a uint4's lanes),
 * into out->one; returns the element's sampler, whose seed and index the lanes take. */
inline Sampler lanes_scalar_sample(__global const LanesIn* in, __global LanesOut* out, int j) {
    Sampler s = sampler_init(FC_SAMPLER_SOBOL, in->k[j], in->m[j], in->n[j]);
    Sampler t = s;
    float4 u = sampler_get4(&t, in->n[j] % 37u);
    out->one[0][j] = u.x;
    out->one[1][j] = u.y;
    out->one[2][j] = u.z;
    out->one[3][j] = u.w;
    return s;
}

/* The W = 8 sampler against the scalar sampler_get4. */
__kernel void lanes_sampler_get4(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    uint seed[8], index_reversed[8];
    for (int j = 0; j < 8; ++j) {
        Sampler s = lanes_scalar_sample(in + i, out + i, j);
        seed[j] = s.seed;
        index_reversed[j] = s.index_reversed;
    }
    float8 u[4];
    sampler_get4_l8(vload8(0, seed), vload8(0, index_reversed), INU8(n) % 37u, u);
    for (int v = 0; v < 4; ++v) OUT8(v, u[v]);
}

/* The sampler at W = 16 (the packets' width on AVX-512 CPUs, where the Sobol' chunks are
 * indexed in one 512-bit register), instantiated here beside the program's W = 8. */
#define FC_LW 16
#include "kernels/lanes/lanes_open.cl"
#include "kernels/util/hash_lanes.cl"
#include "kernels/util/sampler_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

/* The W = 16 sampler against the scalar one: lanes 8-15 take lanes 7-0's inputs, so each
 * lane j's value (eight) stands only where lane 15 - j gave the same bits (else NaN). */
__kernel void lanes_sampler_get4_16(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    uint seed[16], index_reversed[16], set[16];
    for (int j = 0; j < 8; ++j) {
        Sampler s = lanes_scalar_sample(in + i, out + i, j);
        seed[j] = seed[15 - j] = s.seed;
        index_reversed[j] = index_reversed[15 - j] = s.index_reversed;
        set[j] = set[15 - j] = in[i].n[j] % 37u;
    }
    float16 u[4];
    sampler_get4_l16(vload16(0, seed), vload16(0, index_reversed), vload16(0, set), u);
    for (int v = 0; v < 4; ++v) {
        float w[16];
        vstore16(u[v], 0, w);
        for (int j = 0; j < 8; ++j) out[i].eight[v][j] = as_uint(w[j]) == as_uint(w[15 - j]) ? w[j] : NAN;
    }
}

/* The hashes at widths 1, 4 and 8, as bit patterns. */
__kernel void lanes_hashes(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        uint a = in[i].k[j], b = in[i].m[j];
        out[i].one[0][j] = as_float(hash_pair_l1(a, b));
        out[i].one[1][j] = as_float(laine_karras_l1(a, b));
        out[i].one[2][j] = as_float(coordinate_seed_l1(a, b & 3u));
        out[i].one[3][j] = as_float(reverse_bits_l1(a) ^ (uint)mix64_l1(((ulong)b << 32) | a));
    }
    uint8 a = INU8(k), b = INU8(m);
    OUT8(0, as_float8(hash_pair_l8(a, b)));
    OUT8(1, as_float8(laine_karras_l8(a, b)));
    OUT8(2, as_float8(coordinate_seed_l8(a, b & 3u)));
    OUT8(3, as_float8(reverse_bits_l8(a) ^ convert_uint8(mix64_l8((convert_ulong8(b) << 32) | convert_ulong8(a)))));
}

/* The W = 4 hashes the scalar sampler uses (its coordinates in the lanes), lanes 0-3 and
 * 4-7 as two uint4, against W = 1. */
__kernel void lanes_hashes4(__global const LanesIn* in, __global LanesOut* out) {
    uint i = get_global_id(0);
    lanes_clear(out + i);
    for (int j = 0; j < 8; ++j) {
        uint a = in[i].k[j], b = in[i].m[j];
        out[i].one[0][j] = as_float(laine_karras_l1(a, b));
        out[i].one[1][j] = as_float(coordinate_seed_l1(a, b & 3u));
        out[i].one[2][j] = as_float(reverse_bits_l1(a));
        out[i].one[3][j] = as_float(hash32_l1(a));
    }
    for (uint h = 0; h < 2u; ++h) {
        uint4 a = vload4(h, in[i].k), b = vload4(h, in[i].m);
        vstore4(as_float4(laine_karras_l4(a, b)), h, out[i].eight[0]);
        vstore4(as_float4(coordinate_seed_l4(a, b & 3u)), h, out[i].eight[1]);
        vstore4(as_float4(reverse_bits_l4(a)), h, out[i].eight[2]);
        vstore4(as_float4(hash32_l4(a)), h, out[i].eight[3]);
    }
}
