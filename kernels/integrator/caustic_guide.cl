/* Sampling toward glass at Lambertian and glossy vertices: caustics and glints.
 *
 * Light that reaches a diffuse surface through glass (the sun focused by a glass ball onto
 * the floor) is found only by BSDF sampling: next-event estimation's shadow ray stops at the
 * glass. With the cosine lobe alone such a path is rare and, when found, a firefly; on
 * glass_metal_sky these few samples are nearly all of the image's error. The same holds for a
 * rough metal that sees the sun's glint on a glass ball (its reflection). So at a vertex whose
 * BSDF is a Lambertian lobe and no more, or a plain rough microfacet base (caustic_guide_receiver;
 * a smaller share), the direction is drawn from a one-sample mixture (Veach 1997, section
 * 9.2.4): with probability 1 - g by the BSDF (its choice of lobe rescaled past g), with
 * probability g by a guide, itself a mixture of two:
 *
 * - the lens guide (share h): for a smooth analytic glass sphere (a ball lens), a direction
 *   of the environment is drawn as next-event estimation draws it (mostly the sun), and the
 *   direction at the vertex is found whose ray, refracted into the ball and out again, leaves
 *   along it. By the ball's symmetry that ray lies in the plane of the ball's centre and the
 *   environment direction; with alpha its angle from the axis toward the centre and
 *   b = d sin(alpha) its distance from the centre, it leaves turned by
 *       G(alpha) = alpha - D(b),  D(b) = 2 (asin(b / r) - asin(b / (n r)))
 *   (Snell's law at both surfaces, which meet the ray at equal angles), so the directions
 *   are the roots of G(alpha) = +-phi, phi the environment direction's angle from the axis,
 *   alpha up to lens_reach (the rim less a thousandth). G is concave (Lens, below), so its
 *   maximum, found once per ball and vertex, tells how many roots there are (at most three),
 *   and each is found by Newton's method from the side where it converges monotonically; one
 *   of them is taken. Its density is the environment's at the direction it leaves along times
 *   the Jacobian |sin G G'(alpha)| / sin(alpha) (the map keeps the azimuth about the axis),
 *   over the roots' count and the lenses'. At glossy vertices a share (FC_LENS_GLINT) of the
 *   lens guide's draws aims instead at the ball's glint: the direction whose ray, reflected
 *   off the ball, leaves along the environment direction (R, below: one root), with the same
 *   Jacobian in R.
 * - the cone guide (share 1 - h): uniform inside the cone that a glass object's bounding
 *   sphere subtends (pbrt-v4's cone sampling, as kernels/lights/sphere_light.cl), the object
 *   picked in proportion to its cone's solid angle: for glass that is not a smooth ball.
 *
 * The density of the whole mixture is what the sample's weight divides by and what MIS weighs
 * against light sampling, on both sides (for a light at infinity, without the lens share:
 * caustic_guide_density). g is the scene's share scaled down where the cones fill less than
 * FC_CAUSTIC_GUIDE_FULL; h is 1 where every caster that counts is a lens, 1/2 where some are,
 * else 0. The BSDF's own sampling keeps every direction of its support possible, so the
 * estimate stays unbiased whatever the guide; a guided direction below the surface ends the
 * path (its integrand is zero there), and one where the BSDF is 0 weighs 0.
 *
 * The casters (host/scene/caustic_casters.cpp, at most FC_MAX_CASTERS) are two float4 each:
 * (centre, radius) of a dielectric object's bounding sphere, then (n, 0, 0, 0) with n the
 * relative index of a smooth glass ball (a lens), 0 for others. A caster counts at a point
 * only where the point is outside its sphere and part of its cone is above the plane of the
 * shading normal; both tests are functions of the vertex alone, so sampling and density
 * agree. Compiled only into programs with dielectrics (FC_HAS_DIELECTRIC); docs/sampling.md,
 * "Sampling toward glass". */
#ifndef FACET_INTEGRATOR_CAUSTIC_GUIDE_CL
#define FACET_INTEGRATOR_CAUSTIC_GUIDE_CL

