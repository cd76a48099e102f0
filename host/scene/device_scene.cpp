#include "host/scene/device_scene.hpp"

#include "host/scene/texture_tangents.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

#include "host/scene/caustic_casters.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/util/vec3.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

FcRenderParams render_params(const Scene& scene) {
    const RenderSettings& s = scene.settings;
    FcRenderParams p{};
    p.camera = make_camera(scene.camera, float(s.width) / float(s.height));
    p.width = std::uint32_t(s.width);
    p.height = std::uint32_t(s.height);
    p.seed = s.seed;
    p.max_depth = std::uint32_t(s.max_depth);
    p.rr_depth = std::uint32_t(s.rr_depth);
    p.light_count = std::uint32_t(scene.lights.size());
    p.environment = scene.environment.params;
    p.environment_light = scene.environment_light;
    p.strategy = std::uint32_t(s.strategy);
    p.sampler = std::uint32_t(s.sampler);
    p.filter = std::uint32_t(s.filter);
    p.filter_radius = pixel_filter_radius(s.filter, s.filter_radius);
    p.clamp = s.clamp > 0.0f ? s.clamp : FC_MAX_RADIANCE;
    p.roulette_gain = s.roulette_gain;
    return p;
}

// Whether light is equal in every direction: a constant environment lights the scene and nothing
// else does (the white furnace). There a dielectric's choice by its Fresnel factor is exact;
// elsewhere its choice is widened (FC_MAT_WIDE_CHOICE, kernels/bsdf/dielectric.cl).
bool uniform_light(const Scene& scene) {
    for (const FcLight& l : scene.lights)
        if (l.type != FC_LIGHT_ENVIRONMENT || scene.environment.params.width != 0) return false;
    return true;
}

// The shared meshes' BLASes, their shading after the world's, and the instances.
void compile_instances(const Scene& scene, const Bvh& bvh, DeviceScene& d) {
    std::vector<InstancedMesh> meshes;
    std::vector<InstancePlacement> placements;
    std::size_t prim = scene.shading.size();
    for (const SharedMesh& m : scene.meshes) {
        meshes.push_back(InstancedMesh{m.vertices, std::int32_t(prim)});
        prim += m.triangle_count();
    }
    for (const Instance& in : scene.instances) placements.push_back(InstancePlacement{in.mesh, in.object_to_world});
    d.instancing = build_instance_bvh(bvh, meshes, placements);
    if (scene.instances.empty()) return;  // the world's arrays as they are
    d.nodes_owned.reserve(bvh.nodes.size() + d.instancing.nodes.size());
    d.nodes_owned = bvh.nodes;
    d.nodes_owned.insert(d.nodes_owned.end(), d.instancing.nodes.begin(), d.instancing.nodes.end());
    d.triangles_owned.reserve(bvh.triangles.size() + d.instancing.triangles.size());
    d.triangles_owned = bvh.triangles;
    d.triangles_owned.insert(d.triangles_owned.end(), d.instancing.triangles.begin(), d.instancing.triangles.end());
    d.shading_owned.reserve(prim);
    d.shading_owned = scene.shading;
    for (const SharedMesh& m : scene.meshes)
        d.shading_owned.insert(d.shading_owned.end(), m.shading.begin(), m.shading.end());
    d.nodes = d.nodes_owned;
    d.tris = d.triangles_owned;
    d.shading = d.shading_owned;
    // uvs (when the scene has textures or anisotropy): the world's padded to its triangles,
    // then each mesh's
    if (scene_uses_texcoords(scene)) {
        for (const SharedMesh& m : scene.meshes) {
            const std::size_t at = d.texture_data.texcoords.size();
            // The mesh's vertex tangents in object space, as for world triangles; the kernels
            // place them with the instance (instance_tangent_to_world).
            Scene object;
            object.vertices = m.vertices;
            object.shading = m.shading;
            object.texcoords = m.texcoords;
            object.materials = scene.materials;
            std::vector<FcTriTexcoords> texcoords = m.texcoords;
            texcoords.resize(m.triangle_count(), FcTriTexcoords{});
            compute_tangents(object, texcoords);
            d.texture_data.texcoords.insert(d.texture_data.texcoords.end(), texcoords.begin(), texcoords.end());
            d.texture_data.texcoords.resize(at + m.triangle_count(), FcTriTexcoords{});
        }
    }
}

}  // namespace

