/* The packet paths' lights (issue 29): what a lane's light sample reads per lane, a
 * triangle's fields for the sample in lanes (gathered where every light is a triangle), the
 * environment map's directions in lanes, and the environment's and punctual lights' samples
 * per lane (sample_light's, lane by lane). Included by kernels/integrator/packet_paths.cl
 * inside its lanes (FC_LW = FC_PACKET_W), after its lane helpers (l3, l3_load, l3_store,
 * lane3, set_lane3). */
#ifndef FACET_INTEGRATOR_PACKET_LIGHTS_CL
#define FACET_INTEGRATOR_PACKET_LIGHTS_CL

/* Triangle light l's radiance `color` at point u of the square: times its emission texture
 * and its alpha coverage there, where the program has them (sample_light's, per lane). */
inline float3 packet_light_color_at(const SceneView* sc, __global const FcLight* l, float2 u, float3 color) {
#if FC_HAS_TEXTURES
    color *= emission_texture_at(sc, l->prim, sc->shading[l->prim].material, square_to_triangle(u));
#endif
#if FC_HAS_ALPHA
    color *= alpha_light_coverage(sc, l->prim, square_to_triangle(u));
#endif
#if !FC_HAS_TEXTURES && !FC_HAS_ALPHA
    (void)sc;
    (void)l;
    (void)u;
#endif
    return color;
}

/* Lane j's fields of triangle light l, for its sample in lanes at point u of the square (its
 * emission texture and its alpha coverage, if any, read there per lane). */
inline void packet_triangle_light(const SceneView* sc, __global const FcLight* l, int j, float2 u, float* lp0,
                                  float* le1, float* le2, float* ln, float* lc, float* lpick, float* larea,
                                  uint* lflags) {
    set_lane3(lp0, j, load3(l->p0));
    set_lane3(le1, j, load3(l->e1));
    set_lane3(le2, j, load3(l->e2));
    set_lane3(ln, j, load3(l->n));
    set_lane3(lc, j, packet_light_color_at(sc, l, u, load3(l->color)));
    lpick[j] = l->pick_pdf;
    larea[j] = l->area;
    lflags[j] = l->flags;
}

/* The 3-vector at base[index], base[index + 1], base[index + 2] for each lane, gathered. */
inline L3 packet_gather3(__global const float* base, LUINT index) {
    return l3(LNAME(gather)(base, index), LNAME(gather)(base + 1, index), LNAME(gather)(base + 2, index));
}
/* An FcLight's size in floats: a light's index times it is its first float's. */
#define FC_PACKET_LIGHT_FLOATS ((uint)(sizeof(FcLight) / sizeof(float)))

/* Programs whose every light is a triangle: each lane's light picked in lanes at ul[0] (of the
 * `light_count` lights) and its fields gathered straight into lanes, where copying them lane
 * by lane into arrays left each vector load waiting on sixteen stores; the emission texture and
 * alpha coverage at the lane's point (ul[1], ul[2]) read per lane (packet_light_color_at). */
inline void packet_triangle_lights(const SceneView* sc, uint light_count, const LFLOAT* ul, L3* p0, L3* e1, L3* e2,
                                   L3* n, L3* color, LFLOAT* pick, LFLOAT* area, LUINT* flags) {
    const LUINT at = LNAME(pick_light)(sc->light_cdf, light_count, ul[0]) * FC_PACKET_LIGHT_FLOATS;
    __global const FcLight* l0 = sc->lights;
    *p0 = packet_gather3(l0->p0, at);
    *e1 = packet_gather3(l0->e1, at);
    *e2 = packet_gather3(l0->e2, at);
    *n = packet_gather3(l0->n, at);
    *color = packet_gather3(l0->color, at);
    *pick = LNAME(gather)(&l0->pick_pdf, at);
    *area = LNAME(gather)(&l0->area, at);
    *flags = LCONVERT_UINT(LAS_INT(LNAME(gather)((__global const float*)&l0->flags, at)));
#if FC_HAS_TEXTURES || FC_HAS_ALPHA
    float lc[3 * FC_PACKET_W], lu1[FC_PACKET_W], lu2[FC_PACKET_W];
    uint li[FC_PACKET_W];
    l3_store(*color, lc);
    LSTORE(ul[1], lu1);
    LSTORE(ul[2], lu2);
    LSTORE(at / FC_PACKET_LIGHT_FLOATS, li);
    for (int j = 0; j < FC_PACKET_W; ++j)
        set_lane3(lc, j, packet_light_color_at(sc, &sc->lights[li[j]], (float2)(lu1[j], lu2[j]), lane3(lc, j)));
    *color = l3_load(lc);
#endif
}

