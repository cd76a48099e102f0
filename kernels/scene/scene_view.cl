/* Everything a kernel needs to read the scene: the constant parameters and one buffer
 * per scene array of kernels/shared/scene_arrays.h, bound by host/render/renderer.cpp
 * and host/render/aov.cpp in list order. A kernel that reads the scene declares
 *     __kernel void k(FC_SCENE_KERNEL_PARAMS, ...)
 * and opens it with
 *     SceneView sc = FC_SCENE_VIEW_INIT;
 * so that its arguments, their order and the view all come from the one list. */
#ifndef FACET_SCENE_SCENE_VIEW_CL
#define FACET_SCENE_SCENE_VIEW_CL

#include "kernels/shared/scene_arrays.h"

#define FC_SCENE_VIEW_MEMBER(device_type, host_type, name, what, kind) __global const device_type* name;
typedef struct {
    __constant const FcRenderParams* params;
    FC_SCENE_ARRAYS(FC_SCENE_VIEW_MEMBER)
} SceneView;
#undef FC_SCENE_VIEW_MEMBER

/* The kernel arguments: the parameter block, then every array in list order. */
#define FC_SCENE_KERNEL_PARAM(device_type, host_type, name, what, kind) , __global const device_type* name
#define FC_SCENE_KERNEL_PARAMS __constant const FcRenderParams* params FC_SCENE_ARRAYS(FC_SCENE_KERNEL_PARAM)

/* The view of those arguments. */
#define FC_SCENE_VIEW_ARG(device_type, host_type, name, what, kind) , name
#define FC_SCENE_VIEW_INIT \
    { params FC_SCENE_ARRAYS(FC_SCENE_VIEW_ARG) }

#endif
