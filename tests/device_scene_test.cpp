// DeviceScene.*: the host scene compiled into the kernels' arrays (host/scene/device_scene.hpp).
#include <cstring>

#include <gtest/gtest.h>

#include "host/bvh/bvh.hpp"
#include "host/scene/device_scene.hpp"
#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet {
namespace {

void expect_same(const Material& a, const Material& b, std::string_view what) {
    EXPECT_EQ(a.diffuse_model, b.diffuse_model) << what;
    EXPECT_EQ(a.specular_model, b.specular_model) << what;
    EXPECT_EQ(a.ndf, b.ndf) << what;
    EXPECT_EQ(a.geometry, b.geometry) << what;
    EXPECT_EQ(a.fresnel, b.fresnel) << what;
    EXPECT_EQ(a.sampling, b.sampling) << what;
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(a.diffuse[c], b.diffuse[c]) << what;
        EXPECT_EQ(a.f0[c], b.f0[c]) << what;
        EXPECT_EQ(a.ks[c], b.ks[c]) << what;
        EXPECT_EQ(a.transmittance[c], b.transmittance[c]) << what;
        EXPECT_EQ(a.emission[c], b.emission[c]) << what;
        EXPECT_EQ(a.eta[c], b.eta[c]) << what;
        EXPECT_EQ(a.k[c], b.k[c]) << what;
    }
    EXPECT_EQ(a.alpha_x, b.alpha_x) << what;
    EXPECT_EQ(a.alpha_y, b.alpha_y) << what;
    EXPECT_EQ(a.exponent_x, b.exponent_x) << what;
    EXPECT_EQ(a.exponent_y, b.exponent_y) << what;
    EXPECT_EQ(a.ior, b.ior) << what;
    EXPECT_EQ(a.sigma, b.sigma) << what;
    EXPECT_EQ(a.two_sided_emission, b.two_sided_emission) << what;
    EXPECT_EQ(a.energy_compensation, b.energy_compensation) << what;
    EXPECT_EQ(a.anisotropy, b.anisotropy) << what;
    EXPECT_NEAR(a.anisotropy_rotation, b.anisotropy_rotation, 1e-6f) << what;
}

TEST(DeviceScene, MaterialsRoundTrip) {
    for (std::string_view name : material_model_names()) {
        Material m = make_material(std::string(name));
        m.emission = glm::vec3(1.0f, 2.0f, 3.0f);
        m.two_sided_emission = true;
        m.sigma = m.eon_roughness = 0.7f;  // one kernel field for both (EON's or Oren-Nayar's)
        m.alpha_y = 0.2f;
        m.anisotropy = 0.5f;  // KHR_materials_anisotropy: strength, and the rotation as (cos, sin)
        m.anisotropy_rotation = 0.75f;
        const FcMaterial d = device_material(m);
        EXPECT_EQ(d.flags, FC_MAT_TWO_SIDED_EMISSION | FC_MAT_ANISOTROPIC |
                               (m.energy_compensation ? FC_MAT_ENERGY_COMPENSATION : 0u))
            << name;
        EXPECT_EQ(d.emission[2], 3.0f) << name;
        EXPECT_EQ(d.alpha_y, 0.2f) << name;
        expect_same(host_material(d), m, name);
        EXPECT_EQ(describe_material(d), describe_material(m)) << name;
    }
}

TEST(DeviceScene, SpecularColourByLobe) {
    Material m = make_material("ggx");
    m.f0 = glm::vec3(0.1f), m.ks = glm::vec3(0.2f), m.transmittance = glm::vec3(0.3f);
    EXPECT_EQ(device_material(m).specular[0], 0.1f);
    m.specular_model = FC_SPECULAR_BLINN_PHONG_NORMALIZED;
    EXPECT_EQ(device_material(m).specular[0], 0.2f);
    m.specular_model = FC_SPECULAR_DIELECTRIC;
    EXPECT_EQ(device_material(m).specular[0], 0.3f);
    m.specular_model = FC_SPECULAR_NONE;  // the (1 - F0) diffuse lobes read F0
    EXPECT_EQ(device_material(m).specular[0], 0.1f);
    EXPECT_EQ(device_material(m).sigma, m.sigma);
}

