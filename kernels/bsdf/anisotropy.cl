/* Anisotropic materials (FC_MAT_ANISOTROPIC): glTF's KHR_materials_anisotropy on facet's
 * anisotropic microfacet lobes, and the shading frame that follows the surface's tangent
 * (docs/brdf.md, "Anisotropy").
 *
 * Parameters: FcMaterial.anisotropy, the strength s in [0, 1], and anisotropy_direction,
 * (cos theta, sin theta) of the rotation theta. The extension's mapping (its spec,
 * "Implementation"): the roughness along the anisotropy direction alpha_t = mix(alpha, 1, s^2),
 * across it alpha_b = alpha; the direction is the tangent turned by theta toward the
 * bitangent. GGX and Beckmann take alpha_x along the shading frame's x axis (ggx.cl), so
 * alpha_x becomes alpha_t and the frame's x axis the direction, made orthogonal to the
 * shading normal (Gram-Schmidt). Materials with alpha_x != alpha_y of their own (scene files)
 * are oriented the same way. The Phong-style exponents are not stretched: Blinn-Phong and
 * Ashikhmin-Shirley take exponent_x / exponent_y as given, along the same frame.
 *
 * The tangent: the interpolated vertex tangent with its handedness w (the file's TANGENT,
 * or computed from the uvs as for normal maps, host/scene/texture_tangents.cpp), the
 * bitangent w cross(n, t) (glTF's rule). Analytic spheres and triangles without a tangent
 * (no uvs) use dp/dphi about the world's +y axis, cross(n, +y) normalised (+x where n is
 * along y): on a sphere the direction of increasing u (kernels/trace/sphere.cl's
 * sphere_tangent), on a mesh "brushed around the vertical". */
#ifndef FACET_BSDF_ANISOTROPY_CL
#define FACET_BSDF_ANISOTROPY_CL

#include "kernels/shared/material_layout.h"
#include "kernels/util/frame.cl"

/* alpha_x stretched toward 1 by the strength s: alpha_t = mix(alpha, 1, s^2). */
inline void anisotropy_apply(FcMaterial* m) {
    float s = m->anisotropy;
    if (!(s > 0.0f)) return; /* 0, negative or NaN: as it is */
    s = fmin(s, 1.0f);
    m->alpha_x = mix(m->alpha_x, 1.0f, s * s);
}

/* The material's anisotropy direction in world space at unit shading normal n: the
 * tangent t (xyz, w the handedness; w = 0 for none) made orthogonal to n and turned by
 * anisotropy_direction toward the bitangent w cross(n, t). Unit length, orthogonal to n. */
inline float3 anisotropy_axis(const FcMaterial* m, float3 n, float4 t) {
    float3 x = t.xyz - n * dot(n, t.xyz);
    float w = t.w;
    if (!(w != 0.0f) || !(dot(x, x) > 1e-12f)) { /* the fallback: dp/dphi about +y */
        x = (float3)(-n.z, 0.0f, n.x);
        w = 1.0f;
        if (!(dot(x, x) > 1e-12f)) x = (float3)(1.0f, 0.0f, 0.0f) - n * n.x;
    }
    x = normalize(x);
    float3 b = w * cross(n, x);
    return m->anisotropy_direction[0] * x + m->anisotropy_direction[1] * b;
}

/* The frame around unit n whose x axis is `axis` made orthogonal to n; frame_from_normal's
 * where the axis is (nearly) along n. */
inline Frame frame_from_normal_axis(float3 n, float3 axis) {
    float3 x = axis - n * dot(n, axis);
    if (!(dot(x, x) > 1e-8f)) return frame_from_normal(n);
    Frame f;
    f.s = normalize(x);
    f.t = cross(n, f.s);
    f.n = n;
    return f;
}

#endif
