/* Test kernels for tests/instancing_test.cpp: rays against a whole scene (world triangles,
 * instances, spheres) through scene_trace_closest / scene_trace_any, and the surface at
 * each closest hit. */
#ifndef FACET_TEST_INSTANCE_KERNELS_CL
#define FACET_TEST_INSTANCE_KERNELS_CL

/* The kernel binds no materials: no alpha test (kernels/trace/alpha_test.cl), and no
 * anisotropic tangents (surface_at reads the material's flags). */
#define FC_HAS_ALPHA 0
#define FC_HAS_ANISOTROPY 0

#include "kernels/integrator/surface.cl"

/* origins[i].xyz, dirs[i].xyz, dirs[i].w = tmax. Closest hit: hit_out[i] = (t, p), on a miss
 * t = -1; ng_out[i] = (ng, as_float(prim)); ns_out[i] = (ns, as_float(inst)); any_out[i]:
 * scene_trace_any's answer. */
__kernel void trace_scene_batch(__global const FcBvhNode* nodes, __global const FcTriangle* tris,
                                __global const FcTriShading* shading, __global const float4* face_normals,
                                __global const FcSphere* spheres, __global const FcBvhNode* sphere_nodes,
                                __global const FcInstance* instances, __global const FcBvhNode* instance_nodes,
                                __global const float4* origins, __global const float4* dirs, __global float4* hit_out,
                                __global float4* ng_out, __global float4* ns_out, __global int* any_out) {
    const size_t i = get_global_id(0);
    SceneView sc = {.nodes = nodes,
                    .tris = tris,
                    .shading = shading,
                    .face_normals = face_normals,
                    .spheres = spheres,
                    .sphere_nodes = sphere_nodes,
                    .instances = instances,
                    .instance_nodes = instance_nodes};
    const float3 o = origins[i].xyz, d = dirs[i].xyz;
    const float tmax = dirs[i].w;
    Hit hit;
    if (scene_trace_closest(&sc, o, d, tmax, 0u, &hit)) {
        const Surface s = scene_surface_at(&sc, &hit, o, d);
        hit_out[i] = (float4)(hit.t, s.p);
        ng_out[i] = (float4)(s.ng, as_float(s.prim));
        ns_out[i] = (float4)(s.ns, as_float(hit.inst));
    } else {
        hit_out[i] = (float4)(-1.0f, 0.0f, 0.0f, 0.0f);
        ng_out[i] = ns_out[i] = (float4)(0.0f);
    }
    any_out[i] = scene_trace_any(&sc, o, d, tmax, 0u) ? 1 : 0;
}

#endif
