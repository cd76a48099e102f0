/* Test kernels for tests/texture_test.cpp: texture lookups at given (u, v, lod), and
 * the normal-map frame at given texels. */
#include "kernels/texture/texture.cl"
#include "kernels/texture/material_textures.cl"

/* texture_sample of texture `index` at each (u, v, lod) of `uvl` (xyz). */
__kernel void texture_lookup_batch(__global const FcTexture* textures, __global const uint* texels, int index,
                                   __global const float4* uvl, __global float4* out) {
    uint i = (uint)get_global_id(0);
    float4 q = uvl[i];
    out[i] = texture_sample(textures, texels, index, q.xy, q.z);
}

/* normal_mapped on the z = 0 plane with uvs u = x, v = -y (dp/du = +x, dp/dv = -y),
 * shading normal +z, for each texel of `in` (xyz) with scale in w. */
__kernel void normal_map_batch(__global const float4* in, __global float4* out) {
    uint i = (uint)get_global_id(0);
    TexPoint p;
    p.uv = (float2)(0.0f);
    p.dpdu = (float3)(1.0f, 0.0f, 0.0f);
    p.dpdv = (float3)(0.0f, -1.0f, 0.0f);
    p.uv_area = p.world_area = 1.0f;
    p.tangent = (float4)(0.0f);
    out[i] = (float4)(normal_mapped((float3)(0.0f, 0.0f, 1.0f), &p, in[i].xyz, in[i].w), 0.0f);
}

/* add_normal_spread for each (alpha_x, alpha_y, len, scale) of `in`: the roughened
 * (alpha_x, alpha_y, exponent_x, exponent_y). */
__kernel void normal_spread_batch(__global const float4* in, __global float4* out) {
    uint i = (uint)get_global_id(0);
    FcMaterial m;
    set_roughness(&m, in[i].x, in[i].y);
    add_normal_spread(&m, in[i].z, in[i].w);
    out[i] = (float4)(m.alpha_x, m.alpha_y, m.exponent_x, m.exponent_y);
}

/* tex_tangent (the frame normal_mapped reads) for each query (x: the scene triangle,
 * y, z: the barycentrics of its v1 and v2): the interpolated vertex tangent (xyz) and
 * the handedness (w; 0 where the triangle has no tangents). */
__kernel void tangent_batch(__global const FcTriTexcoords* texcoords, __global const float4* query,
                            __global float4* out) {
    uint i = (uint)get_global_id(0);
    float4 q = query[i];
    out[i] = tex_tangent(&texcoords[(int)q.x], q.y, q.z);
}
