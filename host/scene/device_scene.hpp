// The scene compiled into what the kernels read (as Cycles' scene/devicescene.h): the
// render parameters and one array per kernel buffer, in the layouts of
// kernels/shared/*_layout.h. host/render/renderer.cpp uploads it as it is; this is the
// one place where host-side scene data (materials, textures, spheres, instances) becomes
// device structs.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/bvh/instance_bvh.hpp"
#include "host/scene/scene.hpp"
#include "host/bvh/sphere_bvh.hpp"
#include "kernels/shared/material_layout.h"
#include "kernels/shared/render_layout.h"

namespace facet {

struct DeviceScene {
    // Camera, image size, depth, seed, strategy, light count and environment; the
    // per-launch fields (sample_begin/count, row_begin/count) are left 0.
    FcRenderParams params{};
    // Arrays the host already holds in the device's layout: views into the Scene and
    // the Bvh that compile() was given, valid while those live.
    std::span<const FcBvhNode> nodes;
    std::span<const FcTriangle> triangles;
    std::span<const FcTriShading> shading;
    std::span<const FcLight> lights;
    std::span<const float> light_cdf;
    std::span<const float> environment_texels;
    std::span<const float> environment_distribution;
    // The distribution when it is not the scene's own (MIS compensation builds its own):
    // environment_distribution points into it, so it lives as long as this DeviceScene.
    std::vector<float> environment_distribution_owned;
    // Arrays converted from the host's types.
    std::vector<FcMaterial> materials;
    // Texture pool, material bindings and uvs (host/scene/texture.hpp).
    DeviceTextures textures;
    SphereBvh spheres;  // the analytic spheres and their tree (a root only when there are none)
    // Instancing (host/bvh/instance_bvh.hpp): the instances and their top-level tree (a root
    // with two empty children when there are none). With instances, nodes, triangles and
    // shading view the owned arrays below: the world's, then each shared mesh's once.
    InstanceBvh instancing;
    std::vector<FcBvhNode> nodes_owned;
    std::vector<FcTriangle> triangles_owned;
    std::vector<FcTriShading> shading_owned;
};

// The kernels' struct of a host material, and back (for tests and tools that hold
// device structs: host_material(device_material(m)) == m).
FcMaterial device_material(const Material& m);
Material host_material(const FcMaterial& d);
// describe_material (material.hpp) of a device struct.
std::string describe_material(const FcMaterial& d);

// The scene and its BVH as the kernels read them. scene.settings gives the image size
// (width and height >= 1), depth and seed; build_lights() must have run.
DeviceScene compile(const Scene& scene, const Bvh& bvh);

}  // namespace facet
