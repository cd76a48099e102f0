// The scene as the host holds it: a triangle soup with per-triangle shading data,
// meshes shared by several instances, materials, lights, a camera and render settings. Loaded from a JSON scene file
// or directly from an OBJ (host/readers/load_scene.hpp); compiled into the device's
// arrays by host/scene/device_scene.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "host/scene/environment_map.hpp"
#include "host/scene/material.hpp"
#include "host/scene/texture.hpp"
#include "kernels/shared/scene_layout.h"
#include "kernels/shared/sphere_layout.h"
#include "kernels/shared/render_layout.h"

namespace facet {

struct CameraDesc {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    int projection = FC_PROJECTION_PERSPECTIVE;
    float fov_y_degrees = 40.0f;  // perspective: vertical field of view
    float ortho_height = 2.0f;    // orthographic: world-space height of the image
    float aperture = 0.0f;        // perspective: radius of the thin lens (world units); 0: a pinhole
    float focus_distance = 0.0f;  // of the plane in focus, along the view direction; 0: |target - eye|
};

struct RenderSettings {
    int width = 512;
    int height = 512;
    int spp = 64;
    int max_depth = 16;  // path vertices after the camera; 1 = direct light only
    int rr_depth = 3;    // Russian roulette starts after this many bounces
    std::uint32_t seed = 0;
    int strategy = FC_STRATEGY_MIS;  // FC_STRATEGY_*: MIS, light sampling or BSDF sampling only
    int sampler = FC_SAMPLER_SOBOL;  // FC_SAMPLER_*: scrambled Sobol' or independent numbers
    int filter = FC_FILTER_BOX;      // FC_FILTER_*: the pixel filter (scene/pixel_filter.hpp)
    float filter_radius = 0.0f;      // pixels; 0: the filter's default
    float clamp = 0.0f;              // the largest contribution of one sample; 0: no clamp (unbiased)
    // The share of a Lambertian vertex's directions drawn toward the glass objects' bounds
    // (kernels/integrator/caustic_guide.cl); 0: the BSDF alone. Unbiased at any value.
    float caustic_guide = 0.25f;
    // Russian roulette's survival per unit of throughput: a path survives with probability
    // min(roulette_gain * max(throughput) * eta-scale, 0.95) (kernels/integrator/path_lanes.cl).
    // 1 is pbrt-v4's and Mitsuba 3's rule; 2 measured better at equal time (docs/sampling.md).
    // Unbiased at any value > 0.
    float roulette_gain = 2.0f;
};

// A point, spot or directional light as the scene file gives it (docs/lights.md).
struct PunctualLight {
    int type = FC_LIGHT_POINT;  // FC_LIGHT_POINT, FC_LIGHT_SPOT or FC_LIGHT_DIRECTIONAL
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot axis, or the direction light travels
    glm::vec3 color{1.0f};                   // Hoffman's c_light (at distance 1)
    float inner_degrees = 30.0f;             // spot: full intensity inside this half-angle
    float outer_degrees = 45.0f;             // spot: no light outside this half-angle
};

// A mesh stored once, in object space, and placed in the world by instances (a glTF mesh
// that several nodes use, docs/scene-format.md): its triangles go to the device once, with a
// tree of their own (host/bvh/instance_bvh.hpp). Never emissive: the light list samples
// world-space triangles, so emitting meshes are copied into the world instead.
struct SharedMesh {
    std::string name;
    std::vector<glm::vec3> vertices;        // 3 per triangle, object space
    std::vector<FcTriShading> shading;      // 1 per triangle: object-space normals; light -1
    std::vector<FcTriTexcoords> texcoords;  // empty, or up to some triangle (padded with zeros)

    std::size_t triangle_count() const { return shading.size(); }
};

// One use of a shared mesh: its object-to-world transform, affine (last row 0 0 0 1) and
// invertible (instance_transform_ok).
struct Instance {
    int mesh = 0;  // index into Scene::meshes
    glm::mat4 object_to_world{1.0f};
};

struct Scene {
    std::vector<glm::vec3> vertices;    // 3 per triangle
    std::vector<FcTriShading> shading;  // 1 per triangle
    std::vector<FcSphere> spheres;      // analytic spheres (host/bvh/sphere_bvh.hpp)
    std::vector<Material> materials;
    std::vector<std::string> material_names;  // parallel to materials
    std::vector<PunctualLight> punctual_lights;
    EnvironmentMap environment = no_environment();
    std::vector<FcLight> lights;   // built by build_lights()
    std::vector<float> light_cdf;  // light_count + 1 entries, cdf[0] = 0, cdf[n] = 1
    int environment_light = -1;    // index of the environment in `lights`, or -1
    CameraDesc camera;
    RenderSettings settings;
    std::string source_path;            // the file it was loaded from
    std::vector<std::string> warnings;  // non-fatal problems met while loading
    std::string lighting_note;          // the light added or chosen (host/readers/default_lighting.hpp)
    std::string camera_note;            // how a camera was placed for a file without one (frame_camera)
    // One line per mesh file: how its shading normals were obtained (`facet info` prints them).
    std::vector<std::string> normal_sources;
    // Image textures (host/scene/texture.hpp) and per-triangle uvs: empty, or filled
    // up to some triangle (compile_textures pads them with zeros).
    std::vector<TextureImage> textures;
    std::vector<FcTriTexcoords> texcoords;
    std::vector<SharedMesh> meshes;   // instanced meshes, each stored once
    std::vector<Instance> instances;  // their uses
    // --strict: a missing or unreadable asset (texture, material library) is an error,
    // not a warning (asset_warning).
    bool strict_assets = false;