/* Lane j's triangle fields where it sampled no triangle: values that keep the triangle's
 * arithmetic in lanes finite, its results not used. */
inline void packet_no_triangle_light(int j, float* lp0, float* le1, float* le2, float* ln, float* lpick, float* larea,
                                     uint* lflags) {
    set_lane3(lp0, j, (float3)(0.0f));
    set_lane3(le1, j, (float3)(0.0f));
    set_lane3(le2, j, (float3)(0.0f));
    set_lane3(ln, j, (float3)(0.0f, 0.0f, 1.0f));
    lpick[j] = 1.0f;
    larea[j] = 1.0f;
    lflags[j] = 0u;
}

#if FC_HAS_ENVIRONMENT
/* Whether the environment is a map that escaped rays look up and light samples pick texels
 * of: then the packet locates their directions in lanes (packet_env_locate,
 * packet_env_directions), and reads the map per lane (env_map_radiance_pdf). */
inline bool packet_env_map(__constant const FcEnvironment* env) { return env->enabled && env->width > 0; }

/* The map's (u, v) (lane arrays uv: u then v) and sin(theta) of the lanes' directions dir:
 * env_radiance_pdf's location, in lanes. */
inline void packet_env_locate(__constant const FcEnvironment* env, L3 dir, float* uv, float* sin_theta) {
    LFLOAT st;
    const LVEC2 at = LNAME(env_map_dir_to_uv)(
        LNAME(env_dir_to_map)(load3c(env->to_map[0]), load3c(env->to_map[1]), load3c(env->to_map[2]), dir), &st);
    LSTORE(at.x, uv);
    LSTORE(at.y, uv + FC_PACKET_W);
    LSTORE(st, sin_theta);
}

/* Starts the loads of what env_map_radiance_pdf reads at the lanes' (u, v) (uv as
 * packet_env_locate leaves it) for the lanes in `lanes`: the texel and its entry of the row's
 * conditional cdf, which in a large map are mostly cache misses; started together, the misses
 * overlap instead of following one another lane by lane. Only a hint: nothing is read. */
inline void packet_env_prefetch(__constant const FcEnvironment* env, __global const float4* texels,
                                __global const float* dist, const float* uv, uint lanes) {
#if defined(__clang__) && defined(__x86_64__)
    for (uint rest = lanes; rest; rest &= rest - 1u) {
        const uint j = lowest_bit(rest);
        const int2 t = env_texel(env, (float2)(uv[j], uv[FC_PACKET_W + j]));
        __builtin_prefetch(texels + t.y * env->width + t.x);
        __builtin_prefetch(dist + (env->height + 1) + t.y * (env->width + 1) + t.x);
    }
#endif
}

/* The map's points env_sample_uv takes at the lanes' numbers (u1, u2) in suv (u in
 * suv[0..W-1], v in suv[W..2W-1]): the texels and the points across them in lanes
 * (env_sample_texel), moved inside the texel per lane for a bilinear lookup, in the lanes of
 * `lanes`. */
