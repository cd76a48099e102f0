/* Paths in packets (issue 29): render_pass's paths, FC_PACKET_WIDTH a work-item (8 in float8
 * lanes, 16 in float16 on AVX-512 CPUs), with regeneration (a lane starts the next path when
 * its own ends; Novák et al. 2010), for the programs whose scenes it covers: any material,
 * glass included, textured or not, cut out or not, lit by triangle area lights, the
 * environment and punctual lights, made of triangles and spheres, with the Sobol' sampler, on
 * CPUs with 8- or 16-wide vectors (host/render/packet_paths.hpp picks it; path.cl includes
 * this file when FC_PACKET_PATHS is 1). The lanes' rays, and their shadow rays, meet the
 * triangles' tree and the spheres' together (kernels/trace/packet_trace.cl, packet_sphere.cl:
 * the same tests, so the same hits but where two surfaces tie); the surface and its textures,
 * the emission met (or the environment map's texel, when a ray escapes), the camera ray (in
 * lanes when three or more paths begin at once: kernels/camera/camera_lanes.cl), the texel an
 * environment sample picks, a punctual light's sample and the film's sum run per lane through
 * the scalar functions; the sampler, the frame, a triangle light's sample, the environment
 * map's directions (to and from the map's (u, v): kernels/lights/environment_lanes.cl), MIS, a
 * Lambertian BSDF and roulette in lanes,
 * through the lane-generic bodies the scalar path runs at W = 1 (kernels/lanes/packet.cl). In
 * programs with other materials (FC_PACKET_BSDF_PER_LANE), a lane whose material is more than
 * a Lambertian lobe keeps a copy of it, oriented and framed by surface_orient, and its BSDF
 * is evaluated, weighed and sampled per lane by bsdf.cl's own functions, between the lanes'
 * light sample and roulette; in lanes where it is a plain base (kernels/bsdf/plain_base_lanes.cl)
 * or, where FC_PACKET_ROUGH_MIN lanes or more have one, a rough dielectric
 * (kernels/bsdf/dielectric_lanes.cl), the same operations as bsdf.cl's at W = 1. Every sample
 * is the scalar path's, up to the rounding of a few operations written by component here and on
 * float3 there, and the order in which a pixel's samples are added: PacketRender.* demands each
 * pixel within 1e-4 of render_pass's. */
#ifndef FACET_INTEGRATOR_PACKET_PATHS_CL
#define FACET_INTEGRATOR_PACKET_PATHS_CL

#include "kernels/integrator/path.cl"
#include "kernels/lanes/packet.cl"

#define FC_PACKET_W FC_PACKET_WIDTH /* paths a work-item (kernels/shared/render_layout.h) */
/* 1 where some material is more than a Lambertian lobe (host/render/packet_paths.hpp), as
 * every dielectric is */
#ifndef FC_PACKET_BSDF_PER_LANE
#define FC_PACKET_BSDF_PER_LANE FC_HAS_DIELECTRIC
#endif
/* whether each lane keeps its rays' origins (spheres offset their own; refraction leaves from
 * either side) */
#define FC_PACKET_OWN_ORIGINS (FC_HAS_SPHERES || FC_HAS_DIELECTRIC)
#define PATH_ENDED 0xfffffffeu /* depth[j] of a lane whose path ended and is not yet added */

/* The packet's lane types (LFLOAT, LINT, LUINT, LVEC2, LVEC3, LLOAD, LSTORE) and the lane
 * bodies' names (LNAME) at its width, as kernels/lanes/packet.cl instantiated them; closed at
 * the end of this file. */
#define FC_LW FC_PACKET_W
#include "kernels/lanes/lanes_open.cl"
typedef LVEC3 L3;

#define l3 LNAME(vec3)
#define l3_dot LNAME(vec3_dot)
inline L3 l3_load(const float* a) { return l3(LLOAD(a), LLOAD(a + FC_PACKET_W), LLOAD(a + 2 * FC_PACKET_W)); }
inline void l3_store(L3 v, float* a) {
    LSTORE(v.x, a);
    LSTORE(v.y, a + FC_PACKET_W);
    LSTORE(v.z, a + 2 * FC_PACKET_W);
}
inline float3 lane3(const float* a, int j) { return (float3)(a[j], a[FC_PACKET_W + j], a[2 * FC_PACKET_W + j]); }
inline void set_lane3(float* a, int j, float3 v) {
    a[j] = v.x;
    a[FC_PACKET_W + j] = v.y;
    a[2 * FC_PACKET_W + j] = v.z;
}
#include "kernels/integrator/packet_plain.cl"
#include "kernels/integrator/packet_bsdf_merge.cl"
#include "kernels/integrator/packet_dielectric.cl"
#include "kernels/integrator/packet_scene_trace.cl"
#include "kernels/integrator/packet_lights.cl"
#if FC_HAS_DIELECTRIC
#include "kernels/integrator/packet_caustic_guide.cl"
#endif

/* Work-item g renders samples [sample_begin, sample_begin + sample_count) of fc_packet_pixels
 * consecutive pixels of a row (fewer at the row's end): FC_PACKET_W, or a multiple of it when
 * the launch has few samples per pixel, so that each lane gets FC_PACKET_PATHS_PER_LANE paths
 * or more. Their paths form one queue, sample by sample, each sample's pixels in order; a lane
 * takes the queue's next path when its last one ends, whichever pixel that is. So the lanes
 * stay busy until the work-item's last paths, however the path lengths fall among the
 * pixels, and a row's last work-item fills its lanes too. A path's sample is added to its
 * pixel's half in the accumulation buffer as the path ends (the work-item alone writes its
 * pixels in a launch), not in index order. */