FcMaterial device_material(const Material& m) {
    FcMaterial d{};
    store(d.diffuse, m.diffuse);
    store(d.specular, specular_colour(m));
    store(d.emission, m.emission);
    store(d.eta, m.eta);
    store(d.k, m.k);
    d.diffuse_model = m.diffuse_model;
    d.specular_model = m.specular_model;
    d.ndf = m.ndf;
    d.geometry = m.geometry;
    d.fresnel = m.fresnel;
    d.sampling = m.sampling;
    d.metallic = m.metallic;
    store(d.attenuation, m.attenuation);
    d.clearcoat = m.clearcoat;
    d.clearcoat_alpha = m.clearcoat_alpha;
    store(d.sheen, m.sheen);
    d.sheen_roughness = m.sheen_roughness;
    d.anisotropy = m.anisotropy;
    d.anisotropy_direction[0] = std::cos(m.anisotropy_rotation);
    d.anisotropy_direction[1] = std::sin(m.anisotropy_rotation);
    d.alpha_x = m.alpha_x;
    d.alpha_y = m.alpha_y;
    d.exponent_x = m.exponent_x;
    d.exponent_y = m.exponent_y;
    d.ior = m.ior;
    d.sigma = m.diffuse_model == FC_DIFFUSE_EON ? m.eon_roughness : m.sigma;  // one field, by diffuse model
    d.flags = (m.two_sided_emission ? FC_MAT_TWO_SIDED_EMISSION : 0u) |
              (m.energy_compensation ? FC_MAT_ENERGY_COMPENSATION : 0u) |
              (material_is_anisotropic(m) ? FC_MAT_ANISOTROPIC : 0u);
    d.specular_f90 = m.specular_f90;
    if (m.specular_f90 != 1.0f) d.flags |= FC_MAT_SPECULAR_F90;
    d.alpha = m.alpha;
    d.alpha_cutoff = m.alpha_cutoff;
    d.alpha_texture = -1;
    if (m.alpha_mode != FC_ALPHA_OPAQUE) {
        d.flags |= m.alpha_mode == FC_ALPHA_MASK ? FC_MAT_ALPHA_MASK : FC_MAT_ALPHA_BLEND;
        d.alpha_texture = m.textures.alpha;
        if (m.textures.alpha >= 0 && m.textures.alpha_channel == 0) d.flags |= FC_MAT_ALPHA_RED;
    }
    return d;
}

Material host_material(const FcMaterial& d) {
    Material m;
    m.diffuse = load(d.diffuse);
    m.f0 = m.ks = m.transmittance = load(d.specular);
    m.emission = load(d.emission);
    m.eta = load(d.eta);
    m.k = load(d.k);
    m.diffuse_model = d.diffuse_model;
    m.specular_model = d.specular_model;
    m.ndf = d.ndf;
    m.geometry = d.geometry;
    m.fresnel = d.fresnel;
    m.sampling = d.sampling;
    m.metallic = d.metallic;
    m.attenuation = load(d.attenuation);
    m.clearcoat = d.clearcoat;
    m.clearcoat_alpha = d.clearcoat_alpha;
    m.sheen = load(d.sheen);
    m.sheen_roughness = d.sheen_roughness;
    m.anisotropy = d.anisotropy;
    m.anisotropy_rotation = std::atan2(d.anisotropy_direction[1], d.anisotropy_direction[0]);
    m.alpha_x = d.alpha_x;
    m.alpha_y = d.alpha_y;
    m.exponent_x = d.exponent_x;
    m.exponent_y = d.exponent_y;
    m.ior = d.ior;
    m.sigma = m.eon_roughness = d.sigma;
    m.two_sided_emission = (d.flags & FC_MAT_TWO_SIDED_EMISSION) != 0;
    m.energy_compensation = (d.flags & FC_MAT_ENERGY_COMPENSATION) != 0;
    m.specular_f90 = (d.flags & FC_MAT_SPECULAR_F90) ? d.specular_f90 : 1.0f;
    m.alpha_mode = (d.flags & FC_MAT_ALPHA_MASK)    ? FC_ALPHA_MASK
                   : (d.flags & FC_MAT_ALPHA_BLEND) ? FC_ALPHA_BLEND
                                                    : FC_ALPHA_OPAQUE;
    m.alpha = d.alpha;
    m.alpha_cutoff = d.alpha_cutoff;
    m.textures.alpha = d.alpha_texture;
    m.textures.alpha_channel = (d.flags & FC_MAT_ALPHA_RED) ? 0 : 3;
    return m;
}

