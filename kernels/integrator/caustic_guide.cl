/* Sampling toward glass at Lambertian vertices: caustics seen by diffuse surfaces.
 *
 * Light that reaches a diffuse surface through glass (the sun focused by a glass ball onto
 * the floor) is found only by BSDF sampling: next-event estimation's shadow ray stops at the
 * glass. With the cosine lobe alone such a path is rare and, when found, a firefly; on
 * glass_metal_sky these few samples are nearly all of the image's error. So at a vertex whose
 * BSDF is a Lambertian lobe and no more (caustic_guide_receiver), the direction is drawn from
 * a one-sample mixture (Veach 1997, section 9.2.4): with probability 1 - g by the BSDF, with
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
 *   are the roots of G(alpha) = +-phi, phi the environment direction's angle from the axis:
 *   bracketed on FC_LENS_STEPS steps of [0, lens_reach] (the rim less a thousandth), then
 *   bisected; one of them is taken. Its density is the environment's at the direction it
 *   leaves along times the Jacobian |sin G G'(alpha)| / sin(alpha) (the map keeps the azimuth
 *   about the axis), over the roots' count and the lenses'. Two roots in one step are never
 *   drawn and their density is 0 (the evaluation finds the roots the same way).
 * - the cone guide (share 1 - h): uniform inside the cone that a glass object's bounding
 *   sphere subtends (pbrt-v4's cone sampling, as kernels/lights/sphere_light.cl), the object
 *   picked in proportion to its cone's solid angle: for glass that is not a smooth ball.
 *
 * The density of the whole mixture is what the sample's weight divides by and what MIS weighs
 * against light sampling, on both sides (for a light at infinity, without the lens share:
 * caustic_guide_density). g is the scene's share scaled down where the cones fill less than
 * FC_CAUSTIC_GUIDE_FULL; h is 1 where every caster that counts is a lens, 1/2 where some are,
 * else 0. The cosine lobe keeps every direction possible, so
 * the estimate stays unbiased whatever the guide; a guided direction below the surface ends
 * the path (its integrand is zero there).
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

/* The cones' total solid angle (sr) at and above which a vertex draws the full fraction toward
 * them; below, a share in proportion (glass far off seldom focuses light here, and every
 * guided direction costs the BSDF's own samples elsewhere). */
#ifndef FC_CAUSTIC_GUIDE_FULL
#define FC_CAUSTIC_GUIDE_FULL 0.5f
#endif
/* Steps of the lens guide's bracketing, and its bisection's halvings. */
#define FC_LENS_STEPS 16
#define FC_LENS_HALVINGS 20

/* Whether the BSDF of m is sampled with the mixture: a Lambertian lobe, no specular lobe, no
 * layer (the packet path's lanes that keep no material of their own). */
inline bool caustic_guide_receiver(const FcMaterial* m) {
    return m->diffuse_model == FC_DIFFUSE_LAMBERT && m->specular_model == FC_SPECULAR_NONE && !bsdf_layered(m);
}

/* Caster c's cone seen from p: its axis and 1 - cos(theta_max); returns its solid angle, 0 where
 * it does not count (p inside the sphere, or the whole cone below the plane of n). */
inline float caustic_cone(float4 c, float3 p, float3 n, float3* axis, float* one_minus_cos) {
    const float3 pc = c.xyz - p;
    const float dc2 = dot(pc, pc), r = c.w;
    if (!(dc2 > r * r * (1.0f + 1e-3f))) return 0.0f;
    const float dc = sqrt(dc2);
    *axis = pc / dc;
    /* below the horizon: the axis more than 90 degrees + theta_max from n */
    if (!(dot(*axis, n) > -r / dc)) return 0.0f;
    *one_minus_cos = sphere_cone_one_minus_cos(r, dc2);
    return 2.0f * FC_PI * *one_minus_cos;
}

/* ---- the lens guide ---- */

/* asin(x) for x in [0, 1], by atan2_fast (1.7e-7 relative). */
inline float lens_asin(float x) { return atan2_fast(x, safe_sqrt((1.0f - x) * (1.0f + x))); }

/* (sin, cos) of an angle in radians, by sincos_turns. */
inline float2 lens_sincos(float a) { return sincos_turns(a * (0.5f * FC_INV_PI)); }

/* A ball of radius r and relative index n seen from distance dc: G(alpha). */
inline float lens_turn(float alpha, float dc, float r, float n) {
    const float b = fmin(dc * lens_sincos(alpha).x, r);
    return alpha - 2.0f * (lens_asin(b / r) - lens_asin(b / (n * r)));
}