TEST(DeviceScene, CompileViewsTheSceneAndConvertsMaterials) {
    Scene s;
    Material lamp = default_material();
    lamp.emission = glm::vec3(2.0f);
    add_material(s, default_material(), "white");
    add_material(s, lamp, "lamp");
    add_sphere(s, glm::vec3(0.0f), 1.0f, 1, 0, false);
    add_quad(s, glm::vec3(-1, 3, -1), glm::vec3(0, 0, 2), glm::vec3(2, 0, 0), 1);
    s.settings.width = 32;
    s.settings.height = 16;
    s.settings.seed = 7;
    build_lights(s);
    const Bvh bvh = build_bvh(s.vertices);
    const DeviceScene d = compile(s, bvh);
    EXPECT_EQ(d.params.width, 32u);
    EXPECT_EQ(d.params.height, 16u);
    EXPECT_EQ(d.params.seed, 7u);
    EXPECT_EQ(d.params.light_count, 2u);
    EXPECT_EQ(d.params.sample_count, 0u);
    EXPECT_EQ(d.nodes.data(), bvh.nodes.data());
    EXPECT_EQ(d.tris.size(), bvh.triangles.size());
    EXPECT_EQ(d.shading.data(), s.shading.data());
    EXPECT_EQ(d.lights.size(), s.lights.size());
    EXPECT_EQ(d.light_cdf.size(), s.light_cdf.size());
    EXPECT_EQ(d.env_texels.size(), s.environment.texels.size());
    EXPECT_EQ(d.env_dist.size(), s.environment.distribution.size());
    ASSERT_EQ(d.materials.size(), 2u);
    EXPECT_EQ(d.materials[1].emission[0], 2.0f);
    EXPECT_EQ(d.materials[0].diffuse[1], 0.8f);
    const FcMaterial expected = device_material(lamp);
    EXPECT_EQ(std::memcmp(&d.materials[1], &expected, sizeof expected), 0);
}

// A dielectric chooses reflection by its Fresnel factor alone under uniform light (a constant
// environment and no other light: the white furnace, where that choice is exact), widened
// anywhere else (FC_MAT_WIDE_CHOICE); the glass balls and floor of a sunlit scene become
// casters of the caustic guide (two float4 each, the ball's index as a lens).
TEST(DeviceScene, GlassChoiceAndCastersFollowTheLight) {
    auto scene = [](bool lamp) {
        Scene s;
        Material glass = make_material("dielectric");
        add_material(s, default_material(), "floor");
        add_material(s, glass, "glass");
        add_analytic_sphere(s, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 1, false);
        add_quad(s, glm::vec3(-5, 0, -5), glm::vec3(0, 0, 10), glm::vec3(10, 0, 0), 0);
        s.environment = constant_environment(glm::vec3(1.0f));
        if (lamp) s.punctual_lights.push_back(PunctualLight{});
        s.settings.width = s.settings.height = 8;
        build_lights(s);
        return s;
    };
    const Scene white = scene(false), lit = scene(true);
    const Bvh bw = build_bvh(white.vertices), bl = build_bvh(lit.vertices);
    const DeviceScene dw = compile(white, bw), dl = compile(lit, bl);
    EXPECT_EQ(dw.materials[1].flags & FC_MAT_WIDE_CHOICE, 0u);
    EXPECT_EQ(dl.materials[1].flags & FC_MAT_WIDE_CHOICE, FC_MAT_WIDE_CHOICE);
    EXPECT_EQ(dl.materials[0].flags & FC_MAT_WIDE_CHOICE, 0u);  // not a dielectric
    ASSERT_EQ(dl.params.caster_count, 1u);
    EXPECT_EQ(dl.casters.size(), 8u);
    EXPECT_EQ(dl.casters[3], 1.0f);
    EXPECT_EQ(dl.casters[4], 1.5f);
    EXPECT_EQ(dl.params.caster_fraction, 0.25f);
}

// The world triangles' unit geometric normals (face_normals, read by surface_at), from the
// vertices in double: right where a float cross product of the edges underflows (edges of
// 1e-25) or overflows (1e20), where the kernel's own normalisation fell back to +z; +z for a
// triangle without area.
TEST(DeviceScene, FaceNormalsOfEveryWorldTriangle) {
    Scene s;
    add_material(s, default_material(), "white");
    const glm::vec3 o(0.0f);
    const glm::vec3 tris[][3] = {{o, {1, 0, 0}, {0, 1, 0}},
                                 {o, {0, 0, 1e-25f}, {0, 1e-25f, 0}},
                                 {o, {1e20f, 0, 0}, {0, 0, 1e20f}},
                                 {{3, 3, 3}, {3, 3, 3}, {3, 3, 3}},
                                 {o, {0, 2, 0}, {0, 1, 2}}};
    for (const auto& t : tris) {
        s.vertices.insert(s.vertices.end(), {t[0], t[1], t[2]});
        s.shading.push_back(FcTriShading{});
    }
    const DeviceScene d = compile(s, build_bvh(s.vertices));
    const glm::vec4 expected[] = {{0, 0, 1, 0}, {-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}};
    ASSERT_EQ(d.face_normals.size(), 4 * std::size(tris));
    for (std::size_t t = 0; t < std::size(tris); ++t)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(d.face_normals[4 * t + std::size_t(c)], expected[t][c]) << t << " " << c;
}

}  // namespace
}  // namespace facet