#include "kernels/bsdf/bsdf.cl"
#include "kernels/lights/environment.cl"
#include "kernels/lights/sphere_light.cl"
#include "kernels/shared/material_layout.h"
#include "kernels/util/frame.cl"
#include "kernels/util/math.cl"
#include "kernels/util/trig.cl"

/* The casters' cones from a vertex: the W = 1 forms (caustic_cones_l1, caustic_cones_holding_l1) */
#define FC_LW 1
#include "kernels/lanes/lanes_open.cl"
#include "kernels/integrator/caustic_cones_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

/* The cones' total solid angle (sr) at and above which a vertex draws the full fraction toward
 * them; below, a share in proportion (glass far off seldom focuses light here, and every
 * guided direction costs the BSDF's own samples elsewhere, and a guided path through glass
 * costs more time than a cosine one). 1 sr: a ball fills it within about 1.85 radii of its
 * centre. On glass_metal_sky it renders 1.09x the samples of 0.5 sr with lower error in every
 * band of the image, where 1.5 and 2 sr render more still but leave the floor's caustics
 * noisier (docs/performance.md, "The guide's full share at 1 sr"). */
#ifndef FC_CAUSTIC_GUIDE_FULL
#define FC_CAUSTIC_GUIDE_FULL 1.0f
#endif

/* The guide's share at a glossy vertex, relative to a Lambertian one's. Seen in a rough metal,
 * the sun reflected off a glass ball (its glint) or through it is found only by the BSDF's
 * samples (the shadow ray stops at the glass), rarely and then as a firefly of the sun's whole
 * radiance; a small share of directions toward the glass puts the mixture's density there (the
 * sample's weight divides by it), while most of the glossy lobe's own samples stay. */
#ifndef FC_CAUSTIC_GUIDE_GLOSSY
#define FC_CAUSTIC_GUIDE_GLOSSY 0.2f
#endif
/* The share of a glossy vertex's lens guide draws aimed at the ball's glint rather than
 * through the ball. */
#ifndef FC_LENS_GLINT
#define FC_LENS_GLINT 0.5f
#endif

/* The guide's share at a vertex of material m, relative to the scene's: 1 where its BSDF is a
 * Lambertian lobe and no more (the packet path's lanes that keep no material of their own),
 * FC_CAUSTIC_GUIDE_GLOSSY where it is a plain base (a rough microfacet lobe, perhaps over a
 * Lambertian one: no delta lobe, no layer), 0 for others. */
inline float caustic_guide_receiver(const FcMaterial* m) {
    if (bsdf_layered(m)) return 0.0f;
    if (m->diffuse_model == FC_DIFFUSE_LAMBERT && m->specular_model == FC_SPECULAR_NONE) return 1.0f;
    return bsdf_plain(m) ? FC_CAUSTIC_GUIDE_GLOSSY : 0.0f;
}

/* The lens guide's share aimed at the balls' glints at a vertex of the receiver's share:
 * FC_LENS_GLINT at glossy vertices, none at Lambertian ones (whose glints, the sun reflected
 * off a ball onto the floor, are faint: F of a few hundredths spread wide). */
inline float caustic_guide_glint(float share) { return share < 1.0f ? FC_LENS_GLINT : 0.0f; }

/* ---- the lens guide ---- */

/* asin(x) for x in [0, 1], by atan2_fast (1.7e-7 relative). */
inline float lens_asin(float x) { return atan2_fast(x, safe_sqrt((1.0f - x) * (1.0f + x))); }

/* (sin, cos) of an angle in radians, by sincos_turns. */
inline float2 lens_sincos(float a) { return sincos_turns(a * (0.5f * FC_INV_PI)); }

/* The largest alpha the lens guide draws: the ball's rim, less a thousandth. At the rim
 * dG/dalpha is infinite and the density there hangs on the last bits of alpha (the sampling's
 * and the evaluation's would disagree); these grazing rays mostly reflect anyway. */
inline float lens_reach(float r, float dc) { return 0.999f * lens_asin(fmin(r / dc, 1.0f)); }

