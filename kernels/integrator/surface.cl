/* The surface at a ray hit: position from the triangle's barycentrics (more precise
 * than o + t d; an instanced triangle's vertices placed in the world first) or re-projected
 * onto the sphere, geometric and shading normals in world space, and the material. */
#ifndef FACET_INTEGRATOR_SURFACE_CL
#define FACET_INTEGRATOR_SURFACE_CL

#include "kernels/shared/all.h"
#include "kernels/bsdf/anisotropy.cl"
#include "kernels/bsdf/bsdf.cl"
#include "kernels/scene/vertex_tangent.cl"
#include "kernels/trace/bvh_traverse.cl"
#include "kernels/trace/scene_trace.cl"
#include "kernels/util/frame.cl"

typedef struct {
    float3 p;  /* hit point */
    float3 ng; /* geometric normal, on the side the shading normals face */
    float3 ns; /* interpolated shading normal */
    int prim;  /* scene triangle index */
    int material;
    int light;      /* light index, or -1 */
    float3 p_error; /* spheres: bound on p's rounding error per axis; 0 for triangles */
#if FC_HAS_ANISOTROPY
    float4 tangent; /* anisotropic materials: the vertex tangent (xyz) and handedness (w); 0: none */
#endif
} Surface;

/* The surface of triangle hit->tri at the hit, in world space: an instanced triangle's
 * vertices placed by its instance, its vertex normals by the inverse transpose, each
 * renormalised as the normals of a mesh copied into the world are (host/readers/triangle_mesh.cpp),
 * so both give the same surface (their geometric normals to rounding: a world triangle's is
 * the host's, in double). */
inline Surface surface_at(const SceneView* sc, const Hit* hit) {
    float3 v0, v1, v2;
    hit_triangle_vertices(sc, hit, &v0, &v1, &v2);
    float3 e1 = v1 - v0;
    float3 e2 = v2 - v0;
    __global const FcTriShading* sh = &sc->shading[hit->prim];
    float3 n0 = load3(sh->n0), n1 = load3(sh->n1), n2 = load3(sh->n2);
    Surface s;
    s.p = v0 + hit->u * e1 + hit->v * e2;
    /* the unit normal along cross(e1, e2): the host's for a world triangle (face_normals,
     * host/scene/device_scene.hpp); an instance's from its placed vertices */
#if FC_HAS_INSTANCES
    if (hit->inst >= 0) {
        __global const FcInstance* in = &sc->instances[hit->inst];
        s.ng = normalize_scaled_or(cross(e1, e2), (float3)(0.0f, 0.0f, 1.0f));
        n0 = normalize_or(instance_normal_to_world(in, n0), s.ng);
        n1 = normalize_or(instance_normal_to_world(in, n1), s.ng);
        n2 = normalize_or(instance_normal_to_world(in, n2), s.ng);
    } else
#endif
        s.ng = sc->face_normals[hit->prim].xyz;
    float w = 1.0f - hit->u - hit->v;
    s.ns = normalize_or(w * n0 + hit->u * n1 + hit->v * n2, s.ng);
    if (dot(s.ng, s.ns) < 0.0f) s.ng = -s.ng;
    s.prim = hit->prim;
    s.material = sh->material;
    s.light = sh->light;
    s.p_error = (float3)(0.0f);
#if FC_HAS_ANISOTROPY
    /* The tangents are uploaded when the scene has an anisotropic material (host/scene/texture.cpp). */
    s.tangent = (float4)(0.0f);
    if (sc->materials[s.material].flags & FC_MAT_ANISOTROPIC) {
        s.tangent = tex_tangent(&sc->texcoords[hit->prim], hit->u, hit->v);
#if FC_HAS_INSTANCES
        if (hit->inst >= 0 && s.tangent.w != 0.0f)
            s.tangent = instance_tangent_to_world(&sc->instances[hit->inst], s.tangent);
#endif
    }
#endif
    return s;
}

#if FC_HAS_SPHERES
/* The surface where the ray o + t d met sphere hit->prim: the exact normal (facing inward
 * for FC_SPHERE_INWARD spheres) as both geometric and shading normal. */
inline Surface sphere_surface_at(__global const FcSphere* spheres, const Hit* hit, float3 o, float3 d) {
    __global const FcSphere* sp = &spheres[hit->prim];
    Surface s;
    float3 n;
    s.p = sphere_hit_point(load3(sp->center), sp->radius, o, d, hit->t, &n, &s.p_error);
    s.ng = s.ns = (sp->flags & FC_SPHERE_INWARD) ? -n : n;
    s.prim = sp->prim;
    s.material = sp->material;
    s.light = sp->light;
#if FC_HAS_ANISOTROPY
    s.tangent = (float4)(0.0f); /* dp/dphi (kernels/bsdf/anisotropy.cl) */
#endif
    return s;
}
#endif

/* The surface at a hit of scene_trace_closest along o + t d. */
inline Surface scene_surface_at(const SceneView* sc, const Hit* hit, float3 o, float3 d) {
#if FC_HAS_SPHERES
    if (hit->tri == FC_HIT_SPHERE) return sphere_surface_at(sc->spheres, hit, o, d);
#else
    (void)o, (void)d;
#endif
    return surface_at(sc, hit);
}

/* The origin of a ray leaving surface s on the side of its (oriented) geometric normal n. */
inline float3 surface_offset(const Surface* s, float3 n) {
#if FC_HAS_SPHERES
    if (s->p_error.x > 0.0f) return sphere_offset_origin(s->p, s->p_error, n);
#endif
    return offset_ray_origin(s->p, n);
}

/* Two-sided shading: turns surface `s` to the side the ray arrived from (wo points back
 * along it) and returns the shading frame there, with wo in it in *wo_local. A ray arriving
 * from behind the normals (the inside of a closed dielectric) flips ng and ns and sees the
 * relative index n_outside / n_inside = 1 / ior (docs/conventions.md). A shading normal
 * facing away from the viewer is replaced by the geometric one. An anisotropic material
 * gets its roughness stretched and a frame whose x axis is its anisotropy direction
 * (kernels/bsdf/anisotropy.cl), the same physical direction seen from either side. The
 * coat's own normal (if any) is turned with the surface and brought into the frame. */
inline Frame surface_orient(Surface* s, FcMaterial* mat, float3 wo, float3* wo_local) {
#if FC_HAS_ANISOTROPY
    const bool aniso = (mat->flags & FC_MAT_ANISOTROPIC) != 0u;
    float3 axis = (float3)(0.0f);
    if (aniso) {
        anisotropy_apply(mat);
        axis = anisotropy_axis(mat, s->ns, s->tangent);
    }
#endif
    bool flipped = dot(s->ng, wo) < 0.0f;
    if (flipped) {
        s->ng = -s->ng;
        s->ns = -s->ns;
        if (bsdf_is_dielectric(mat)) mat->ior = 1.0f / mat->ior;
    }
    Frame frame = frame_from_normal(s->ns);
#if FC_HAS_ANISOTROPY
    if (aniso) frame = frame_from_normal_axis(s->ns, axis);
#endif
    *wo_local = frame_to_local(&frame, wo);
    if (wo_local->z <= 0.0f) {
        s->ns = s->ng;
        frame = frame_from_normal(s->ng);
#if FC_HAS_ANISOTROPY
        if (aniso) frame = frame_from_normal_axis(s->ng, axis);
#endif
        *wo_local = frame_to_local(&frame, wo);
    }
    clearcoat_normal_to_shading(mat, &frame, wo, flipped); /* the coat's own normal, if any */
    return frame;
}

#endif
