/* Textured materials: the textures bound to a material (FcMaterialTextures) read at a
 * hit and written into the material's parameters and the shading normal, before the
 * BSDF sees them. The BSDF code is unchanged: a texture is one more input to the same
 * FcMaterial (docs/textures.md). Compiled only when the scene has textures
 * (FC_HAS_TEXTURES). */
#ifndef FACET_TEXTURE_MATERIAL_TEXTURES_CL
#define FACET_TEXTURE_MATERIAL_TEXTURES_CL

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

/* Sets the microfacet roughness (and the Phong-style exponents that follow from it,
 * e = 2 / alpha^2 - 2). */
inline void set_roughness(FcMaterial* mat, float alpha_x, float alpha_y) {
    mat->alpha_x = alpha_x;
    mat->alpha_y = alpha_y;
    mat->exponent_x = clamp(2.0f / fmax(alpha_x * alpha_x, 1e-12f) - 2.0f, 0.0f, FC_PHONG_EXPONENT_MAX);
    mat->exponent_y = clamp(2.0f / fmax(alpha_y * alpha_y, 1e-12f) - 2.0f, 0.0f, FC_PHONG_EXPONENT_MAX);
}

/* The spread of the normals a minified normal-map texel averages, added to the roughness so
 * that bumps seen from afar keep their look instead of flattening into a mirror (Toksvig
 * 2005; here in the von Mises-Fisher form of Han et al. 2007, "Frequency Domain Normal Map
 * Filtering"). `len` is the length of the mean of the unit normals under the texel (the
 * alpha of a normal map's smaller levels, host/scene/normal_map_pyramid.cpp; 1 at level 0).
 * A vMF lobe of that mean length has concentration kappa = (3 len - len^3) / (1 - len^2)
 * (Banerjee et al. 2005), and exp(kappa cos t) ~ exp(-kappa t^2 / 2) matches a microfacet
 * distribution exp(-t^2 / alpha^2) of alpha^2 = 2 / kappa; slope variances add. The map's
 * scale scales the slopes, so their variance by scale^2. */
inline void add_normal_spread(FcMaterial* mat, float len, float scale) {
    if (!(len < 1.0f)) return;
    float r = fmax(len, 1e-3f);
    float spread = 2.0f * (1.0f - r * r) / (3.0f * r - r * r * r) * scale * scale;
    set_roughness(mat, sqrt(fmin(mat->alpha_x * mat->alpha_x + spread, 1.0f)),
                  sqrt(fmin(mat->alpha_y * mat->alpha_y + spread, 1.0f)));
}

/* Writes the textures of material `material` at hit `hit` into `mat` and the shading
 * normal `ns`. `cone` is the ray cone's width at the hit, `d` the ray's direction. */