__kernel void packet_pass(FC_SCENE_KERNEL_PARAMS, __global float4* accum) {
    const uint run = fc_packet_pixels(FC_PACKET_W, params->width, params->sample_count);
    const uint groups = (params->width + run - 1u) / run;
    uint gid = get_global_id(0);
    uint x0 = (gid % groups) * run;
    uint y = params->row_begin + gid / groups;
    if (gid / groups >= params->row_count || y >= params->height) return;
    SceneView scv = FC_SCENE_VIEW_INIT;
    const SceneView* sc = &scv;
    __constant const FcRenderParams* P = params;
    const uint pixels = params->width * params->height;
    __global float* squares = (__global float*)(accum + 2u * pixels); /* the second moments */

    /* per-lane state, in arrays (lane j at [j], 3-vectors as x[0..W-1] y[W..2W-1] z[2W..3W-1]) */
    float o[3 * FC_PACKET_W], d[3 * FC_PACKET_W], thr[3 * FC_PACKET_W], rad[3 * FC_PACKET_W], p[3 * FC_PACKET_W],
        ng[3 * FC_PACKET_W], ns[3 * FC_PACKET_W], alb[3 * FC_PACKET_W];
#if FC_PACKET_OWN_ORIGINS
    /* the new rays' origin on ng's side (surface_offset: a sphere's hit has its own offset) */
    float org[3 * FC_PACKET_W];
#endif
#if FC_HAS_DIELECTRIC
    /* a lane's origin on the far side (a refraction's), roulette's scale (path.cl's rr_scale:
     * etap^2 of its refractions, the guide's densities over its BSDFs'), and whether its material
     * is a dielectric */
    float orgb[3 * FC_PACKET_W], rr_scale[FC_PACKET_W];
    int trans[FC_PACKET_W];
#endif
    float prev_pdf[FC_PACKET_W], fweight[FC_PACKET_W];
#if FC_PACKET_BSDF_PER_LANE
    /* lanes whose material is more than a Lambertian lobe: the material (textured, oriented),
     * its shading frame (fs, ft and ns) and wo in it, and whether every lobe is a delta */
    FcMaterial mats[FC_PACKET_W];
    float fs[3 * FC_PACKET_W], ft[3 * FC_PACKET_W], wol[3 * FC_PACKET_W];
    int gen[FC_PACKET_W], delta_bsdf[FC_PACKET_W];
    /* lanes whose BSDF is a plain base (bsdf_plain, no layers), evaluated and sampled in lanes
     * (kernels/bsdf/plain_base_lanes.cl) from their parameters */
    PacketPlain pls;
    int plain[FC_PACKET_W];
#if !FC_HAS_TEXTURES
    /* the material whose plain base lane j of pls holds (-1: none): a lane that meets it again
     * keeps it, since without textures a plain base is its material's alone (plain_base_of: a
     * conductor's Fresnel average is eight evaluations of its Fresnel term) */
    int pls_material[FC_PACKET_W];
#endif
#if FC_HAS_DIELECTRIC
    /* lanes whose BSDF is a rough dielectric of the lanes, and their parameters at the vertex
     * (packet_dielectric.cl) */
    PacketRough rds;
    int rough[FC_PACKET_W];
#endif
#endif
#if FC_HAS_TEXTURES
    float plen[FC_PACKET_W]; /* each path's length from the camera: its ray cone (texture filtering) */
#endif
    uint slot[FC_PACKET_W], index[FC_PACKET_W], depth[FC_PACKET_W], seed[FC_PACKET_W], irev[FC_PACKET_W];
    int active[FC_PACKET_W], alive[FC_PACKET_W];
    /* the queue: path q is sample sample_begin + q / pixels of pixel x0 + q % pixels */
    const uint pixels_here = min(run, params->width - x0);
    const uint queue = pixels_here * params->sample_count;
    uint next = 0u;
#if FC_PACKET_BSDF_PER_LANE
    const PlainBase_l1 unplain = packet_unplain(); /* read before a lane's first surface */
#endif
    for (int j = 0; j < FC_PACKET_W; ++j) {
        active[j] = 1;
        alive[j] = 0; /* start a path */
        depth[j] = 0u;
        slot[j] = 0u;
        index[j] = 0u;
        seed[j] = 0u;
        irev[j] = 0u;
#if FC_PACKET_BSDF_PER_LANE
        gen[j] = 0;
        plain[j] = 0;
        packet_plain_set(&pls, j, &unplain);
#if !FC_HAS_TEXTURES
        pls_material[j] = -1;
#endif
#if FC_HAS_DIELECTRIC
        rough[j] = 0;
        packet_rough_clear(&rds, j);
#endif
#endif
    }
    for (;;) {
        /* A: until every lane has a surface to shade or the queue is empty: a finished path is
         * added to its pixel's half and the queue's next path started (per lane); the rays are
         * traced (in a packet: packet_trace_closest) and the emission met added (per lane). A
         * path that ends here (it escapes, or reaches max_depth) is replaced at once and its
         * new ray traced in the next pass, so that the lanes' work below runs on full lanes. */
        uint need = 0u;  /* the lanes whose ray is to be traced */
        uint fresh = 0u; /* the lanes whose path has just begun: their camera ray to make */
        for (int j = 0; j < FC_PACKET_W; ++j)
            if (active[j] && alive[j]) need |= 1u << j;
        for (;;) {
            /* the lanes to refill, in lane order: a mask first, so that the loop does not
             * branch on each lane's flags (which paths ended is as good as random) */
            uint idle = 0u;
            for (int j = 0; j < FC_PACKET_W; ++j)
                if (active[j] && !alive[j]) idle |= 1u << j;
            for (uint rest = idle; rest; rest &= rest - 1u) {
                const int j = (int)lowest_bit(rest);
                if (depth[j] == PATH_ENDED) {
                    const uint at = (index[j] & 1u) * pixels + y * params->width + x0 + slot[j];
                    float4 sum = (float4)(0.0f);
                    float square = 0.0f;
                    film_add_sample(lane3(rad, j), fweight[j], params->clamp, &sum, &square);
                    accum[at] += sum;
                    squares[at] += square;
                    depth[j] = 0u;
                }
                if (next >= queue) {
                    active[j] = 0;
                    continue;
                }
                slot[j] = next % pixels_here;
                index[j] = params->sample_begin + next / pixels_here;
                next += 1u;
                const Sampler sm =
                    sampler_init(params->sampler, params->seed, y * params->width + x0 + slot[j], index[j]);
                seed[j] = sm.seed;
                irev[j] = sm.index_reversed;
                fresh |= 1u << j; /* its camera ray below */
                set_lane3(thr, j, (float3)(1.0f));
                set_lane3(rad, j, (float3)(0.0f));
                prev_pdf[j] = INFINITY;
#if FC_HAS_TEXTURES
                plen[j] = 0.0f;
#endif
#if FC_HAS_DIELECTRIC
                rr_scale[j] = 1.0f;
#endif
                depth[j] = 0u;
                alive[j] = 1;
                need |= 1u << j;
            }
            if (fresh) {
                /* the paths begun: their camera rays, in lanes when there are a few of them
                 * (else per lane: pixel_sample_ray's) */
                if (popcount(fresh) >= 3) {
                    LFLOAT uc[4];
                    LNAME(sampler_get4)(LLOAD(seed), LLOAD(irev), (LUINT)(FC_SET_CAMERA), uc);
                    L3 co, cd;
                    const LFLOAT cw =
                        LNAME(pixel_sample_ray_at)(params, LCONVERT_FLOAT(LLOAD(slot) + x0), (LFLOAT)((float)y), uc[0],
                                                   uc[1], uc[2], uc[3], &co, &cd);
                    float ca[3 * FC_PACKET_W], cb[3 * FC_PACKET_W], cwa[FC_PACKET_W];
                    l3_store(co, ca);
                    l3_store(cd, cb);
                    LSTORE(cw, cwa);
                    for (uint rest = fresh; rest; rest &= rest - 1u) {
                        const uint j = lowest_bit(rest);
                        set_lane3(o, j, lane3(ca, j));
                        set_lane3(d, j, lane3(cb, j));
                        fweight[j] = cwa[j];
                    }
                } else {
                    for (uint rest = fresh; rest; rest &= rest - 1u) {
                        const uint j = lowest_bit(rest);
                        Sampler sm; /* the Sobol' sampler's state (packets run no other) */
                        sm.kind = params->sampler;
                        sm.seed = seed[j];
                        sm.index_reversed = irev[j];
                        float3 oo, dd;
                        fweight[j] = pixel_sample_ray(params, x0 + slot[j], y, &sm, &oo, &dd);
                        set_lane3(o, j, oo);
                        set_lane3(d, j, dd);
                    }
                }
                fresh = 0u;
            }
            if (!need) break;
            Hit hits[FC_PACKET_W];
            const uint met = packet_trace_closest(sc, o, d, need, seed, irev, depth, hits);
#if FC_HAS_ENVIRONMENT
            /* the escaped rays' directions on the map, in lanes */
            float euv[2 * FC_PACKET_W], est[FC_PACKET_W];
            const bool env_map = packet_env_map(&P->environment);
            if (env_map && (need & ~met)) {
                packet_env_locate(&P->environment, l3_load(d), euv, est);
                packet_env_prefetch(&P->environment, sc->env_texels, sc->env_dist, euv, need & ~met);
            }
#endif
            for (uint rest = need; rest; rest &= rest - 1u) {
                const int j = (int)lowest_bit(rest);
                float3 oo = lane3(o, j), dd = lane3(d, j);
                if (!((met >> j) & 1u)) {
#if FC_HAS_ENVIRONMENT
                    /* escaped: the environment, MIS-weighted against light sampling (path_radiance's) */
                    float env_pdf_d;
                    float3 le = env_map
                                    ? env_map_radiance_pdf(&P->environment, sc->env_texels, sc->env_dist,
                                                           (float2)(euv[j], euv[FC_PACKET_W + j]), est[j], &env_pdf_d)
                                    : env_radiance_pdf(&P->environment, sc->env_texels, sc->env_dist, dd, &env_pdf_d);
                    if (!is_black(le)) {
                        float light_pdf = environment_pick_pdf(sc) * env_pdf_d;
                        float w = depth[j] > 0u ? bsdf_strategy_weight(P->strategy, prev_pdf[j], light_pdf) : 1.0f;
                        set_lane3(rad, j, lane3(rad, j) + lane3(thr, j) * le * w);
                    }
#endif
                    alive[j] = 0;
                    depth[j] = PATH_ENDED;
                    continue;
                }
                Hit hit = hits[j];
                Surface s = scene_surface_at(sc, &hit, oo, dd);
#if FC_HAS_VOLUME
                {
                    /* met from behind: the segment ran inside a closed absorbing dielectric
                     * (path_radiance's Beer-Lambert) */
                    __global const FcMaterial* mv = &sc->materials[s.material];
                    if (mv->specular_model == FC_SPECULAR_DIELECTRIC && dot(s.ng, dd) > 0.0f)
                        set_lane3(thr, j, lane3(thr, j) * exp(-load3(mv->attenuation) * hit.t));
                }
#endif
#if FC_HAS_TEXTURES
                /* the textured material, path_radiance's (a private copy per lane) */
                plen[j] += hit.t;
                FcMaterial mat = sc->materials[s.material];
                apply_textures(sc, &hit, s.material, dd, ray_cone_width(P, plen[j]), &s.ns, &mat);
                const float3 m_emission = load3p(mat.emission), m_diffuse = load3p(mat.diffuse);
                const uint m_flags = mat.flags;
#else
                __global const FcMaterial* m = &sc->materials[s.material];
                const float3 m_emission = load3(m->emission), m_diffuse = load3(m->diffuse);
                const uint m_flags = m->flags;
#endif
                (void)m_emission; /* read below in programs with area lights */
                (void)m_flags;
                float3 wo = -dd;
#if FC_HAS_AREA_LIGHTS
                float3 le = area_light_radiance(m_emission, m_flags, s.ng, wo);
                if (!is_black(le) && s.light >= 0) {
                    float w = 1.0f;
                    if (depth[j] > 0u) {
                        float light_pdf = light_pdf_hit(sc, s.light, oo, hit.t, dot(s.ng, wo));
                        w = bsdf_strategy_weight(P->strategy, prev_pdf[j], light_pdf);
                    }
                    set_lane3(rad, j, lane3(rad, j) + lane3(thr, j) * le * w);
                }
#endif
                if (depth[j] >= P->max_depth) {
                    alive[j] = 0;
                    depth[j] = PATH_ENDED;
                    continue;
                }
#if FC_PACKET_BSDF_PER_LANE
                /* a material beyond a Lambertian lobe: oriented and framed as path_radiance does
                 * (surface_orient), its BSDF evaluated and sampled per lane below */
#if FC_HAS_TEXTURES
                mats[j] = mat;
#else
                mats[j] = *m;
#endif
                gen[j] = !(mats[j].diffuse_model == FC_DIFFUSE_LAMBERT && mats[j].specular_model == FC_SPECULAR_NONE &&
                           !bsdf_layered(&mats[j]));
                if (gen[j]) {
                    float3 wo_local;
                    const Frame fr = surface_orient(&s, &mats[j], wo, &wo_local);
                    set_lane3(fs, j, fr.s);
                    set_lane3(ft, j, fr.t);
                    set_lane3(wol, j, wo_local);
                    delta_bsdf[j] = bsdf_is_delta(&mats[j]);
                    s.ns = fr.n;
                    plain[j] = !bsdf_layered(&mats[j]) && bsdf_plain(&mats[j]);
#if FC_HAS_TEXTURES
                    if (plain[j]) {
#else
                    if (plain[j] && pls_material[j] != s.material) {
                        pls_material[j] = s.material;
#endif
                        const PlainBase_l1 b = plain_base_of(&mats[j]);
                        packet_plain_set(&pls, j, &b);
                    }
#if FC_HAS_DIELECTRIC
                    rough[j] = packet_rough_at(&rds, j, &mats[j], wo_local);
#endif
                } else {
                    delta_bsdf[j] = 0;
                    plain[j] = 0;
#if FC_HAS_DIELECTRIC
                    rough[j] = 0;
#endif
                }
#if FC_HAS_DIELECTRIC
                trans[j] = gen[j] && bsdf_is_dielectric(&mats[j]);
                set_lane3(orgb, j, surface_offset(&s, -s.ng)); /* after surface_orient's turn */
#endif
#endif
                /* two-sided: the side the ray came from (the frame follows in lanes) */
                if (dot(s.ng, wo) < 0.0f) {
                    s.ng = -s.ng;
                    s.ns = -s.ns;
                }
                set_lane3(alb, j, m_diffuse);
#if FC_PACKET_OWN_ORIGINS
                set_lane3(org, j, surface_offset(&s, s.ng));
#endif
                set_lane3(p, j, s.p);
                set_lane3(ng, j, s.ng);
                set_lane3(ns, j, s.ns);
            }
            need = 0u;
        }
        bool any_active = false;
        for (int j = 0; j < FC_PACKET_W; ++j) any_active |= active[j] != 0;
        if (!any_active) break;

        /* C: in lanes, the frame, the light sample and the BSDF sample */
        LINT live = (LLOAD(alive) != 0) & (LLOAD(active) != 0);
        L3 D = l3_load(d), N = l3_load(ns), NG = l3_load(ng), PP = l3_load(p), A = l3_load(alb), T = l3_load(thr);
        L3 wo = l3(-D.x, -D.y, -D.z);
        /* the shading frame; ns = ng where wo is below ns */
        LFLOAT wz = l3_dot(wo, N);
        N = LNAME(vec3_select)(N, NG, wz <= 0.0f);
        L3 S, Tt;
        LNAME(frame_from_normal)(N, &S, &Tt);
        LFLOAT wo_z = l3_dot(wo, N);
#if FC_PACKET_BSDF_PER_LANE
        /* lanes with a BSDF of their own: the frame surface_orient gave it */
        const LINT G = live & (LLOAD(gen) != 0);
        N = LNAME(vec3_select)(N, l3_load(ns), G);
        S = LNAME(vec3_select)(S, l3_load(fs), G);
        Tt = LNAME(vec3_select)(Tt, l3_load(ft), G);
        wo_z = select(wo_z, LLOAD(wol + 2 * FC_PACKET_W), G);
#endif
#if FC_HAS_DIELECTRIC
        /* the mixtures toward glass of the Lambertian and glossy lanes, and which lanes they
         * guide (own: those whose BSDF is their own) */
        CausticGuide cgs[FC_PACKET_W];
        uint own = 0u, cone_bits[FC_PACKET_W];
        const uint guided = packet_caustic_guides(sc, live, gen, mats, PP, N, cgs, &own, cone_bits);
#endif
#if FC_PACKET_OWN_ORIGINS
        L3 so = l3_load(org);
#else
        L3 so = LNAME(offset_ray_origin)(PP, NG); /* every ray leaves on ng's side */
#endif
        LUINT dep = LLOAD(depth), sd = LLOAD(seed), ir = LLOAD(irev);
        LFLOAT ul[4], ub[4];
        LNAME(sampler_get4)(sd, ir, 1u + 2u * dep, ul);
        LNAME(sampler_get4)(sd, ir, 2u + 2u * dep, ub);

        /* the light: each lane's triangle (its point below in lanes), or a light sampled per
         * lane */
        L3 LP, E1, E2, LN, LC;
        LFLOAT LPICK, LAREA;
        LUINT LFLAGS;
#if FC_PACKET_LANE_LIGHTS
        /* picked and read per lane; an environment sampled per lane (env_sample) */
        float lp0[3 * FC_PACKET_W], le1[3 * FC_PACKET_W], le2[3 * FC_PACKET_W], ln[3 * FC_PACKET_W],
            lc[3 * FC_PACKET_W], lpick[FC_PACKET_W], larea[FC_PACKET_W];
        uint lflags[FC_PACKET_W];
        uint lpicked[FC_PACKET_W]; /* each lane's light, picked in lanes */
        LSTORE(LNAME(pick_light)(sc->light_cdf, P->light_count, ul[0]), lpicked);
        float lu1[FC_PACKET_W], lu2[FC_PACKET_W]; /* the light sample's point, lane by lane */
        LSTORE(ul[1], lu1);
        LSTORE(ul[2], lu2);
        /* lanes whose light is sampled per lane: its direction, density (pick included; 0 for
         * nothing), shadow ray length, and whether it is a delta light */
        float xwi[3 * FC_PACKET_W], xpdf[FC_PACKET_W], xtmax[FC_PACKET_W];
        int xl[FC_PACKET_W], xdelta[FC_PACKET_W];
#if FC_HAS_ENVIRONMENT
        /* lanes that sample the map: env_sample_uv's point, and the light's pick density */
        float suv[2 * FC_PACKET_W], spick[FC_PACKET_W];
        uint xenv = 0u;
        const bool env_sampled = packet_env_map(&P->environment) && P->environment.total > 0.0f;
#endif
        for (int j = 0; j < FC_PACKET_W; ++j) {
            /* A lane with no path (the queue is empty) samples nothing: it goes as a per-lane
             * light of zero density, since such a sample is not cheap. */
            xl[j] = -1;
            xpdf[j] = 0.0f;
            xtmax[j] = INFINITY;
            xdelta[j] = 0;
            set_lane3(xwi, j, (float3)(0.0f, 0.0f, 1.0f));
            set_lane3(lc, j, (float3)(0.0f));
#if FC_PACKET_BSDF_PER_LANE
            const bool nee = !(gen[j] && delta_bsdf[j]); /* no light sample for a delta BSDF */
#else
            const bool nee = true;
#endif
            if (active[j] && alive[j] && nee) {
                __global const FcLight* l = &sc->lights[lpicked[j]];
                if (l->type == FC_LIGHT_AREA_TRIANGLE) {
                    xl[j] = 0;
                    packet_triangle_light(sc, l, j, (float2)(lu1[j], lu2[j]), lp0, le1, le2, ln, lc, lpick, larea,
                                          lflags);
                    continue;
                }
#if FC_HAS_ENVIRONMENT
                if (l->type == FC_LIGHT_ENVIRONMENT && env_sampled) {
                    /* the map's point, its direction and lookup after this loop */
                    spick[j] = l->pick_pdf;
                    xenv |= 1u << j;
                    packet_no_triangle_light(j, lp0, le1, le2, ln, lpick, larea, lflags);
                    continue;
                }
#endif
                float3 wi;
                set_lane3(lc, j,
                          packet_lane_light(sc, l, lane3(p, j), (float2)(lu1[j], lu2[j]), &wi, &xpdf[j], &xtmax[j],
                                            &xdelta[j]));
                set_lane3(xwi, j, wi);
            }
            packet_no_triangle_light(j, lp0, le1, le2, ln, lpick, larea, lflags);
        }
#if FC_HAS_ENVIRONMENT
        if (xenv) {
            /* the map's samples: their points and directions in lanes (packet_lights.cl), then
             * each one's radiance and density by the lookup of env_sample (per lane) */
            packet_env_sample_points(&P->environment, sc->env_texels, sc->env_dist, lu1, lu2, xenv, suv);
            float sdir[3 * FC_PACKET_W], luv[2 * FC_PACKET_W], lst[FC_PACKET_W];
            packet_env_directions(&P->environment, suv, sdir, luv, lst);
            packet_env_prefetch(&P->environment, sc->env_texels, sc->env_dist, luv, xenv);
            for (uint rest = xenv; rest; rest &= rest - 1u) {
                const uint j = lowest_bit(rest);
                float pdf_dir;
                const float3 li = env_map_radiance_pdf(&P->environment, sc->env_texels, sc->env_dist,
                                                       (float2)(luv[j], luv[FC_PACKET_W + j]), lst[j], &pdf_dir);
                set_lane3(lc, j, li);
                set_lane3(xwi, j, lane3(sdir, j));
                xpdf[j] = packet_light_pdf(li, pdf_dir * spick[j]);
            }
        }
#endif
        LP = l3_load(lp0);
        E1 = l3_load(le1);
        E2 = l3_load(le2);
        LN = l3_load(ln);
        LC = l3_load(lc);
        LPICK = LLOAD(lpick);
        LAREA = LLOAD(larea);
        LFLAGS = LLOAD(lflags);
#else
        /* every light is a triangle: each lane's pick, and its light's fields gathered */
        packet_triangle_lights(sc, P->light_count, ul, &LP, &E1, &E2, &LN, &LC, &LPICK, &LAREA, &LFLAGS);
#endif
        LVEC2 bary = LNAME(square_to_triangle)(ul[1], ul[2]);
        LFLOAT b0 = bary.x, b1 = bary.y;
        L3 point = l3(LP.x + b0 * E1.x + b1 * E2.x, LP.y + b0 * E1.y + b1 * E2.y, LP.z + b0 * E1.z + b1 * E2.z);
        L3 to = l3(point.x - PP.x, point.y - PP.y, point.z - PP.z);
        LFLOAT d2 = l3_dot(to, to);
        LFLOAT dist = sqrt(d2);
        L3 wi = l3(to.x / dist, to.y / dist, to.z / dist);
        LFLOAT cl = l3_dot(LN, wi);
        LFLOAT pdf_l = LNAME(area_light_pdf_solid_angle)(LPICK, LAREA, dist, cl);
        LINT lit = LNAME(area_light_lit)((LFLAGS & FC_MAT_TWO_SIDED_EMISSION) != 0u, -cl); /* toward -wi */
        LINT ok = (d2 > 0.0f) & lit;
#if FC_PACKET_LANE_LIGHTS
        const LINT is_x = LLOAD(xl);
        wi = LNAME(vec3_select)(wi, l3_load(xwi), is_x);
        pdf_l = select(pdf_l, LLOAD(xpdf), is_x);
        ok = select(ok, (LINT)(-1), is_x);
#endif
        LFLOAT side = l3_dot(NG, wi);
        LFLOAT wi_z = l3_dot(wi, N);
        LFLOAT f_scale = FC_INV_PI;
#if FC_HAS_DIELECTRIC
        /* a light behind the surface counts through a dielectric (sample_direct's test) */
        const LINT through = G & (LLOAD(trans) != 0);
        ok &= live & (pdf_l > 0.0f) & isfinite(pdf_l) & ((side > 0.0f) | ((side < 0.0f) & through)) &
              (wi_z * side > 0.0f) & (wo_z > 0.0f) & ((wi_z > 0.0f) | through);
#else
        ok &= live & (pdf_l > 0.0f) & isfinite(pdf_l) & (side > 0.0f) & (wi_z * side > 0.0f) & (wo_z > 0.0f) &
              (wi_z > 0.0f);
#endif
        /* D: the shadow rays, in a packet where they can be, from the offset point on wi's side to
         * the offset point on a triangle; traced before the BSDF and the guide's density at wi
         * are made, so that those are made only where the light is seen (a glass vertex's light
         * behind its surface, or any seen from inside a ball, is blocked by the ball itself) */
#if FC_HAS_DIELECTRIC
        const L3 sso = LNAME(vec3_select)(so, l3_load(orgb), side < 0.0f);
#else
        const L3 sso = so;
#endif
        LINT back = cl < 0.0f;
        L3 tn = l3(select(-LN.x, LN.x, back), select(-LN.y, LN.y, back), select(-LN.z, LN.z, back));
        L3 target = LNAME(offset_ray_origin)(point, tn);
        L3 seg = l3(target.x - sso.x, target.y - sso.y, target.z - sso.z);
        LFLOAT tmax = sqrt(l3_dot(seg, seg));
        L3 sdir = l3(seg.x / tmax, seg.y / tmax, seg.z / tmax);
#if FC_PACKET_LANE_LIGHTS
        /* toward a per-lane light: along its direction, to its distance (unbounded for the
         * environment and a directional light) */
        sdir = LNAME(vec3_select)(sdir, wi, is_x);
        tmax = select(tmax, LLOAD(xtmax), is_x);
#endif
        ok &= tmax > 0.0f;
        uint unblocked;
        {
            float so_a[3 * FC_PACKET_W], sd_a[3 * FC_PACKET_W], tmax_a[FC_PACKET_W];
            l3_store(sso, so_a);
            l3_store(sdir, sd_a);
            LSTORE(tmax, tmax_a);
            int oka[FC_PACKET_W];
            LSTORE(ok, oka);
            uint shadow = 0u;
            for (int j = 0; j < FC_PACKET_W; ++j)
                if (oka[j]) shadow |= 1u << j;
            unblocked = shadow & ~packet_trace_any(sc, so_a, sd_a, tmax_a, shadow, seed, irev, depth);
            for (int j = 0; j < FC_PACKET_W; ++j) oka[j] = (unblocked >> j) & 1u ? -1 : 0;
            ok = LLOAD(oka);
        }
#if FC_PACKET_BSDF_PER_LANE
        /* a lane's own BSDF at the light's direction, per lane (sample_direct's), where it
         * has one; f and its density (for MIS) */
        L3 F = l3(A.x * f_scale, A.y * f_scale, A.z * f_scale);
        LFLOAT bsdf_pdf_l = LNAME(cosine_hemisphere_pdf)(wo_z, wi_z);
        /* lanes whose BSDF is a plain base, evaluated and sampled in lanes (bsdf_eval_pdf's and
         * bsdf_sample's route for them, at W = 1 there) */
        const LINT PL = G & (LLOAD(plain) != 0);
        const bool some_plain = LNAME(lanes_any)(PL);
        LNAME(PlainBase) pb;
        LNAME(PlainView) pv;
        if (some_plain) {
            packet_plain_base(PL, &pls, &pb);
            LNAME(plain_base_view)(&pb, l3_load(wol), &pv);
        }
#if FC_HAS_DIELECTRIC
        /* rough dielectrics in lanes where enough lanes have one (else per lane) */
        LNAME(RoughDielectric) rdb;
        const LINT RD = packet_rough_lanes(G, rough, &rds, l3_load(wol), &rdb);
        const bool some_rough = LNAME(lanes_any)(RD);
#endif
        {
            float wil[3 * FC_PACKET_W], fa[3 * FC_PACKET_W], pa[FC_PACKET_W];
            int ga[FC_PACKET_W];
            l3_store(l3(l3_dot(wi, S), l3_dot(wi, Tt), wi_z), wil);
            LSTORE(ok & G, ga);
            for (int j = 0; j < FC_PACKET_W; ++j) {
                set_lane3(fa, j, (float3)(0.0f));
                pa[j] = 0.0f;
                if (!ga[j]) continue;
                ga[j] = 0;
                if (delta_bsdf[j] || plain[j]) continue;
#if FC_HAS_DIELECTRIC
                if (rough[j] && some_rough) continue;
#endif
                /* with MIS, f and its density at once (bsdf_eval_pdf: the same bits as the two) */
                float pdf_j = 0.0f;
                const float3 f = P->strategy == FC_STRATEGY_MIS
                                     ? bsdf_eval_pdf(&mats[j], lane3(wol, j), lane3(wil, j), &pdf_j)
                                     : bsdf_eval(&mats[j], lane3(wol, j), lane3(wil, j));
                if (is_black(f)) continue;
                set_lane3(fa, j, f);
                pa[j] = pdf_j;
                ga[j] = -1;
            }
            LINT okg = LLOAD(ga);
            L3 Fg = l3_load(fa);
            LFLOAT pg = LLOAD(pa);
            /* plain bases in lanes: f and its density */
            const LINT PLok = ok & PL;
            const bool mis = P->strategy == FC_STRATEGY_MIS;
            if (some_plain && LNAME(lanes_any)(PLok)) {
                LFLOAT pp;
                const L3 fp = LNAME(plain_base_eval_pdf)(&pb, &pv, l3_load(wol), l3_load(wil), &pp);
                packet_bsdf_merge_eval(PLok, fp, pp, mis, &okg, &Fg, &pg);
            }
#if FC_HAS_DIELECTRIC
            /* rough dielectrics in lanes: f and its density */
            if (some_rough) packet_rough_eval(&rdb, ok & RD, mis, l3_load(wol), l3_load(wil), &okg, &Fg, &pg);
#endif
            ok = select(ok, okg, G);
            F = LNAME(vec3_select)(F, Fg, G);
            bsdf_pdf_l = select(bsdf_pdf_l, pg, G);
        }
#if FC_HAS_DIELECTRIC
        if ((guided & unblocked) && P->strategy == FC_STRATEGY_MIS) {
            /* the lanes whose light is at infinity (the environment, a directional light) */
            uint at_infinity = 0u;
#if FC_PACKET_LANE_LIGHTS
            for (int j = 0; j < FC_PACKET_W; ++j)
                if (xl[j] && !isfinite(xtmax[j])) at_infinity |= 1u << j;
#endif
            bsdf_pdf_l =
                packet_guided_light_pdf(sc, guided & unblocked, cgs, cone_bits, PP, at_infinity, bsdf_pdf_l, wi);
        }
#endif
        LFLOAT w = LNAME(light_strategy_weight)(P->strategy, pdf_l, bsdf_pdf_l);
#else
        LFLOAT w = LNAME(light_strategy_weight)(P->strategy, pdf_l, LNAME(cosine_hemisphere_pdf)(wo_z, wi_z));
#endif
#if FC_HAS_PUNCTUAL_LIGHTS
        w = select(w, (LFLOAT)(1.0f), LLOAD(xdelta)); /* a delta light: no MIS, under any strategy */
#endif
        LFLOAT k = select((LFLOAT)(0.0f), fabs(wi_z) * w / pdf_l, ok);
#if FC_PACKET_BSDF_PER_LANE
        L3 contrib = l3(T.x * F.x * LC.x * k, T.y * F.y * LC.y * k, T.z * F.z * LC.z * k);
#else
        L3 contrib = l3(T.x * A.x * f_scale * LC.x * k, T.y * A.y * f_scale * LC.y * k, T.z * A.z * f_scale * LC.z * k);
#endif
        {
            /* the lanes whose light is seen and counts */
            float cx[3 * FC_PACKET_W];
            int oka[FC_PACKET_W];
            l3_store(contrib, cx);
            LSTORE(ok, oka);
            for (int j = 0; j < FC_PACKET_W; ++j)
                if (oka[j]) set_lane3(rad, j, lane3(rad, j) + lane3(cx, j));
        }
        /* E: the BSDF sample (cosine hemisphere), throughput and roulette, in lanes */
        L3 dir_local = LNAME(square_to_cosine_hemisphere)(ub[0], ub[1]);
        LFLOAT dz = dir_local.z;
        L3 nwi = LNAME(vec3_combine)(dir_local.x, S, dir_local.y, Tt, dz, N);
        LFLOAT nside = l3_dot(NG, nwi);
        LINT cont = live & (wo_z > 0.0f) & (dz > 0.0f) & (nside * dz > 0.0f);
        LFLOAT next_pdf = LNAME(cosine_hemisphere_pdf)(wo_z, dz);
#if FC_PACKET_BSDF_PER_LANE
        /* a lane's own BSDF sampled per lane (path_radiance's): the direction, its weight in A */
        {
            float u0[FC_PACKET_W], u1[FC_PACKET_W], u2[FC_PACKET_W], gwi[3 * FC_PACKET_W], gw[3 * FC_PACKET_W],
                gp[FC_PACKET_W];
            int ga[FC_PACKET_W];
#if FC_HAS_DIELECTRIC
            int below[FC_PACKET_W]; /* a refraction: the next ray leaves from the far side */
#endif
            LSTORE(ub[0], u0);
            LSTORE(ub[1], u1);
            LSTORE(ub[2], u2);
            LSTORE(G, ga);
            for (int j = 0; j < FC_PACKET_W; ++j) {
                set_lane3(gwi, j, (float3)(0.0f, 0.0f, 1.0f));
                set_lane3(gw, j, (float3)(0.0f));
                gp[j] = 0.0f;
#if FC_HAS_DIELECTRIC
                below[j] = 0;
                if (rough[j] && some_rough) ga[j] = 0; /* sampled in lanes below */
#endif
                if (!ga[j] || plain[j]) continue;
                ga[j] = 0;
                BsdfSample bs;
                const Frame fr = {lane3(fs, j), lane3(ft, j), lane3(ns, j)};
                if (!path_bsdf_sample(&P->environment, sc->env_texels, sc->env_dist, &mats[j], &fr, lane3(wol, j),
                                      (float3)(u0[j], u1[j], u2[j]), &bs))
                    continue;
                const float3 wi_world = frame_to_world(&fr, bs.wi);
                /* the shading frame and the geometric normal agree on wi's side (a reflection
                 * stays on wo's side, a refraction crosses) */
                const float wi_side = dot(lane3(ng, j), wi_world);
                if (!(wi_side * bs.wi.z > 0.0f)) continue;
#if FC_HAS_DIELECTRIC
                below[j] = wi_side < 0.0f ? -1 : 0;
                if (bs.wi.z < 0.0f) rr_scale[j] = roulette_scale_times(rr_scale[j], mats[j].ior * mats[j].ior);
#endif
                set_lane3(gwi, j, wi_world);
                set_lane3(gw, j, bs.weight);
                gp[j] = bs.delta ? INFINITY : bs.pdf;
                ga[j] = -1;
            }
            nwi = LNAME(vec3_select)(nwi, l3_load(gwi), G);
            cont = select(cont, LLOAD(ga), G);
            next_pdf = select(next_pdf, LLOAD(gp), G);
            A = LNAME(vec3_select)(A, l3_load(gw), G);
#if FC_HAS_DIELECTRIC
            so = LNAME(vec3_select)(so, l3_load(orgb), LLOAD(below));
            if (some_rough) /* rough dielectrics in lanes */
                packet_rough_sample(&rdb, RD, l3_load(wol), ub, S, Tt, N, NG, orgb, mats, rr_scale, &nwi, &cont,
                                    &next_pdf, &A, &so);
#endif
            /* plain bases in lanes, reflections only (the glossy guided lanes' choice of lobe
             * rescaled past the guide's share) */
            if (some_plain) {
                L3 wl, fl, wt;
                LFLOAT pl;
#if FC_HAS_DIELECTRIC
                const LFLOAT u2p = own ? packet_guided_bsdf_u(own, cgs, ub[2]) : ub[2];
#else
                const LFLOAT u2p = ub[2];
#endif
                LFLOAT plain_side;
                const LINT okp =
                    LNAME(plain_base_sample)(&pb, &pv, l3_load(wol), ub[0], ub[1], u2p, &wl, &fl, &pl, &wt);
                packet_bsdf_merge_sample(PL, okp, wl, pl, wt, S, Tt, N, NG, &nwi, &cont, &next_pdf, &A, &plain_side);
#if FC_HAS_DIELECTRIC
                /* the glossy guided lanes: the mixture's density and the guide's directions */
                if (own)
                    packet_guided_own_directions(sc, own, cgs, ub, mats, wol, fs, ft, ns, ng, fl, wl.z, &nwi, &A,
                                                 &next_pdf, &cont, rr_scale);
#endif
            }
        }
#endif
#if FC_HAS_DIELECTRIC
        if (guided & ~own)
            packet_guided_directions(sc, guided & ~own, cgs, cone_bits, ub, wo_z, PP, N, NG, alb, &nwi, &A, &next_pdf,
                                     &cont, rr_scale);
#endif
        L3 T2 = l3(T.x * A.x, T.y * A.y, T.z * A.z);
        LINT rr = LCONVERT_INT(dep + 1u >= P->rr_depth);
#if FC_HAS_DIELECTRIC
        LFLOAT survive = LNAME(roulette_survival)(T2, LLOAD(rr_scale), P->roulette_gain);
#else
        LFLOAT survive = LNAME(roulette_survival)(T2, 1.0f, P->roulette_gain); /* no refraction, no guide: rr_scale 1 */
#endif
        cont &= select((LINT)(-1), ub[3] < survive, rr);
        T2 = l3(select(T2.x, T2.x / survive, rr), select(T2.y, T2.y / survive, rr), select(T2.z, T2.z / survive, rr));
        l3_store(T2, thr);
        l3_store(nwi, d);
        l3_store(so, o);
        LSTORE(next_pdf, prev_pdf);
        int conta[FC_PACKET_W];
        LSTORE(cont, conta);
        /* a live path goes on a bounce deeper or ends here: selects, not a branch a lane */
        for (int j = 0; j < FC_PACKET_W; ++j) {
            const int running = (active[j] != 0) & (alive[j] != 0);
            const int go = running & (conta[j] != 0);
            depth[j] = go ? depth[j] + 1u : running ? PATH_ENDED : depth[j];
            alive[j] = running ? go : alive[j];
        }
    }
}

#include "kernels/lanes/lanes_close.cl"

#endif
