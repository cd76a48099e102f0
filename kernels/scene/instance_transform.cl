/* An instance's transforms (kernels/shared/instance_layout.h), written once for the
 * traversal (rays into the mesh's space), the surface (positions, normals) and the texture
 * frames (tangents). Points take the whole 3x4 matrix, vectors and tangents its linear part,
 * normals the inverse transpose of the linear part (the transpose of world_to_object's), so
 * that they stay perpendicular to the surface under non-uniform scales and mirrors. */
#ifndef FACET_SCENE_INSTANCE_TRANSFORM_CL
#define FACET_SCENE_INSTANCE_TRANSFORM_CL

#include "kernels/shared/instance_layout.h"

/* m (rows of four floats) times (p, 1). */
inline float3 affine_point(__global const float* m, float3 p) {
    return (float3)(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                    m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
}

/* m's linear part times v. */
inline float3 affine_vector(__global const float* m, float3 v) {
    return (float3)(m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
                    m[8] * v.x + m[9] * v.y + m[10] * v.z);
}

/* m's linear part, transposed, times v. */
inline float3 affine_vector_transposed(__global const float* m, float3 v) {
    return (float3)(m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
                    m[2] * v.x + m[6] * v.y + m[10] * v.z);
}

inline float3 instance_point_to_world(__global const FcInstance* in, float3 p) {
    return affine_point(&in->object_to_world[0][0], p);
}

/* Directions and tangents (dp/du, edges). */
inline float3 instance_vector_to_world(__global const FcInstance* in, float3 v) {
    return affine_vector(&in->object_to_world[0][0], v);
}

/* A vertex tangent (xyz) with its handedness (w = +-1) placed in the world: the tangent
 * by the linear part, the handedness flipped by a mirroring transform (negative
 * determinant), since the bitangent is built as w cross(n, t) from the placed n and t. */
inline float4 instance_tangent_to_world(__global const FcInstance* in, float4 t) {
    __global const float* m = &in->object_to_world[0][0];
    const float3 c0 = affine_vector(m, (float3)(1.0f, 0.0f, 0.0f)), c1 = affine_vector(m, (float3)(0.0f, 1.0f, 0.0f)),
                 c2 = affine_vector(m, (float3)(0.0f, 0.0f, 1.0f));
    const float det = dot(c0, cross(c1, c2));
    return (float4)(affine_vector(m, t.xyz), det < 0.0f ? -t.w : t.w);
}

/* A normal, not renormalised. */
inline float3 instance_normal_to_world(__global const FcInstance* in, float3 n) {
    return affine_vector_transposed(&in->world_to_object[0][0], n);
}

inline float3 instance_point_to_object(__global const FcInstance* in, float3 p) {
    return affine_point(&in->world_to_object[0][0], p);
}

/* A ray direction, not renormalised: t along the object-space ray is the world ray's t. */
inline float3 instance_vector_to_object(__global const FcInstance* in, float3 v) {
    return affine_vector(&in->world_to_object[0][0], v);
}

#endif
