/* Kernels of tests/anisotropy_test.cpp: the shading frame and the material that
 * surface_orient (kernels/integrator/surface.cl) makes of a material at a surface point,
 * with FC_HAS_ANISOTROPY as a scene with an anisotropic material builds it. */
#include "kernels/integrator/surface.cl"

/* Item i: material mats[i] at a surface point of unit normal n (geometric and shading) and
 * vertex tangent t (xyz, handedness w; 0 for none), seen from world direction wo[i].
 * out_mat[i]: the material as the BSDF sees it; out_wo[i]: wo in the shading frame;
 * out_f[i]: the BSDF's value toward world direction wi[i] (xyz), and its density (w). */
__kernel void aniso_orient_batch(__global const FcMaterial* mats, float4 n, float4 t, __global const float4* wo,
                                 __global const float4* wi, __global FcMaterial* out_mat, __global float4* out_wo,
                                 __global float4* out_f) {
    int i = (int)get_global_id(0);
    Surface s;
    s.p = (float3)(0.0f);
    s.ng = s.ns = n.xyz;
    s.prim = 0;
    s.material = 0;
    s.light = -1;
    s.p_error = (float3)(0.0f);
    s.tangent = t;
    FcMaterial m = mats[i];
    float3 wo_local;
    Frame frame = surface_orient(&s, &m, wo[i].xyz, &wo_local);
    float3 wi_local = frame_to_local(&frame, wi[i].xyz);
    out_mat[i] = m;
    out_wo[i] = (float4)(wo_local, 0.0f);
    out_f[i] = (float4)(bsdf_eval(&m, wo_local, wi_local), bsdf_pdf(&m, wo_local, wi_local));
}
