// The scene compiled into what the kernels read (as Cycles' scene/devicescene.h): the
// render parameters and one array per entry of kernels/shared/scene_arrays.h, in the
// layouts of kernels/shared/*_layout.h. host/render/ uploads it as it is, once per render
// for every device and the AOV pass; this is the one place where host-side scene data
// becomes device structs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/bvh/instance_bvh.hpp"
#include "host/scene/scene.hpp"
#include "host/bvh/sphere_bvh.hpp"
#include "kernels/shared/scene_arrays.h"
#include "host/bvh/sphere_bvh.hpp"
#include "kernels/shared/material_layout.h"
#include "kernels/shared/render_layout.h"

namespace facet {

struct DeviceScene {
    DeviceScene() = default;
    // The arrays view storage of this object: moved, never copied.
    DeviceScene(DeviceScene&&) = default;
    DeviceScene& operator=(DeviceScene&&) = default;
    DeviceScene(const DeviceScene&) = delete;
    DeviceScene& operator=(const DeviceScene&) = delete;

    // Camera, image size, depth, seed, strategy, light count and environment; the
    // per-launch fields (sample_begin/count, row_begin/count) are left 0.
    FcRenderParams params{};

    // One view per array of kernels/shared/scene_arrays.h, in its order: into the Scene
    // and the Bvh that compile() was given (valid while those live), or into the storage
    // below.
#define FC_DEVICE_SCENE_MEMBER(device_type, host_type, name, what, kind) std::span<const host_type> name;
    FC_SCENE_ARRAYS(FC_DEVICE_SCENE_MEMBER)
#undef FC_DEVICE_SCENE_MEMBER

    // One array of the list as bytes: its name in the kernels, what it holds (for
    // messages) and its contents.
    struct Array {
        const char* name;
        const char* what;
        std::span<const std::byte> bytes;
        std::size_t element;  // the bytes of one element on the host
        int kind;             // FC_ARRAY_CONTENT or FC_ARRAY_TREE
    };
    // Every array of the list, in list order (the order the kernels take them).
    std::vector<Array> arrays() const;
    // Their bytes, together.
    std::size_t bytes() const;

    // What the FC_ARRAY_TREE arrays are built from, whatever the node width: the world's
    // vertices, each shared mesh's, and the instances' placements (mesh, object to world).
    std::vector<std::span<const std::byte>> tree_inputs;
    std::vector<std::uint32_t> placements_owned;

    // Storage of the arrays the host does not already hold in the device's layout.
    // The environment distribution when it is not the scene's own (MIS compensation
    // builds its own).
    std::vector<float> environment_distribution_owned;
    std::vector<FcMaterial> materials_owned;
    // The world triangles' unit geometric normals, 4 floats each (x, y, z, 0), in the order
    // of `shading`: along cross(v1 - v0, v2 - v0) in double, +z where it has no area
    // (triangle_normal). The kernels read them for world triangles (surface_at), where
    // normalising the cross product of each hit took a twentieth of the Cornell box's time;
    // an instance's triangles keep theirs computed from its placed vertices.
    std::vector<float> face_normals_owned;
    std::vector<float> casters_owned;  // caustic_casters (host/scene/caustic_casters.hpp)
    DeviceTextures texture_data;       // texture pool, material bindings and uvs (host/scene/texture.hpp)
    SphereBvh sphere_tree;             // the analytic spheres and their tree (a root only when there are none)
    // Instancing (host/bvh/instance_bvh.hpp): the instances and their top-level tree (a root
    // with two empty children when there are none). With instances, nodes, tris and
    // shading view the owned arrays below: the world's, then each shared mesh's once.
    InstanceBvh instancing;
    std::vector<FcBvhNode> nodes_owned;
    std::vector<FcTriangle> triangles_owned;
    std::vector<FcTriShading> shading_owned;
};

// The number of arrays in kernels/shared/scene_arrays.h.
#define FC_COUNT_SCENE_ARRAY(device_type, host_type, name, what, kind) +1
inline constexpr std::size_t kSceneArrayCount = 0 FC_SCENE_ARRAYS(FC_COUNT_SCENE_ARRAY);
#undef FC_COUNT_SCENE_ARRAY

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