/* One ball (radius r, relative index n) seen from distance dc = k r, in the angle of incidence
 * theta at its surface (sin(theta) = b / r = k sin(alpha)), where the turn is smooth up to the
 * rim:
 *     G(theta) = asin(sin(theta) / k) - 2 (theta - asin(sin(theta) / n)),
 *     G'(theta) = cos(theta) (1 / sqrt(k^2 - sin^2) + 2 / sqrt(n^2 - sin^2)) - 2,
 *     G''(theta) = sin(theta) sum_m w_m / sqrt(m^2 - sin^2) (cos^2(theta) / (m^2 - sin^2) - 1)
 * (m = k, n; w = 1, 2), and each bracket is negative (k, n > 1): G is concave on the whole
 * range, rising from G(0) = 0 while G'(0) = 1 / k + 2 / n - 2 > 0, to its maximum m_top at
 * theta_top, then falling to m_end at the range's end theta_end. So G = +phi has a root on
 * the rising side where phi < m_top and one on the falling side where also m_end < phi, and
 * G = -phi one on the falling side where m_end < -phi: the roots' count is known without a
 * search, and Newton's method approaches each root monotonically from the end of its side
 * where G is below the target (the tangent of a concave function lies above it). */
typedef struct {
    float dc, r, n, k;
    float alpha_end, theta_end;
    float theta_top, m_top, m_end;
    float r_end; /* the glint's turn at theta_end */
} Lens;

/* G(theta) from sin(theta) and theta. */
inline float lens_turn(const Lens* l, float s, float theta) {
    return lens_asin(s / l->k) - 2.0f * (theta - lens_asin(s / l->n));
}

/* G'(theta) from sin(theta) and cos(theta). */
inline float lens_slope(const Lens* l, float s, float c) {
    const float s2 = s * s;
    return c * (rsqrt(fmax(l->k * l->k - s2, 1e-12f)) + 2.0f * rsqrt(l->n * l->n - s2)) - 2.0f;
}

/* The ball's glint, the sun reflected off its surface: a ray at incidence theta is turned by
 * pi - 2 theta, so it leaves at
 *     R(theta) = asin(sin(theta) / k) + pi - 2 theta
 * from the axis, on its own side; R'(theta) = cos(theta) / sqrt(k^2 - sin^2) - 2 < 0 and
 * R'' = sin(theta) / sqrt(k^2 - sin^2) (cos^2(theta) / (k^2 - sin^2) - 1) < 0: R falls, concave,
 * from pi to r_end, and a direction phi > r_end has one root. */
inline float glint_turn(const Lens* l, float s, float theta) { return lens_asin(s / l->k) + FC_PI - 2.0f * theta; }

inline float glint_slope(const Lens* l, float s, float c) {
    return c * rsqrt(fmax(l->k * l->k - s * s, 1e-12f)) - 2.0f;
}

inline Lens lens_of(float dc, float r, float n) {
    Lens l;
    l.dc = dc;
    l.r = r;
    l.n = n;
    l.k = fmax(dc / r, 1.0f);
    l.alpha_end = lens_reach(r, dc);
    const float s_end = fmin(l.k * lens_sincos(l.alpha_end).x, 1.0f);
    l.theta_end = lens_asin(s_end);
    const float c_end = safe_sqrt((1.0f - s_end) * (1.0f + s_end));
    l.m_end = lens_turn(&l, s_end, l.theta_end);
    l.r_end = glint_turn(&l, s_end, l.theta_end);
    /* G' as a function of c = cos(theta) rises with c: its zero, if inside, by Newton's
     * method safeguarded by bisection */
    if (!(lens_slope(&l, 0.0f, 1.0f) > 0.0f)) {
        l.theta_top = 0.0f;
        l.m_top = 0.0f;
    } else if (lens_slope(&l, s_end, c_end) >= 0.0f) {
        l.theta_top = l.theta_end;
        l.m_top = l.m_end;
    } else {
        const float kk = l.k * l.k - 1.0f, nn = n * n - 1.0f;
        float lo = c_end, hi = 1.0f, c = c_end;
        for (int i = 0; i < 16; ++i) {
            const float a = rsqrt(fmax(kk + c * c, 1e-12f)), b = rsqrt(nn + c * c);
            const float f = c * (a + 2.0f * b) - 2.0f;
            if (f < 0.0f) lo = c;
            else hi = c;
            const float df = kk * a * a * a + 2.0f * nn * b * b * b;
            float next = c - f / df;
            if (!(next >= lo && next <= hi)) next = 0.5f * (lo + hi);
            const bool done = fabs(next - c) <= 1e-6f;
            c = next;
            if (done) break;
        }
        const float s = safe_sqrt((1.0f - c) * (1.0f + c));
        l.theta_top = atan2_fast(s, c);
        l.m_top = lens_turn(&l, s, l.theta_top);
    }
    return l;
}