std::string describe_material(const FcMaterial& d) { return describe_material(host_material(d)); }

std::vector<DeviceScene::Array> DeviceScene::arrays() const {
#define FC_DEVICE_SCENE_ARRAY(device_type, host_type, name, what, kind) \
    Array{#name, what, std::as_bytes(name), sizeof(host_type), kind},
    return {FC_SCENE_ARRAYS(FC_DEVICE_SCENE_ARRAY)};
#undef FC_DEVICE_SCENE_ARRAY
}

std::size_t DeviceScene::bytes() const {
    std::size_t total = 0;
    for (const Array& a : arrays()) total += a.bytes.size();
    return total;
}

DeviceScene compile(const Scene& scene, const Bvh& bvh) {
    DeviceScene d;
    d.params = render_params(scene);
    d.nodes = bvh.nodes;
    d.tris = bvh.triangles;
    d.shading = scene.shading;
    d.lights = scene.lights;
    d.light_cdf = scene.light_cdf;
    d.env_texels = scene.environment.texels;
    if (scene.environment.sampling == EnvironmentSampling::plain) {
        d.env_dist = scene.environment.distribution;
    } else {
        d.environment_distribution_owned =
            environment_sampling_distribution(scene.environment, scene.settings.strategy);
        d.env_dist = d.environment_distribution_owned;
    }
    d.face_normals_owned.reserve(4 * scene.shading.size());
    for (std::size_t t = 0; t < scene.shading.size(); ++t) {
        const glm::vec3 n =
            triangle_normal(scene.vertices[3 * t], scene.vertices[3 * t + 1], scene.vertices[3 * t + 2]);
        d.face_normals_owned.insert(d.face_normals_owned.end(), {n.x, n.y, n.z, 0.0f});
    }
    d.face_normals = d.face_normals_owned;
    d.materials_owned.reserve(scene.materials.size());
    const bool wide_choice = !uniform_light(scene);
    for (const Material& m : scene.materials) {
        d.materials_owned.push_back(device_material(m));
        if (wide_choice && m.specular_model == FC_SPECULAR_DIELECTRIC)
            d.materials_owned.back().flags |= FC_MAT_WIDE_CHOICE;
    }
    d.materials = d.materials_owned;
    d.texture_data = compile_textures(scene);
    d.sphere_tree = build_sphere_bvh(scene.spheres, bvh.stats.width);
    d.spheres = d.sphere_tree.spheres;
    d.sphere_nodes = d.sphere_tree.nodes;
    compile_instances(scene, bvh, d);
    d.instances = d.instancing.instances;
    d.tree_inputs.push_back(std::as_bytes(std::span<const glm::vec3>(scene.vertices)));
    for (const SharedMesh& m : scene.meshes)
        d.tree_inputs.push_back(std::as_bytes(std::span<const glm::vec3>(m.vertices)));
    for (const Instance& in : scene.instances) {
        d.placements_owned.push_back(std::uint32_t(in.mesh));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                d.placements_owned.push_back(std::bit_cast<std::uint32_t>(in.object_to_world[c][r]));
    }
    d.tree_inputs.push_back(std::as_bytes(std::span<const std::uint32_t>(d.placements_owned)));
    d.instance_nodes = d.instancing.tree;
    d.textures = d.texture_data.table;
    d.texels = d.texture_data.texels;
    d.material_textures = d.texture_data.materials;
    d.texcoords = d.texture_data.texcoords;
    d.casters_owned = caustic_casters(scene);
    d.casters = d.casters_owned;
    d.params.caster_count = std::uint32_t(d.casters_owned.size() / 8);
    d.params.caster_fraction = d.params.caster_count > 0 ? scene.settings.caustic_guide : 0.0f;
    return d;
}

}  // namespace facet