/* G'(alpha) = 1 - D'(b) dc cos(alpha), D'(b) = 2 (1 / sqrt(r^2 - b^2) - 1 / sqrt(n^2 r^2 - b^2)). */
inline float lens_slope(float alpha, float dc, float r, float n) {
    const float2 sc = lens_sincos(alpha);
    const float b = fmin(dc * sc.x, r);
    const float x = b / r, y = b / (n * r);
    const float dd = 2.0f * (1.0f / (r * safe_sqrt(1.0f - x * x)) - 1.0f / (n * r * safe_sqrt(1.0f - y * y)));
    return 1.0f - dd * dc * sc.y;
}

/* The largest alpha the lens guide draws: the ball's rim, less a thousandth. At the rim G'
 * is infinite and G's roots, and the density there, hang on the last bits of alpha (the
 * sampling's and the evaluation's would disagree); these grazing rays mostly reflect anyway. */
inline float lens_reach(float r, float dc) { return 0.999f * lens_asin(fmin(r / dc, 1.0f)); }

/* G on the FC_LENS_STEPS + 1 points alpha_max k / FC_LENS_STEPS of one ball seen from one point. */
typedef struct {
    float g[FC_LENS_STEPS + 1];
    float alpha_max, dc, r, n;
} LensScan;

inline void lens_scan(LensScan* l, float alpha_max, float dc, float r, float n) {
    l->alpha_max = alpha_max;
    l->dc = dc;
    l->r = r;
    l->n = n;
    l->g[0] = 0.0f;
    for (int k = 1; k <= FC_LENS_STEPS; ++k)
        l->g[k] = lens_turn(alpha_max * ((float)k / (float)FC_LENS_STEPS), dc, r, n);
}

/* Whether step k (from point k - 1 to k) brackets a root of G = target. */
inline bool lens_brackets(const LensScan* l, int k, float target) {
    return (l->g[k - 1] < target) != (l->g[k] < target);
}

/* The roots of G = target the scan brackets. */
inline uint lens_count(const LensScan* l, float target) {
    uint found = 0u;
    for (int k = 1; k <= FC_LENS_STEPS; ++k) found += lens_brackets(l, k, target) ? 1u : 0u;
    return found;
}

/* The root of G = target in step k, by bisection. */
inline float lens_bisect(const LensScan* l, int k, float target) {
    float lo = l->alpha_max * ((float)(k - 1) / (float)FC_LENS_STEPS);
    float hi = l->alpha_max * ((float)k / (float)FC_LENS_STEPS);
    const bool below = l->g[k - 1] < target;
    for (int i = 0; i < FC_LENS_HALVINGS; ++i) {
        const float mid = 0.5f * (lo + hi);
        if ((lens_turn(mid, l->dc, l->r, l->n) < target) == below) lo = mid;
        else hi = mid;
    }
    return 0.5f * (lo + hi);
}