/* How many directions leave toward an environment direction phi from the axis. */
inline uint lens_count(const Lens* l, float phi) {
    return (phi < l->m_top ? 1u : 0u) + (l->m_end < phi && phi < l->m_top ? 1u : 0u) + (l->m_end < -phi ? 1u : 0u);
}

/* The root of G = target in [lo, hi], where G rises (rising) or falls: Newton's method from the
 * end where G is below the target (there it approaches monotonically), safeguarded by
 * bisection. */
inline float lens_solve(const Lens* l, float target, float lo, float hi, bool rising, bool glint) {
    float x = rising ? lo : hi;
    for (int i = 0; i < 16; ++i) {
        const float2 sc = lens_sincos(x);
        const float f = (glint ? glint_turn(l, sc.x, x) : lens_turn(l, sc.x, x)) - target;
        /* the turn to its rounding error (the direction it leaves along is then that close) */
        if (fabs(f) <= 1e-6f) break;
        if ((f < 0.0f) == rising) lo = x;
        else hi = x;
        float next = x - f / (glint ? glint_slope(l, sc.x, sc.y) : lens_slope(l, sc.x, sc.y));
        if (!(next >= lo && next <= hi)) next = 0.5f * (lo + hi);
        const bool done = fabs(next - x) <= 1e-6f;
        x = next;
        if (done) break;
    }
    return x;
}

/* The environment direction s on the ball's plane: its angle phi from the axis and the unit e
 * toward it (false where s is along the axis). */
inline bool lens_plane(float3 axis, float3 s, float* phi, float3* e) {
    const float c = clamp(dot(s, axis), -1.0f, 1.0f);
    const float3 perp = s - c * axis;
    const float len = length(perp);
    if (!(len > 1e-6f)) return false;
    *e = perp / len;
    *phi = atan2_fast(len, c);
    return true;
}

/* The density at the direction alpha from the axis, of incidence theta (sine s, cosine c),
 * that the ray leaving at turn (G or R, of slope dturn/dtheta) and count roots of it give:
 * pdf_s |sin(turn) dturn/dalpha| / sin(alpha) / count, with dturn/dalpha = slope k cos(alpha) /
 * cos(theta), pdf_s the environment's density at the direction it leaves along. */
inline float lens_root_density(const Lens* l, float pdf_s, uint count, float alpha, float c, float turn, float slope) {
    if (count == 0u) return 0.0f;
    const float2 sa = lens_sincos(alpha);
    const float d = slope * l->k * sa.y / fmax(c, 1e-7f);
    const float jacobian = alpha > 1e-6f ? fabs(lens_sincos(turn).x * d) / sa.x : d * d;
    return pdf_s * jacobian / (float)count;
}

/* The lens guide's density of ball l (seen along axis) at the direction alpha from the axis
 * toward e, of incidence theta (sine s): a share glint of it the glint's, the rest the way
 * through the ball's. through: the environment's density at the direction the ray through the
 * ball leaves along where the caller has it (lens_sample's draw through the ball: the direction
 * drawn, which the root turns to within 1e-6), else negative (looked up here). */
inline float lens_density_at(__constant const FcEnvironment* env, __global const float4* texels,
                             __global const float* dist, const Lens* l, float3 axis, float3 e, float alpha, float s,
                             float theta, float glint, float through) {
    const float c = safe_sqrt((1.0f - s) * (1.0f + s));
    float density = 0.0f;
    const float turn = lens_turn(l, s, theta);
    const float2 st = lens_sincos(turn);
    const float pdf_t = through >= 0.0f ? through : env_pdf(env, texels, dist, st.y * axis + st.x * e);
    if (pdf_t > 0.0f)
        density += (1.0f - glint) *
                   lens_root_density(l, pdf_t, lens_count(l, fabs(turn)), alpha, c, turn, lens_slope(l, s, c));
    if (!(glint > 0.0f)) return density;
    const float turn_g = glint_turn(l, s, theta);
    const float2 sg = lens_sincos(turn_g);
    const float pdf_g = env_pdf(env, texels, dist, sg.y * axis + sg.x * e);
    if (pdf_g > 0.0f) density += glint * lens_root_density(l, pdf_g, 1u, alpha, c, turn_g, glint_slope(l, s, c));
    return density;
}

