/* Everything a kernel needs to read the scene: the constant parameters and one
 * buffer per scene array (bound in host/render/renderer.cpp). */
#ifndef FACET_SCENE_SCENE_VIEW_CL
#define FACET_SCENE_SCENE_VIEW_CL

#include "kernels/shared/all.h"

typedef struct {
    __constant const FcRenderParams* params;
    __global const FcBvhNode* nodes;
    __global const FcTriangle* tris;
    __global const FcTriShading* shading;
    __global const FcMaterial* materials;
    __global const FcLight* lights;
    __global const float* light_cdf;
    __global const float4* env_texels;
    __global const float* env_dist;
    /* Textures (kernels/shared/texture_layout.h); one-element placeholders without them. */
    __global const FcTexture* textures;
    __global const uint* texels;
    __global const FcMaterialTextures* material_textures;
    __global const FcTriTexcoords* texcoords;
    __global const FcSphere* spheres;
    __global const FcBinaryNode* sphere_nodes;
    /* Instances and their top-level tree (kernels/shared/instance_layout.h). */
    __global const FcInstance* instances;
    __global const FcBinaryNode* instance_nodes;
} SceneView;

#endif