    // The world-space triangles (not counting instanced meshes).
    std::size_t triangle_count() const { return shading.size(); }
    // The triangles held on the device: the world's plus each shared mesh's once.
    std::size_t stored_triangle_count() const;
    // The triangles the image shows: the world's plus each instance's mesh.
    std::size_t placed_triangle_count() const;
};

// A missing or unreadable asset the scene can be rendered without: a warning, or with
// scene.strict_assets a facet::Error of the same message.
void asset_warning(Scene& scene, const std::string& message);

// A material with Lambertian defaults (diffuse 0.8 grey, no emission).
Material default_material();

// Camera parameters as the kernels see them, for an image of the given aspect ratio.
FcCamera make_camera(const CameraDesc& desc, float aspect);

// Fills scene.lights and scene.light_cdf (host/scene/lights.cpp): one area light per
// emissive triangle with non-zero area, the punctual lights, and the environment;
// each picked in proportion to an estimate of its power.
void build_lights(Scene& scene);

// Shapes made on the host (host/scene/shapes.cpp), appended to `scene` with
// `material` (an index into scene.materials) and flat face normals.
// An icosphere: the icosahedron split `subdivisions` times (20 * 4^subdivisions
// triangles), vertices on the sphere. Faces point outward, or inward (winding and
// normals flipped) when `inward` is set, e.g. for an emitting furnace enclosure.
void add_sphere(Scene& scene, glm::vec3 center, float radius, int subdivisions, int material, bool inward);
// An analytic sphere: intersected exactly on the device (kernels/trace/sphere.cl); faces
// outward, or inward when `inward` is set.
void add_analytic_sphere(Scene& scene, glm::vec3 center, float radius, int material, bool inward);
// A parallelogram corner, corner + e1, corner + e1 + e2, corner + e2 as two
// triangles facing normalize(cross(e1, e2)).
void add_quad(Scene& scene, glm::vec3 corner, glm::vec3 e1, glm::vec3 e2, int material);

// Appends one triangle with per-vertex normals (normalised here) and a material.
void add_triangle(Scene& scene, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 n0, glm::vec3 n1, glm::vec3 n2,
                  int material);

// The axis-aligned box around every vertex, sphere and instance (lo > hi when there are none).
struct Bounds {
    glm::vec3 lo, hi;
    bool empty() const { return !(lo.x <= hi.x); }
    glm::vec3 center() const { return 0.5f * (lo + hi); }
    float radius() const;  // of the bounding sphere about center(): half the diagonal
};
Bounds scene_bounds(const Scene& scene);
// The box around `points` placed by `transform` (its eight corners transformed).
Bounds transformed_bounds(const std::vector<glm::vec3>& points, const glm::mat4& transform);

// Whether `transform` can place an instance: finite, affine (last row 0 0 0 1) and with a
// non-zero determinant (the kernels trace rays in the mesh's space through its inverse).
bool instance_transform_ok(const glm::mat4& transform);
// Appends a shared mesh and returns its index.
int add_shared_mesh(Scene& scene, SharedMesh mesh);
// Places shared mesh `mesh` by `object_to_world`; throws an Error naming the problem
// when the mesh does not exist or the transform is not instance_transform_ok.
void add_instance(Scene& scene, int mesh, const glm::mat4& object_to_world);
// Sets used[m] for every material that a world or shared-mesh triangle uses (`used` has
// one entry per material).
void mark_triangle_materials(const Scene& scene, std::vector<bool>& used);

// A camera that frames the scene's bounding box: looking at its centre from +z and
// slightly above, far enough that the bounding sphere fits a 40 degree vertical fov.
// glTF's front faces +z; a format with no convention (OBJ, PLY, ...) is `broadside`: seen
// from +x instead when the model is longer along z than along x by more than a quarter, so
// that the view takes in its largest extent (a cow modelled along z is seen from the side,
// not from behind; a Cornell box about as deep as wide keeps its open +z side).
enum class Framing { Front, Broadside };
CameraDesc frame_camera(const Scene& scene, Framing framing = Framing::Front);
// The note frame_camera's view gets in Scene::camera_note: "framed to fit the model,
// seen from +x (its longer side)".
std::string framing_note(const Scene& scene, Framing framing);

// Appends a material (with its name) and returns its index.
int add_material(Scene& scene, const Material& material, const std::string& name);

}  // namespace facet