inline void packet_env_sample_points(__constant const FcEnvironment* env, __global const float4* texels,
                                     __global const float* dist, const float* u1, const float* u2, uint lanes,
                                     float* suv) {
    LINT tx, ty;
    LFLOAT tdu, tdv;
    LNAME(env_sample_texel)(env->width, env->height, dist, LLOAD(u1), LLOAD(u2), &tx, &ty, &tdu, &tdv);
    if (env->filter == FC_ENV_FILTER_BILINEAR) {
        int xa[FC_PACKET_W], ya[FC_PACKET_W];
        float across[2 * FC_PACKET_W];
        LSTORE(tx, xa);
        LSTORE(ty, ya);
        LSTORE(tdu, across);
        LSTORE(tdv, across + FC_PACKET_W);
        for (uint rest = lanes; rest; rest &= rest - 1u) {
            const uint j = lowest_bit(rest);
            const float2 in =
                env_bilinear_in_texel(env, texels, xa[j], ya[j], (float2)(across[j], across[FC_PACKET_W + j]));
            across[j] = in.x;
            across[FC_PACKET_W + j] = in.y;
        }
        tdu = LLOAD(across);
        tdv = LLOAD(across + FC_PACKET_W);
    }
    LSTORE((LCONVERT_FLOAT(tx) + tdu) / (float)env->width, suv);
    LSTORE((LCONVERT_FLOAT(ty) + tdv) / (float)env->height, suv + FC_PACKET_W);
}

/* The directions of the map's points `suv` (env_sample_uv's, in lanes) in dir, and their
 * location again (uv, sin_theta) for the lookup: env_sample's middle steps, in lanes. */
inline void packet_env_directions(__constant const FcEnvironment* env, const float* suv, float* dir, float* uv,
                                  float* sin_theta) {
    const L3 w = LNAME(env_uv_to_dir)(load3c(env->to_map[0]), load3c(env->to_map[1]), load3c(env->to_map[2]),
                                      LNAME(vec2)(LLOAD(suv), LLOAD(suv + FC_PACKET_W)));
    l3_store(w, dir);
    packet_env_locate(env, w, uv, sin_theta);
}
#endif

/* A per-lane light's density, pick included, or 0 where its sample carries nothing
 * (sample_light's test). */
inline float packet_light_pdf(float3 li, float lpdf) {
    return lpdf > 0.0f && isfinite(lpdf) && !is_black(li) && all_finite(li) ? lpdf : 0.0f;
}

/* The lights a lane samples per lane, where the program has them: the environment and the
 * punctual lights. */
#define FC_PACKET_LANE_LIGHTS (FC_HAS_ENVIRONMENT || FC_HAS_PUNCTUAL_LIGHTS)

#if FC_PACKET_LANE_LIGHTS
/* Light l, the environment or a punctual light, sampled as sample_light does from point p at u
 * of the square: the radiance (a punctual light's irradiance at normal incidence), the
 * direction in *wi, the density in *pdf (pick included; 0 where the sample carries nothing,
 * sample_light's test), the shadow ray's length in *tmax (sample_direct's: short of a point
 * light, unbounded otherwise) and in *delta whether it is a delta light (-1) or not (0). */
inline float3 packet_lane_light(const SceneView* sc, __global const FcLight* l, float3 p, float2 u, float3* wi,
                                float* pdf, float* tmax, int* delta) {
    float3 li = (float3)(0.0f);
    float lpdf = 0.0f;
    *wi = (float3)(0.0f, 0.0f, 1.0f);
    *tmax = INFINITY;
    *delta = 0;
    (void)p;
    (void)u;
#if FC_HAS_ENVIRONMENT
    if (l->type == FC_LIGHT_ENVIRONMENT) {
        float pdf_dir;
        li = env_sample(&sc->params->environment, sc->env_texels, sc->env_dist, u, wi, &pdf_dir);
        lpdf = pdf_dir * l->pick_pdf;
    }
#endif
#if FC_HAS_PUNCTUAL_LIGHTS
    if (l->type == FC_LIGHT_POINT || l->type == FC_LIGHT_SPOT || l->type == FC_LIGHT_DIRECTIONAL) {
        float dist;
        li = punctual_light_irradiance(l, p, wi, &dist);
        lpdf = l->pick_pdf;
        *delta = -1;
        *tmax = isfinite(dist) ? dist * (1.0f - 1e-5f) : dist;
    }
#endif
    *pdf = packet_light_pdf(li, lpdf);
    return li;
}
#endif

#endif
