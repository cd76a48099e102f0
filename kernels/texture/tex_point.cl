/* A hit point as textures see it (TexPoint: uv, surface derivatives, areas, vertex tangent),
 * filtered lookups for a ray cone, and tangent-space normal mapping: the pieces the material
 * textures (material_textures.cl) and the glTF extensions' textures (extension_textures.cl)
 * share. Compiled only when the scene has textures (FC_HAS_TEXTURES). */
#ifndef FACET_TEXTURE_TEX_POINT_CL
#define FACET_TEXTURE_TEX_POINT_CL

#include "kernels/scene/scene_view.cl"
#include "kernels/scene/vertex_tangent.cl"
#include "kernels/texture/texture.cl"
#include "kernels/trace/bvh_traverse.cl"
#include "kernels/trace/instance.cl"
#include "kernels/trace/sphere.cl"

/* A hit point's texture coordinates and what filtering and normal maps need. */
typedef struct {
    float2 uv;
    float3 dpdu, dpdv; /* surface derivatives along u and v (zero where the uvs are degenerate) */
    float uv_area;     /* the triangle's area in the (u, v) square */
    float world_area;  /* and in world units */
    float4 tangent;    /* the vertex tangents interpolated (xyz) and the handedness (w = +-1);
                        * w = 0 where the triangle has none (dp/du is used) */
} TexPoint;

/* The width of the ray cone at distance `dist` along the path from the camera: the
 * pixel's footprint (Akenine-Möller et al. 2019). A perspective camera's cone spreads
 * by one pixel's angle 2 tan(fov_y / 2) / height; an orthographic one keeps its pixel's
 * width. Bounces keep the camera's spread (surface curvature is not followed). */
inline float ray_cone_width(__constant const FcRenderParams* P, float dist) {
    float pixel = 2.0f * length(load3c(P->camera.up)) / (float)P->height;
    return P->camera.projection == FC_PROJECTION_PERSPECTIVE ? pixel * dist : pixel;
}

/* The texture point of scene triangle `prim` at barycentrics (b1, b2) of v1 and v2,
 * with edges e1 = v1 - v0, e2 = v2 - v0. */
inline TexPoint tex_point(__global const FcTriTexcoords* tc, int prim, float b1, float b2, float3 e1, float3 e2) {
    __global const FcTriTexcoords* t = &tc[prim];
    float2 uv0 = (float2)(t->uv[0][0], t->uv[0][1]);
    float2 d1 = (float2)(t->uv[1][0], t->uv[1][1]) - uv0;
    float2 d2 = (float2)(t->uv[2][0], t->uv[2][1]) - uv0;
    TexPoint p;
    p.uv = uv0 + b1 * d1 + b2 * d2;
    float det = d1.x * d2.y - d1.y * d2.x;
    p.uv_area = 0.5f * fabs(det);
    p.world_area = 0.5f * length(cross(e1, e2));
    float inv = det != 0.0f ? 1.0f / det : 0.0f;
    p.dpdu = (d2.y * e1 - d1.y * e2) * inv;
    p.dpdv = (d1.x * e2 - d2.x * e1) * inv;
    p.tangent = tex_tangent(t, b1, b2);
    return p;
}

/* The texture point of analytic sphere `sp` whose outward normal at the hit is n, by
 * sphere_uv's parametrisation: u = phi / 2pi, v = theta / pi with n = (sin theta cos phi,
 * cos theta, sin theta sin phi); dp/du = 2 pi r (-sin theta sin phi, 0, sin theta cos phi),
 * dp/dv = pi r (cos theta cos phi, -sin theta, cos theta sin phi), and the world area per
 * unit uv area |dp/du x dp/dv| = 2 pi^2 r^2 sin theta (kept above 1e-4 of its equator
 * value at the poles). */
inline TexPoint tex_point_sphere(__global const FcSphere* sp, float3 n) {
    TexPoint p;
    p.uv = sphere_uv(n);
    const float r = sp->radius;
    const float sin_theta = sqrt(fmax(0.0f, 1.0f - n.y * n.y));
    const float3 radial = sin_theta > 0.0f ? (float3)(n.x, 0.0f, n.z) / sin_theta : (float3)(1.0f, 0.0f, 0.0f);
    p.dpdu = 2.0f * FC_PI * r * sin_theta * (float3)(-radial.z, 0.0f, radial.x);
    p.dpdv = FC_PI * r * (float3)(n.y * radial.x, -sin_theta, n.y * radial.z);
    p.uv_area = 1.0f;
    p.world_area = 2.0f * FC_PI * FC_PI * r * r * fmax(sin_theta, 1e-4f);
    p.tangent = (float4)(0.0f);
    return p;
}

inline void tex_store3(float* p, float3 v) {
    p[0] = v.x;
    p[1] = v.y;
    p[2] = v.z;
}

/* Channel i (0: R ... 3: A) of a texel; OpenCL C has no run-time subscript of vectors. */
inline float tex_channel(float4 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : i == 2 ? v.z : v.w; }

/* Texture `index` at the point, filtered for a cone of width `cone` meeting the surface
 * at cosine `cos_hit`. */
inline float4 tex_lookup(const SceneView* sc, int index, float2 uv, const TexPoint* p, float cone, float cos_hit) {
    __global const FcTexture* t = &sc->textures[index];
    float lod = texture_lod(t->width * t->height, p->uv_area, p->world_area, cone, cos_hit);
    return texture_sample(sc->textures, sc->texels, index, uv, lod);
}

/* The tangent-space normal map's normal: x along the tangent, y along the bitangent
 * (toward the image's top, the OpenGL / glTF / MikkTSpace convention), z along ns. The
 * tangent is the interpolated vertex tangent (the file's or MikkTSpace-style) made
 * orthogonal to ns (Gram-Schmidt), the bitangent w cross(ns, t) (glTF's rule); a
 * triangle without vertex tangents uses its dp/du, the handedness from its uv winding. */
inline float3 normal_mapped(float3 ns, const TexPoint* p, float3 texel, float scale) {
    float3 m = 2.0f * texel - 1.0f;
    m.xy *= scale;
    float3 t0 = p->tangent.w != 0.0f ? p->tangent.xyz : p->dpdu;
    float3 t = t0 - ns * dot(ns, t0);
    if (!(dot(t, t) > 0.0f)) return ns;
    t = normalize(t);
    float3 b = cross(ns, t);
    if (p->tangent.w != 0.0f) b *= p->tangent.w;
    else if (dot(b, p->dpdv) > 0.0f) b = -b;
    return normalize_or(m.x * t + m.y * b + m.z * ns, ns);
}

#endif