inline void apply_textures(const SceneView* sc, const Hit* hit, int material, float3 d, float cone, float3* ns,
                           FcMaterial* mat) {
    __global const FcMaterialTextures* mt = &sc->material_textures[material];
    if (mt->base_color < 0 && mt->specular < 0 && mt->roughness < 0 && mt->metalness < 0 && mt->emission < 0 &&
        mt->normal < 0)
        return;
    TexPoint p;
    if (hit->tri == FC_HIT_SPHERE) { /* ns is the exact normal, inward for an inward sphere */
        __global const FcSphere* sp = &sc->spheres[hit->prim];
        p = tex_point_sphere(sp, (sp->flags & FC_SPHERE_INWARD) ? -*ns : *ns);
    } else {
        float3 v0, v1, v2; /* world space: dp/du and the areas of the placed triangle */
        hit_triangle_vertices(sc, hit, &v0, &v1, &v2);
        p = tex_point(sc->texcoords, hit->prim, hit->u, hit->v, v1 - v0, v2 - v0);
#if FC_HAS_INSTANCES
        /* An instanced mesh's vertex tangents are in object space, like its vertices. */
        if (hit->inst >= 0 && p.tangent.w != 0.0f)
            p.tangent = instance_tangent_to_world(&sc->instances[hit->inst], p.tangent);
#endif
    }
    float2 uv = tex_transform(mt, p.uv);
    float cos_hit = dot(*ns, d);

    /* Base colour and specular colour (or the metallic workflow's pair). */
    float3 base = load3(mt->base_factor);
    if (mt->base_color >= 0) {
        float3 c = tex_lookup(sc, mt->base_color, uv, &p, cone, cos_hit).xyz;
        if (mt->flags & FC_TEX_METALLIC_WORKFLOW) base *= c;
        else tex_store3(mat->diffuse, load3p(mat->diffuse) * c);
    }
    if (mt->flags & FC_TEX_METALLIC_WORKFLOW) {
        float metal = mt->metallic_factor;
        if (mt->metalness >= 0)
            metal *= tex_channel(tex_lookup(sc, mt->metalness, uv, &p, cone, cos_hit), mt->metal_channel);
        /* glTF's mix of a dielectric (F0 dielectric_f0 over the base) and a metal (F0 base) by
         * metalness, kernels/bsdf/metallic.cl. */
        tex_store3(mat->diffuse, base);
        tex_store3(mat->specular, (float3)(mt->dielectric_f0));
        mat->metallic = clamp(metal, 0.0f, 1.0f);
    }
    if (mt->specular >= 0)
        tex_store3(mat->specular, load3p(mat->specular) * tex_lookup(sc, mt->specular, uv, &p, cone, cos_hit).xyz);

    /* Roughness: perceptual (alpha scaled by r^2) or a Phong exponent map. */
    if (mt->roughness >= 0) {
        float r = tex_channel(tex_lookup(sc, mt->roughness, uv, &p, cone, cos_hit), mt->roughness_channel);
        if (mt->roughness_mode == FC_ROUGHNESS_SHININESS) {
            float e = clamp(mat->exponent_x * r, 0.0f, FC_PHONG_EXPONENT_MAX);
            mat->exponent_x = mat->exponent_y = e;
            mat->alpha_x = mat->alpha_y = sqrt(2.0f / (e + 2.0f));
        } else {
            float s = r * r;
            set_roughness(mat, mat->alpha_x * s, mat->alpha_y * s);
        }
    }
    /* Sphere lights are sampled with their untextured emission (sphere_light.cl): an
     * emission texture on a sphere is left out on both sides, so the two estimates agree. */
    if (mt->emission >= 0 && hit->tri != FC_HIT_SPHERE)
        tex_store3(mat->emission, load3p(mat->emission) * tex_lookup(sc, mt->emission, uv, &p, cone, cos_hit).xyz);
    if (mt->normal >= 0) {
        float4 n = tex_lookup(sc, mt->normal, uv, &p, cone, cos_hit);
        *ns = normal_mapped(*ns, &p, n.xyz, mt->normal_scale);
        add_normal_spread(mat, n.w, mt->normal_scale);
    }
}

/* The emission of scene triangle `prim` (material `material`) at a light sample's
 * barycentrics b along the light's edges (FcLight e1, e2): the emission texture at full
 * resolution, or 1 when the material has none. */
inline float3 emission_texture_at(const SceneView* sc, int prim, int material, float2 b) {
    __global const FcMaterialTextures* mt = &sc->material_textures[material];
    if (mt->emission < 0) return (float3)(1.0f);
    __global const FcTriTexcoords* t = &sc->texcoords[prim];
    if (t->light_swapped) b = b.yx;
    float2 uv0 = (float2)(t->uv[0][0], t->uv[0][1]);
    float2 uv =
        uv0 + b.x * ((float2)(t->uv[1][0], t->uv[1][1]) - uv0) + b.y * ((float2)(t->uv[2][0], t->uv[2][1]) - uv0);
    return texture_sample(sc->textures, sc->texels, mt->emission, tex_transform(mt, uv), 0.0f).xyz;
}

#endif