/* The density of the lens guide of ball (c, n) at wi, as lens_sample draws it, before the
 * pick among the lenses. */
inline float lens_density(__constant const FcEnvironment* env, __global const float4* texels,
                          __global const float* dist, float4 ball, float n, float glint, float3 p, float3 wi) {
    const float3 pc = ball.xyz - p;
    const float dc = length(pc), r = ball.w;
    const float3 axis = pc / dc;
    float alpha;
    float3 e;
    if (!lens_plane(axis, wi, &alpha, &e) || !(alpha < lens_reach(r, dc))) return 0.0f;
    const Lens l = lens_of(dc, r, n);
    const float s = fmin(l.k * lens_sincos(alpha).x, 1.0f);
    return lens_density_at(env, texels, dist, &l, axis, e, alpha, s, lens_asin(s), glint, -1.0f);
}

/* A direction whose ray, through ball (c, n) or reflected off it (its glint, with probability
 * glint), leaves along an environment direction drawn by u; u_root picks the way and the root.
 * False where there is none. *density: lens_density's at it. */
inline bool lens_sample(__constant const FcEnvironment* env, __global const float4* texels, __global const float* dist,
                        float4 ball, float n, float glint, float3 p, float2 u, float u_root, float3* wi,
                        float* density) {
    float3 s;
    float pdf_s;
    env_sample(env, texels, dist, u, &s, &pdf_s);
    if (!(pdf_s > 0.0f)) return false;
    const float3 pc = ball.xyz - p;
    const float dc = length(pc), r = ball.w;
    const float3 axis = pc / dc;
    float phi;
    float3 e;
    if (!lens_plane(axis, s, &phi, &e)) return false;
    const Lens l = lens_of(dc, r, n);
    float theta;
    const bool through = !(u_root < glint);
    if (!through) {
        /* the glint: one root where phi is past r_end */
        if (!(phi > l.r_end)) return false;
        theta = lens_solve(&l, phi, 0.0f, l.theta_end, false, true);
    } else {
        const uint count = lens_count(&l, phi);
        if (count == 0u) return false;
        /* the roots in order: on the rising side (+phi), on the falling side (+phi), (-phi) */
        const bool rising = phi < l.m_top, falling = rising && l.m_end < phi;
        const float v = (u_root - glint) / (1.0f - glint);
        const uint j = min((uint)(v * (float)count), count - 1u);
        if (rising && j == 0u) theta = lens_solve(&l, phi, 0.0f, l.theta_top, true, false);
        else if (falling && j == 1u) theta = lens_solve(&l, phi, l.theta_top, l.theta_end, false, false);
        else {
            e = -e;
            theta = lens_solve(&l, -phi, l.theta_top, l.theta_end, false, false);
        }
    }
    const float st = lens_sincos(theta).x;
    const float alpha = lens_asin(fmin(st / l.k, 1.0f));
    const float2 sa = lens_sincos(alpha);
    *wi = normalize(sa.y * axis + sa.x * e);
    *density = lens_density_at(env, texels, dist, &l, axis, e, alpha, st, theta, glint, through ? pdf_s : -1.0f);
    return true;
}

/* ---- the mixture ---- */

/* A vertex's mixture: g (0 where it is not guided), the lens share h, the cones' total, the
 * lenses that count, the point and normal. */
typedef struct {
    float g;
    float h;
    float glint; /* the lens guide's share aimed at the balls' glints */
    float total;
    uint lenses;
    uint casters;   /* the casters that count, bit i for caster i (caustic_cones) */
    uint lens_bits; /* the lenses among them */
    float3 p;
    float3 n;
} CausticGuide;

