/* Vertex tangents of scene triangles (FcTriTexcoords.tangent, kernels/shared/texture_layout.h):
 * octahedral-decoded and interpolated at a hit. Normal maps (kernels/texture/material_textures.cl)
 * and anisotropic materials (kernels/bsdf/anisotropy.cl) read them. */
#ifndef FACET_SCENE_VERTEX_TANGENT_CL
#define FACET_SCENE_VERTEX_TANGENT_CL

#include "kernels/shared/all.h"

/* The unit vector of an octahedral code (kernels/shared/texture_layout.h: two 16-bit
 * signed normalised integers, x in the low half). */
inline float3 tex_octahedral_decode(uint code) {
    int ix = (int)(code & 0xffffu), iy = (int)(code >> 16);
    float x = (float)(ix >= 32768 ? ix - 65536 : ix) / 32767.0f;
    float y = (float)(iy >= 32768 ? iy - 65536 : iy) / 32767.0f;
    float3 v = (float3)(x, y, 1.0f - fabs(x) - fabs(y));
    float fold = fmax(-v.z, 0.0f); /* the lower half, unfolded over the diagonals */
    v.x += v.x >= 0.0f ? -fold : fold;
    v.y += v.y >= 0.0f ? -fold : fold;
    return normalize(v);
}

/* The triangle's corner tangents interpolated at barycentrics (b1, b2), with the
 * handedness of the nearest corner; w = 0 when it has none. */
inline float4 tex_tangent(__global const FcTriTexcoords* t, float b1, float b2) {
    if (!(t->tangent_flags & FC_TANGENTS_SET)) return (float4)(0.0f);
    float b0 = 1.0f - b1 - b2;
    float3 v = b0 * tex_octahedral_decode(t->tangent[0]) + b1 * tex_octahedral_decode(t->tangent[1]) +
               b2 * tex_octahedral_decode(t->tangent[2]);
    int nearest = b0 >= b1 && b0 >= b2 ? 0 : b1 >= b2 ? 1 : 2;
    return (float4)(v, ((t->tangent_flags >> nearest) & 1u) ? -1.0f : 1.0f);
}

#endif
