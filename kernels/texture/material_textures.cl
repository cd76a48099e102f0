/* Textured materials: the textures bound to a material (FcMaterialTextures) read at a
 * hit and written into the material's parameters and the shading normal, before the
 * BSDF sees them. The BSDF code is unchanged: a texture is one more input to the same
 * FcMaterial (docs/textures.md). Compiled only when the scene has textures
 * (FC_HAS_TEXTURES). */
#ifndef FACET_TEXTURE_MATERIAL_TEXTURES_CL
#define FACET_TEXTURE_MATERIAL_TEXTURES_CL

#include "kernels/texture/extension_textures.cl"
#include "kernels/texture/tex_point.cl"

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
        mt->normal < 0 && !extension_textures_bound(mt))
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
    float3 ns_surface = *ns; /* before the normal map: the coat's without a map of its own */

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
    /* glTF's extensions: clearcoat, sheen, KHR_materials_specular (after the dielectric's F0 above). */
    apply_extension_textures(sc, mt, uv, &p, cone, cos_hit, mat);

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
    apply_clearcoat_normal(sc, mt, uv, &p, cone, cos_hit, ns_surface, *ns, mat);
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