inline CausticGuide caustic_guide_none(void) {
    CausticGuide c;
    c.g = c.h = c.glint = c.total = 0.0f;
    c.lenses = c.casters = c.lens_bits = 0u;
    c.p = c.n = (float3)(0.0f);
    return c;
}

/* The mixture at p (shading normal n) of the guide's share `fraction`, from the casters' cones
 * there (caustic_cones: their total solid angle, the casters that count, the lenses among them). */
inline CausticGuide caustic_guide_of_cones(float fraction, float glint, float total, uint casters, uint lens_bits,
                                           float3 p, float3 n) {
    CausticGuide c = caustic_guide_none();
    if (!(fraction > 0.0f) || !(total > 0.0f)) return c;
    c.p = p;
    c.n = n;
    c.glint = glint;
    c.total = total;
    c.casters = casters;
    c.lens_bits = lens_bits;
    c.lenses = popcount(lens_bits);
    c.g = fraction * fmin(total * (1.0f / FC_CAUSTIC_GUIDE_FULL), 1.0f);
    c.h = c.lenses == 0u ? 0.0f : c.lenses == popcount(casters) ? 1.0f : 0.5f;
    return c;
}

/* The mixture at a vertex whose BSDF caustic_guide_receiver takes, at p with shading normal n
 * (env: whether the environment can be sampled, for the lenses). */
inline CausticGuide caustic_guide_of_receiver(__global const float4* casters, uint count, float fraction, float glint,
                                              bool env, float3 p, float3 n) {
    if (!(fraction > 0.0f)) return caustic_guide_none();
    uint bits, lens_bits;
    const float total = caustic_cones_l1(casters, count, env, p, n, &bits, &lens_bits);
    return caustic_guide_of_cones(fraction, glint, total, bits, lens_bits, p, n);
}

/* Whether a render's lens guides can draw: the environment is a light (env_sample). */
inline bool caustic_guide_lenses_draw(__constant const FcRenderParams* P) {
    return FC_HAS_ENVIRONMENT && P->environment_light >= 0;
}

/* The mixture at a vertex of material m in a render of parameters P. */
inline CausticGuide caustic_guide_at(__constant const FcRenderParams* P, __global const float4* casters,
                                     const FcMaterial* m, float3 p, float3 n) {
    const float share = caustic_guide_receiver(m);
    return share > 0.0f ? caustic_guide_of_receiver(casters, P->caster_count, P->caster_fraction * share,
                                                    caustic_guide_glint(share), caustic_guide_lenses_draw(P), p, n)
                        : caustic_guide_none();
}

/* What caustic_guide_sample drew: the caster of the lens guide (-1: another way) and its
 * density there (lens_density's, from the sampling's own roots). */
typedef struct {
    int lens;
    float density;
} GuideDraw;

/* The guide's density at wi (unit, world). Without `lenses`, the lens guide's share is left out:
 * for a light at infinity, whose shadow ray a lens's cone would have stopped (the ray meets
 * the ball wherever the lens guide's density is not 0), so the weight of an unblocked light
 * sample is the same. */
inline float caustic_guide_density_held(__constant const FcEnvironment* env, __global const float4* texels,
                                        __global const float* dist, __global const float4* casters,
                                        const CausticGuide* c, float3 wi, bool lenses, const GuideDraw* drawn,
                                        uint held, uint inside) {
    float lens = 0.0f;
    if (lenses) {
        for (uint rest = c->lens_bits; rest; rest &= rest - 1u) {
            const uint i = lowest_bit(rest);
            /* a lens's density is 0 outside its cone (lens_reach is inside it) */
            if (drawn && drawn->lens == (int)i) lens += drawn->density;
            else if ((inside >> i) & 1u)
                lens += lens_density(env, texels, dist, casters[2u * i], casters[2u * i + 1u].x, c->glint, c->p, wi);
        }
    }
    const float cone = (float)held / c->total;
    return c->h >= 1.0f ? lens / (float)c->lenses
                        : (1.0f - c->h) * cone + (c->lenses > 0u ? c->h * lens / (float)c->lenses : 0.0f);
}

