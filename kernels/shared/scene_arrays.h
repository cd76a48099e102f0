/* The closed list of scene arrays: every buffer the kernels read besides the parameter
 * block, written once (as Cycles' kernel/data_arrays.h). From it are generated the scene
 * arguments of render_pass and aov_pass and the SceneView that holds them
 * (kernels/scene/scene_view.cl), DeviceScene's array members (host/scene/device_scene.hpp),
 * the Renderer's buffers, its bind loop and the AOV pass's (host/render/renderer.cpp,
 * host/render/aov.cpp), the device memory check and the film's scene identity
 * (host/render/film_identity.cpp). Adding an array is one line here plus its producer in
 * host/scene/device_scene.cpp.
 *
 * X(device_type, host_type, name, what, kind): the kernels read `__global const
 * device_type* name`; the host holds `std::span<const host_type> name` with the same bytes
 * (the environment map's float4 texels are 4 floats each on the host); `what` names the
 * array in messages. `kind` says how the film's identity covers it: FC_ARRAY_CONTENT by its
 * bytes; FC_ARRAY_TREE (acceleration structures and what indexes into them, whose layout
 * depends on the node width each device chooses) by what the trees are built from
 * (DeviceScene::tree_inputs), so that devices with different trees still share films. Every array is bound in every
 * program, a one-element placeholder when empty, so that a feature left out of a program (feature_flags.h) changes no
 * argument. */
#ifndef FACET_SHARED_SCENE_ARRAYS_H
#define FACET_SHARED_SCENE_ARRAYS_H

#include "kernels/shared/all.h"
#include "kernels/shared/material_layout.h"

#define FC_ARRAY_CONTENT 0
#define FC_ARRAY_TREE 1

// clang-format off
#define FC_SCENE_ARRAYS(X)                                                                                         \
    X(FcBvhNode, FcBvhNode, nodes, "BVH nodes", FC_ARRAY_TREE)                                                     \
    X(FcTriangle, FcTriangle, tris, "triangles", FC_ARRAY_TREE)                                                    \
    X(FcTriShading, FcTriShading, shading, "shading data", FC_ARRAY_CONTENT)                                       \
    X(float4, float, face_normals, "face normals", FC_ARRAY_CONTENT)                                               \
    X(FcMaterial, FcMaterial, materials, "materials", FC_ARRAY_CONTENT)                                            \
    X(FcLight, FcLight, lights, "lights", FC_ARRAY_CONTENT)                                                        \
    X(float, float, light_cdf, "light distribution", FC_ARRAY_CONTENT)                                             \
    X(float4, float, env_texels, "environment map", FC_ARRAY_CONTENT)                                              \
    X(float, float, env_dist, "environment distribution", FC_ARRAY_CONTENT)                                        \
    X(FcTexture, FcTexture, textures, "texture table", FC_ARRAY_CONTENT)                                           \
    X(fc_uint, fc_uint, texels, "textures (texels)", FC_ARRAY_CONTENT)                                             \
    X(FcMaterialTextures, FcMaterialTextures, material_textures, "material texture bindings", FC_ARRAY_CONTENT)    \
    X(FcTriTexcoords, FcTriTexcoords, texcoords, "texture uvs", FC_ARRAY_CONTENT)                                  \
    X(FcSphere, FcSphere, spheres, "spheres", FC_ARRAY_CONTENT)                                                    \
    X(FcBvhNode, FcBvhNode, sphere_nodes, "sphere BVH", FC_ARRAY_TREE)                                             \
    X(FcInstance, FcInstance, instances, "instances", FC_ARRAY_TREE)                                               \
    X(FcBvhNode, FcBvhNode, instance_nodes, "instance BVH", FC_ARRAY_TREE)                                         \
    X(float4, float, casters, "glass bounds", FC_ARRAY_CONTENT)
// clang-format on

#endif
