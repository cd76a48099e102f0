/* Test kernels for tests/sphere_test.cpp: the ray/sphere roots, the spheres' tree, chains of
 * rays bouncing inside a sphere from offset origins, and the sphere light's sampling. */
#ifndef FACET_TEST_SPHERE_KERNELS_CL
#define FACET_TEST_SPHERE_KERNELS_CL

#include "kernels/integrator/surface.cl"
#include "kernels/lights/sphere_light.cl"

/* sphere = (centre, radius), origins[i].xyz, dirs[i].xyz: roots[i] = (t0, t1), NaN on a miss. */
__kernel void sphere_roots_batch(float4 sphere, __global const float4* origins, __global const float4* dirs,
                                 __global float2* roots) {
    const uint i = get_global_id(0);
    float t0, t1;
    if (sphere_roots(sphere.xyz, sphere.w, origins[i].xyz, dirs[i].xyz, &t0, &t1)) roots[i] = (float2)(t0, t1);
    else roots[i] = (float2)(NAN);
}

/* The nearest sphere of the tree along origins[i] + t dirs[i].xyz, t < dirs[i].w:
 * out[i] = (t, as_float(sphere index in the FcSphere array)), index -1 on a miss. */
__kernel void trace_spheres_batch(__global const FcBvhNode* nodes, __global const FcSphere* spheres,
                                  __global const float4* origins, __global const float4* dirs, __global float2* out) {
    const uint i = get_global_id(0);
    Hit hit;
    hit.t = dirs[i].w;
    hit.prim = -1;
    hit.tri = -1;
    trace_spheres(nodes, spheres, origins[i].xyz, dirs[i].xyz, &hit, false);
    out[i] = (float2)(hit.t, as_float(hit.prim));
}

/* A ray from outside (origins[i], dirs[i]) enters the sphere, bounces `bounces` times inside
 * along the directions bounce_dirs[i * bounces + k] (turned inward) and leaves along
 * exit_dirs[i] (turned outward), every new ray from the surface's offset origin. leaks[i]
 * counts the rays that went wrong: an inside ray that misses the sphere or meets it again at
 * less than 1% of the chord, and a leaving ray that meets it at all. -1: the first ray
 * missed. */
__kernel void sphere_leaks(float4 sphere, uint bounces, __global const float4* origins, __global const float4* dirs,
                           __global const float4* bounce_dirs, __global const float4* exit_dirs, __global int* leaks) {
    const uint i = get_global_id(0);
    const float3 c = sphere.xyz;
    const float r = sphere.w;
    float3 o = origins[i].xyz, d = dirs[i].xyz;
    float t;
    if (!sphere_hit(c, r, o, d, INFINITY, &t)) {
        leaks[i] = -1;
        return;
    }
    int count = 0;
    float3 n, err;
    float3 p = sphere_hit_point(c, r, o, d, t, &n, &err);
    for (uint k = 0; k < bounces; ++k) {
        float3 w = normalize(bounce_dirs[i * bounces + k].xyz);
        if (dot(w, n) > 0.0f) w = -w;
        const float chord = 2.0f * r * -dot(w, n);
        o = sphere_offset_origin(p, err, -n);
        if (!sphere_hit(c, r, o, w, INFINITY, &t) || t < 0.01f * chord) {
            ++count;
            break;
        }
        p = sphere_hit_point(c, r, o, w, t, &n, &err);
    }
    float3 w = normalize(exit_dirs[i].xyz);
    if (dot(w, n) < 0.0f) w = -w;
    if (sphere_hit(c, r, sphere_offset_origin(p, err, n), w, INFINITY, &t)) ++count;
    leaks[i] = count;
}

/* sphere_offset_origin(p[i], err[i], n[i]) in out[2i] and the same point stepped by
 * nextafter coordinate by coordinate (its definition) in out[2i + 1]. */
__kernel void sphere_offset_batch(__global const float4* p, __global const float4* err, __global const float4* n,
                                  __global float4* out) {
    const uint i = get_global_id(0);
    const float3 ni = n[i].xyz;
    float3 po = p[i].xyz + 2.0f * dot(fabs(ni), err[i].xyz) * ni;
    po.x = ni.x > 0.0f ? nextafter(po.x, INFINITY) : (ni.x < 0.0f ? nextafter(po.x, -INFINITY) : po.x);
    po.y = ni.y > 0.0f ? nextafter(po.y, INFINITY) : (ni.y < 0.0f ? nextafter(po.y, -INFINITY) : po.y);
    po.z = ni.z > 0.0f ? nextafter(po.z, INFINITY) : (ni.z < 0.0f ? nextafter(po.z, -INFINITY) : po.z);
    out[2 * i] = (float4)(sphere_offset_origin(p[i].xyz, err[i].xyz, ni), 0.0f);
    out[2 * i + 1] = (float4)(po, 0.0f);
}

/* Light `l` seen from p: pdfs[i] = sphere_light_pdf for the direction dirs[i] (0 where it
 * misses the sphere). */
__kernel void sphere_light_pdf_batch(__global const FcLight* l, float4 p, __global const float4* dirs,
                                     __global float* pdfs) {
    const uint i = get_global_id(0);
    const float3 w = normalize(dirs[i].xyz);
    float t;
    pdfs[i] = 0.0f;
    if (!sphere_hit(load3(l->p0), l->e1[0], p.xyz, w, INFINITY, &t)) return;
    const float3 n = normalize(p.xyz + t * w - load3(l->p0));
    pdfs[i] = sphere_light_pdf(l, p.xyz, t, dot(n, w));
}

/* Samples of light `l` from p: points[i] = (point, pdf), check[i] = (distance of the point from
 * the sphere relative to r, the density sphere_light_pdf gives the same direction, cosine at the
 * light toward p along the emitting normal, 0). */
__kernel void sphere_light_sample_batch(__global const FcLight* l, float4 p, __global const float2* u,
                                        __global float4* points, __global float4* check) {
    const uint i = get_global_id(0);
    float3 point, normal;
    float pdf;
    if (!sphere_light_sample(l, p.xyz, u[i], &point, &normal, &pdf)) {
        points[i] = (float4)(NAN);
        check[i] = (float4)(NAN);
        return;
    }
    const float3 c = load3(l->p0);
    const float r = l->e1[0];
    const float3 w = normalize(point - p.xyz);
    float t;
    float pdf_again = -1.0f;
    if (sphere_hit(c, r, p.xyz, w, INFINITY, &t))
        pdf_again = sphere_light_pdf(l, p.xyz, t, dot(normalize(p.xyz + t * w - c), w));
    points[i] = (float4)(point, pdf);
    check[i] = (float4)(fabs(length(point - c) - r) / r, pdf_again, dot(normal, -w), 0.0f);
}

/* The parametrisation at unit normals[i]: out[i] = (u, v), tangents[i] = dp/du's direction. */
__kernel void sphere_uv_batch(__global const float4* normals, __global float2* out, __global float4* tangents) {
    const uint i = get_global_id(0);
    const float3 n = normals[i].xyz;
    out[i] = sphere_uv(n);
    tangents[i] = (float4)(sphere_tangent(n), 0.0f);
}

#endif