/* The guide's density at wi (caustic_guide_density_held's), its cones tested here. */
inline float caustic_guide_density(__constant const FcEnvironment* env, __global const float4* texels,
                                   __global const float* dist, __global const float4* casters, uint count,
                                   const CausticGuide* c, float3 wi, bool lenses, const GuideDraw* drawn) {
    uint inside;
    const uint held = caustic_cones_holding_l1(casters, count, c->casters, c->p, wi, &inside);
    return caustic_guide_density_held(env, texels, dist, casters, c, wi, lenses, drawn, held, inside);
}

/* Russian roulette's scale for a direction the guide's mixture sampled (path.cl's rr_scale):
 * the mixture's density pdf_mix over the BSDF's own pdf_own at it, so that roulette judges the
 * path by the weight the BSDF alone would have given it; 1 where the BSDF's is 0 (its f is 0
 * too). */
inline float roulette_guide_scale(float pdf_mix, float pdf_own) { return pdf_own > 0.0f ? pdf_mix / pdf_own : 1.0f; }

/* A direction drawn by the guide: v picks the lens or cone guide and, rescaled, the caster (and
 * the root); u draws the environment direction or the point in the cone. False: nothing drawn. */
inline bool caustic_guide_sample(__constant const FcEnvironment* env, __global const float4* texels,
                                 __global const float* dist, __global const float4* casters, const CausticGuide* c,
                                 float v, float2 u, float3* wi, GuideDraw* drawn) {
    drawn->lens = -1;
    drawn->density = 0.0f;
    if (v < c->h) {
        /* a lens, each as likely */
        const float t = fmin(v / c->h, FC_ONE_MINUS_EPSILON) * (float)c->lenses;
        const uint pick = min((uint)t, c->lenses - 1u);
        const float u_root = t - (float)pick;
        uint rest = c->lens_bits;
        for (uint seen = 0u; seen < pick; ++seen) rest &= rest - 1u;
        if (!rest) return false;
        const uint i = lowest_bit(rest);
        drawn->lens = (int)i;
        return lens_sample(env, texels, dist, casters[2u * i], casters[2u * i + 1u].x, c->glint, c->p, u, u_root, wi,
                           &drawn->density);
    }
    /* a cone, in proportion to its solid angle */
    float t = fmin((v - c->h) / (1.0f - c->h), FC_ONE_MINUS_EPSILON) * c->total;
    float3 axis = c->n, pc;
    float omc = 0.0f;
    for (uint rest = c->casters; rest; rest &= rest - 1u) {
        const float4 s = casters[2u * lowest_bit(rest)];
        pc = s.xyz - c->p;
        const float o = caustic_cone_omc_l1(s, vec3_dot_l1(pc, pc));
        const float w = 2.0f * FC_PI * o;
        axis = normalize(pc);
        omc = o;
        if (t < w) break;
        t -= w;
    }
    /* uniform in the cone: 1 - cos(theta) = omc u.x, sin from it without cancellation */
    const float q = omc * u.x;
    const float cos_t = 1.0f - q, sin_t = safe_sqrt(q * (2.0f - q));
    const float2 sc = sincos_turns(u.y);
    const Frame f = frame_from_normal(axis);
    *wi = normalize(frame_to_world(&f, (float3)(sin_t * sc.y, sin_t * sc.x, cos_t)));
    return true;
}

/* The mixture's density from the BSDF's and the guide's at the same direction. */
inline float caustic_guide_mix(const CausticGuide* c, float bsdf_pdf, float guide_pdf) {
    return (1.0f - c->g) * bsdf_pdf + c->g * guide_pdf;
}

/* The mixture's density at wi (world), given the BSDF's there (exactly bsdf_pdf unguided);
 * `lenses` as caustic_guide_density takes it, and `drawn` (or 0) what caustic_guide_sample drew
 * for wi. */
inline float caustic_guide_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, __global const float4* casters, uint count,
                               const CausticGuide* c, float bsdf_pdf, float3 wi, bool lenses, const GuideDraw* drawn) {
    if (!(c->g > 0.0f)) return bsdf_pdf;
    return caustic_guide_mix(c, bsdf_pdf,
                             caustic_guide_density(env, texels, dist, casters, count, c, wi, lenses, drawn));
}

#endif