/* The root of index j (in order of alpha) of G = target. */
inline float lens_root(const LensScan* l, float target, uint j) {
    for (int k = 1; k <= FC_LENS_STEPS; ++k) {
        if (!lens_brackets(l, k, target)) continue;
        if (j == 0u) return lens_bisect(l, k, target);
        j -= 1u;
    }
    return 0.0f;
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

/* The lens guide's density at the root alpha (turned by G = turn) of a direction of the
 * environment's density pdf_s that has `count` roots: pdf_s |sin G G'(alpha)| / sin(alpha) / count. */
inline float lens_root_density(float pdf_s, uint count, float alpha, float turn, float dc, float r, float n) {
    const float slope = lens_slope(alpha, dc, r, n);
    const float jacobian = alpha > 1e-6f ? fabs(lens_sincos(turn).x * slope) / lens_sincos(alpha).x : slope * slope;
    return pdf_s * jacobian / (float)count;
}

/* The density of the lens guide of ball (c, n) at wi, as lens_sample draws it, before the
 * pick among the lenses. */
inline float lens_density(__constant const FcEnvironment* env, __global const float4* texels,
                          __global const float* dist, float4 c, float n, float3 p, float3 wi) {
    const float3 pc = c.xyz - p;
    const float dc = length(pc), r = c.w;
    const float3 axis = pc / dc;
    const float alpha_max = lens_reach(r, dc);
    float alpha;
    float3 e;
    if (!lens_plane(axis, wi, &alpha, &e) || !(alpha < alpha_max)) return 0.0f;
    const float turn = lens_turn(alpha, dc, r, n);
    const float2 sc = lens_sincos(turn);
    const float pdf_s = env_pdf(env, texels, dist, sc.y * axis + sc.x * e);
    if (!(pdf_s > 0.0f)) return 0.0f;
    /* is alpha the root the scan finds for the direction it leaves along (G = +phi on e's
     * side, -phi beyond)? Its own step must bracket turn, and the bisection there end at it. */
    LensScan l;
    lens_scan(&l, alpha_max, dc, r, n);
    const float at = alpha / alpha_max * (float)FC_LENS_STEPS;
    const int k = clamp((int)at + 1, 1, FC_LENS_STEPS);
    bool held = lens_brackets(&l, k, turn) && fabs(lens_bisect(&l, k, turn) - alpha) <= alpha_max * 1e-4f;
    /* a root at a step's end: the bisection of the step beside may be the one that found it */
    const int side = at - (float)(k - 1) < 0.5f ? k - 1 : k + 1;
    if (!held && side >= 1 && side <= FC_LENS_STEPS && lens_brackets(&l, side, turn))
        held = fabs(lens_bisect(&l, side, turn) - alpha) <= alpha_max * 1e-4f;
    if (!held) return 0.0f;
    return lens_root_density(pdf_s, lens_count(&l, turn) + lens_count(&l, -turn), alpha, turn, dc, r, n);
}

/* A direction whose ray leaves ball (c, n) along an environment direction drawn by u; u_root
 * picks the root. False where there is none. *density: lens_density's at it, from the same
 * scan. */
inline bool lens_sample(__constant const FcEnvironment* env, __global const float4* texels, __global const float* dist,
                        float4 c, float n, float3 p, float2 u, float u_root, float3* wi, float* density) {
    float3 s;
    float pdf_s;
    env_sample(env, texels, dist, u, &s, &pdf_s);
    if (!(pdf_s > 0.0f)) return false;
    const float3 pc = c.xyz - p;
    const float dc = length(pc), r = c.w;
    const float3 axis = pc / dc;
    float phi;
    float3 e;
    if (!lens_plane(axis, s, &phi, &e)) return false;
    LensScan l;
    lens_scan(&l, lens_reach(r, dc), dc, r, n);
    const uint plus = lens_count(&l, phi), minus = lens_count(&l, -phi);
    if (plus + minus == 0u) return false;
    const uint j = min((uint)(u_root * (float)(plus + minus)), plus + minus - 1u);
    float root;
    if (j < plus) root = lens_root(&l, phi, j);
    else {
        root = lens_root(&l, -phi, j - plus);
        e = -e;
    }
    const float2 sc = lens_sincos(root);
    *wi = normalize(sc.y * axis + sc.x * e);
    *density = lens_root_density(pdf_s, plus + minus, root, j < plus ? phi : -phi, dc, r, n);
    return true;
}

/* ---- the mixture ---- */

/* A vertex's mixture: g (0 where it is not guided), the lens share h, the cones' total, the
 * lenses that count, the point and normal. */
typedef struct {
    float g;
    float h;
    float total;
    uint lenses;
    float3 p;
    float3 n;
} CausticGuide;

inline CausticGuide caustic_guide_none(void) {
    CausticGuide c;
    c.g = c.h = c.total = 0.0f;
    c.lenses = 0u;
    c.p = c.n = (float3)(0.0f);
    return c;
}

/* The mixture at a vertex whose BSDF caustic_guide_receiver takes, at p with shading normal n
 * (env: whether the environment can be sampled, for the lenses). */
inline CausticGuide caustic_guide_of_receiver(__global const float4* casters, uint count, float fraction, bool env,
                                              float3 p, float3 n) {
    CausticGuide c = caustic_guide_none();
    if (!(fraction > 0.0f)) return c;
    c.p = p;
    c.n = n;
    uint counting = 0u;
    for (uint i = 0; i < count; ++i) {
        float3 axis;
        float omc;
        const float w = caustic_cone(casters[2u * i], p, n, &axis, &omc);
        if (!(w > 0.0f)) continue;
        c.total += w;
        counting += 1u;
        if (env && casters[2u * i + 1u].x > 1.0f) c.lenses += 1u;
    }
    if (!(c.total > 0.0f)) return c;
    c.g = fraction * fmin(c.total * (1.0f / FC_CAUSTIC_GUIDE_FULL), 1.0f);
    c.h = c.lenses == 0u ? 0.0f : c.lenses == counting ? 1.0f : 0.5f;
    return c;
}

/* Whether a render's lens guides can draw: the environment is a light (env_sample). */
inline bool caustic_guide_lenses_draw(__constant const FcRenderParams* P) {
    return FC_HAS_ENVIRONMENT && P->environment_light >= 0;
}

/* The mixture at a vertex of material m in a render of parameters P. */
inline CausticGuide caustic_guide_at(__constant const FcRenderParams* P, __global const float4* casters,
                                     const FcMaterial* m, float3 p, float3 n) {
    return caustic_guide_receiver(m) ? caustic_guide_of_receiver(casters, P->caster_count, P->caster_fraction,
                                                                 caustic_guide_lenses_draw(P), p, n)
                                     : caustic_guide_none();
}

/* What caustic_guide_sample drew: the caster of the lens guide (-1: another way) and its
 * density there (lens_density's, from the sampling's own scan). */
typedef struct {
    int lens;
    float density;
} GuideDraw;

/* The guide's density at wi (unit, world). Without `lenses`, the lens guide's share is left out:
 * for a light at infinity, whose shadow ray a lens's cone would have stopped (the ray meets
 * the ball wherever the lens guide's density is not 0), so the weight of an unblocked light
 * sample is the same. */
inline float caustic_guide_density(__constant const FcEnvironment* env, __global const float4* texels,
                                   __global const float* dist, __global const float4* casters, uint count,
                                   const CausticGuide* c, float3 wi, bool lenses, const GuideDraw* drawn) {
    uint held = 0u;
    float lens = 0.0f;
    for (uint i = 0; i < count; ++i) {
        float3 axis;
        float omc;
        const float4 s = casters[2u * i];
        if (!(caustic_cone(s, c->p, c->n, &axis, &omc) > 0.0f)) continue;
        if (1.0f - dot(wi, axis) <= omc) held += 1u;
        const float n = casters[2u * i + 1u].x;
        if (!lenses || c->lenses == 0u || !(n > 1.0f)) continue;
        lens += drawn && drawn->lens == (int)i ? drawn->density : lens_density(env, texels, dist, s, n, c->p, wi);
    }
    const float cone = (float)held / c->total;
    return c->h >= 1.0f ? lens / (float)c->lenses
                        : (1.0f - c->h) * cone + (c->lenses > 0u ? c->h * lens / (float)c->lenses : 0.0f);
}

/* A direction drawn by the guide: v picks the lens or cone guide and, rescaled, the caster (and
 * the root); u draws the environment direction or the point in the cone. False: nothing drawn. */
inline bool caustic_guide_sample(__constant const FcEnvironment* env, __global const float4* texels,
                                 __global const float* dist, __global const float4* casters, uint count,
                                 const CausticGuide* c, float v, float2 u, float3* wi, GuideDraw* drawn) {
    drawn->lens = -1;
    drawn->density = 0.0f;
    if (v < c->h) {
        /* a lens, each as likely */
        const float t = fmin(v / c->h, FC_ONE_MINUS_EPSILON) * (float)c->lenses;
        const uint pick = min((uint)t, c->lenses - 1u);
        const float u_root = t - (float)pick;
        uint seen = 0u;
        for (uint i = 0; i < count; ++i) {
            float3 axis;
            float omc;
            const float4 s = casters[2u * i];
            const float n = casters[2u * i + 1u].x;
            if (!(n > 1.0f) || !(caustic_cone(s, c->p, c->n, &axis, &omc) > 0.0f)) continue;
            if (seen == pick) {
                drawn->lens = (int)i;
                return lens_sample(env, texels, dist, s, n, c->p, u, u_root, wi, &drawn->density);
            }
            seen += 1u;
        }
        return false;
    }
    /* a cone, in proportion to its solid angle */
    float t = fmin((v - c->h) / (1.0f - c->h), FC_ONE_MINUS_EPSILON) * c->total;
    float3 axis = c->n, a;
    float omc = 0.0f, o;
    for (uint i = 0; i < count; ++i) {
        const float w = caustic_cone(casters[2u * i], c->p, c->n, &a, &o);
        if (!(w > 0.0f)) continue;
        axis = a;
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

/* The mixture's density at wi (world), given the BSDF's there (exactly bsdf_pdf unguided);
 * `lenses` as caustic_guide_density takes it, and `drawn` (or 0) what caustic_guide_sample drew
 * for wi. */
inline float caustic_guide_pdf(__constant const FcEnvironment* env, __global const float4* texels,
                               __global const float* dist, __global const float4* casters, uint count,
                               const CausticGuide* c, float bsdf_pdf, float3 wi, bool lenses, const GuideDraw* drawn) {
    if (!(c->g > 0.0f)) return bsdf_pdf;
    return (1.0f - c->g) * bsdf_pdf +
           c->g * caustic_guide_density(env, texels, dist, casters, count, c, wi, lenses, drawn);
}

#endif
