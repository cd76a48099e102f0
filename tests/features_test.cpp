// Kernel specialisation: the program built for a scene holds only the features the
// scene uses (checked on the prelude actually passed to the OpenCL build), and renders
// the same image as the generic program.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "host/bvh/bvh.hpp"
#include "tests/cl_test_env.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"
#include "host/scene/material.hpp"
#include "kernels/shared/feature_flags.h"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

// The prelude of the program passed to the OpenCL build: the lines before the first
// source file (kernels/shared/feature_flags.h's own defaults come after it).
std::string prelude(const Renderer& r) {
    const std::string& text = r.build().source.text;
    return text.substr(0, text.find("#line"));
}

bool built_with(const Renderer& r, const std::string& feature, int value) {
    return prelude(r).find("#define FC_HAS_" + feature + " " + std::to_string(value) + "\n") != std::string::npos;
}

struct Pair {
    Renderer::Halves specialised, generic;
};

// Renders `scene` with the specialised and the generic program, same seed.
Pair render_both(Scene scene, std::uint32_t spp, Renderer** keep_specialised = nullptr) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer s(test::context(), scene, bvh, false), g(test::context(), scene, bvh, true);
    render_fixed(s, spp);
    render_fixed(g, spp);
    EXPECT_TRUE(prelude(g).empty()) << "the generic program has no prelude";
    return {s.halves(), g.halves()};
}

// Bit-identical, or per-pixel means that agree in a z-test at significance 0.01 with
// a Sidak correction over every pixel and channel (variances from the half-images).
void expect_same_distribution(const Pair& p, const std::string& what) {
    const auto& a = p.specialised;
    const auto& b = p.generic;
    bool identical = a.rgb[0] == b.rgb[0] && a.rgb[1] == b.rgb[1];
    if (identical) return;
    const std::size_t n = a.rgb[0].size();
    const double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(n));
    // two-sided threshold: solve erfc(z / sqrt 2) = alpha by bisection
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    std::size_t failures = 0;
    for (std::size_t i = 0; i < n; ++i) {
        auto stats = [&](const Renderer::Halves& h, double& mean, double& var) {
            double na = double(h.samples[0]), nb = double(h.samples[1]), nt = na + nb;
            mean = (na * double(h.rgb[0][i]) + nb * double(h.rgb[1][i])) / nt;
            double d = double(h.rgb[0][i]) - double(h.rgb[1][i]);
            var = d * d * na * nb / (nt * nt);
        };
        double ma, va, mb, vb;
        stats(a, ma, va);
        stats(b, mb, vb);
        double sd = std::sqrt(va + vb);
        if (sd == 0.0 ? std::fabs(ma - mb) > 1e-5 * std::max(1.0, std::fabs(ma)) : std::fabs(ma - mb) / sd > lo)
            ++failures;
    }
    EXPECT_EQ(failures, 0u) << what << ": pixels whose means differ (z threshold " << lo << ")";
}

Scene small(const std::string& file) {
    Scene scene = load_scene(test::scenes_dir() + "/" + file);
    scene.settings.width = 24;
    scene.settings.height = 24;
    scene.settings.max_depth = 6;
    return scene;
}

TEST(Features, LambertCornellBoxLeavesOutEverythingElse) {
    Scene scene = small("cornell_box.json");
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    EXPECT_TRUE(built_with(r, "AREA_LIGHTS", 1));
    for (const char* off : {"ENVIRONMENT", "PUNCTUAL_LIGHTS", "MICROFACET", "BECKMANN", "BLINN_PHONG",
                            "ASHIKHMIN_SHIRLEY", "OREN_NAYAR", "DIELECTRIC", "CLEARCOAT", "SHEEN", "ANISOTROPY"})
        EXPECT_TRUE(built_with(r, off, 0)) << off;
    Renderer g(test::context(), scene, bvh, true);
    EXPECT_TRUE(prelude(g).empty()) << "the generic program has no prelude";
}

TEST(Features, SceneAnalysis) {
    EXPECT_EQ(describe_features(scene_features(small("cornell_box.json"))), "area_lights");
    std::string sky = describe_features(scene_features(small("spheres_sky.json")));
    EXPECT_NE(sky.find("environment"), std::string::npos) << sky;
    EXPECT_EQ(sky.find("area_lights"), std::string::npos) << sky;
    FeatureMask grid = scene_features(small("material_grid.json"));
    for (const char* f : {"oren_nayar", "ashikhmin_shirley", "blinn_phong", "microfacet", "beckmann", "area_lights"})
        EXPECT_NE(describe_features(grid).find(f), std::string::npos) << f;
    EXPECT_EQ(describe_features(grid).find("environment"), std::string::npos);
}

// Every demo scene: the specialised program renders what the generic one does.
TEST(Features, DemoScenesMatchGeneric) {
    for (const char* file :
         {"cornell_box.json", "material_grid.json", "spheres_sky.json", "furnace_sphere.json", "glass_metal_sky.json"})
        expect_same_distribution(render_both(small(file), 16), file);
}

// Every flag of the closed list, on and off, against the generic program.
TEST(Features, EveryFlagIsExercised) {
    auto base = [] {
        Scene s;
        s.camera.eye = glm::vec3(0, 1, 4);
        s.camera.target = glm::vec3(0.0f);
        s.settings.width = s.settings.height = 16;
        s.settings.max_depth = 4;
        return s;
    };
    std::vector<std::pair<std::string, Scene>> cases;
    auto with_material = [&](const std::string& label, Material m) {
        Scene s = base();
        add_material(s, m, label);
        add_sphere(s, glm::vec3(0.0f), 1.0f, 2, 0, false);
        s.environment = constant_environment(glm::vec3(0.5f));
        PunctualLight p;
        p.position = glm::vec3(2, 3, 2);
        s.punctual_lights.push_back(p);
        Material e = make_material("lambert");
        e.emission[0] = e.emission[1] = e.emission[2] = 2.0f;
        add_material(s, e, "emitter");
        add_quad(s, glm::vec3(-1, 3, -1), glm::vec3(0, 0, 2), glm::vec3(2, 0, 0), 1);
        build_lights(s);
        cases.push_back({label, s});
    };
    with_material("lambert", make_material("lambert"));
    with_material("oren_nayar", make_material("oren_nayar"));
    with_material("ashikhmin_shirley", make_material("ashikhmin_shirley"));
    with_material("blinn_phong", make_material("blinn_phong_normalized"));
    with_material("ggx", make_material("ggx"));
    with_material("beckmann", make_material("cook_torrance"));
    with_material("dielectric", make_material("dielectric"));
    Material rough_glass = make_material("dielectric");
    rough_glass.ndf = FC_NDF_BECKMANN;
    rough_glass.alpha_x = rough_glass.alpha_y = 0.2f;
    with_material("rough dielectric (beckmann)", rough_glass);
    with_material("conductor", make_material("conductor"));
    Material half_metal = make_material("ggx");
    set_metallic_roughness(half_metal, glm::vec3(0.9f, 0.6f, 0.3f), 0.5f, 0.04f);
    with_material("metallic", half_metal);
    Material tinted_glass = make_material("dielectric");
    tinted_glass.attenuation = glm::vec3(0.5f, 1.0f, 2.0f);  // Beer-Lambert inside (KHR_materials_volume)
    with_material("absorbing dielectric (volume)", tinted_glass);
    Material layered = half_metal;  // glTF's clearcoat and sheen layers over it
    layered.clearcoat = 0.8f;
    layered.clearcoat_alpha = 0.05f;
    layered.sheen = glm::vec3(0.6f, 0.3f, 0.9f);
    layered.sheen_roughness = 0.5f;
    with_material("clearcoat and sheen", layered);
    Material brushed = half_metal;  // KHR_materials_anisotropy: the frame follows the tangent
    brushed.anisotropy = 0.8f;
    brushed.anisotropy_rotation = 0.5f;
    with_material("anisotropy", brushed);
    Material textured = make_material("ggx");
    textured.textures.base_color = textured.textures.roughness = textured.textures.normal = 0;
    with_material("textured", textured);
    cases.back().second.textures.push_back(make_texture(2, 1, {0.2f, 0.4f, 0.6f, 1.0f, 0.9f, 0.5f, 0.7f, 1.0f}));
    Material layer_textures = layered;  // the extensions' textures: clearcoat, sheen, specular
    layer_textures.textures.clearcoat = layer_textures.textures.clearcoat_roughness = 0;
    layer_textures.textures.sheen_color = layer_textures.textures.sheen_roughness = 0;
    layer_textures.textures.specular_extension = true;
    layer_textures.textures.specular_strength = 0;
    layer_textures.textures.clearcoat_normal = 0;  // the coat's own normal map
    with_material("clearcoat, sheen and specular textures", layer_textures);
    cases.back().second.textures.push_back(make_texture(2, 1, {0.2f, 0.4f, 0.6f, 0.3f, 0.9f, 0.5f, 0.7f, 1.0f}));
    Material cutout = make_material("lambert");  // alpha: a texture's cut-out, and a constant's veil
    cutout.alpha_mode = FC_ALPHA_MASK;
    cutout.textures.alpha = 0;
    with_material("alpha mask", cutout);
    cases.back().second.textures.push_back(make_texture(2, 1, {1.0f, 1.0f, 1.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f}));
    Material veil = make_material("lambert");
    veil.alpha_mode = FC_ALPHA_BLEND;
    veil.alpha = 0.5f;
    with_material("alpha blend", veil);
    {
        Scene s = base();  // analytic spheres, one of them a sphere light
        add_material(s, make_material("lambert"), "white");
        Material e = make_material("lambert");
        e.emission = glm::vec3(2.0f);
        add_material(s, e, "emitter");
        add_analytic_sphere(s, glm::vec3(0.0f), 1.0f, 0, false);
        add_analytic_sphere(s, glm::vec3(0.0f, 2.5f, 0.0f), 0.5f, 1, false);
        add_quad(s, glm::vec3(-3, -1, 3), glm::vec3(6, 0, 0), glm::vec3(0, 0, -6), 0);
        build_lights(s);
        cases.push_back({"analytic spheres", s});
    }
    {
        Scene s = base();  // one mesh placed twice (instances), once mirrored
        add_material(s, make_material("lambert"), "white");
        Scene ico;
        add_sphere(ico, glm::vec3(0.0f), 0.7f, 1, 0, false);
        SharedMesh mesh;
        mesh.name = "icosphere";
        mesh.vertices = ico.vertices;
        mesh.shading = ico.shading;
        const int m = add_shared_mesh(s, mesh);
        glm::mat4 left(1.0f), right(1.0f);
        left[3] = glm::vec4(-0.8f, 0.0f, 0.0f, 1.0f);
        right[0][0] = -1.0f, right[1][1] = 1.3f;
        right[3] = glm::vec4(0.8f, 0.0f, 0.0f, 1.0f);
        add_instance(s, m, left);
        add_instance(s, m, right);
        add_quad(s, glm::vec3(-3, -1, 3), glm::vec3(6, 0, 0), glm::vec3(0, 0, -6), 0);
        PunctualLight p;
        p.position = glm::vec3(0, 3, 3);
        s.punctual_lights.push_back(p);
        build_lights(s);
        cases.push_back({"instances", s});
    }
    FeatureMask seen_on = 0, seen_off = 0;
    for (auto& [label, scene] : cases) {
        FeatureMask mask = scene_features(scene);
        seen_on |= mask;
        seen_off |= ~mask;
        expect_same_distribution(render_both(scene, 8), label);
    }
    // Lights off: a scene lit only by a point light, one only by the environment.
    for (int only_environment = 0; only_environment < 2; ++only_environment) {
        Scene dark = base();
        add_material(dark, make_material("lambert"), "white");
        add_sphere(dark, glm::vec3(0.0f), 1.0f, 2, 0, false);
        if (only_environment) {
            dark.environment = constant_environment(glm::vec3(1.0f));
        } else {
            PunctualLight p;
            p.position = glm::vec3(0, 3, 3);
            dark.punctual_lights.push_back(p);
        }
        build_lights(dark);
        seen_off |= ~scene_features(dark);
        expect_same_distribution(render_both(dark, 8), only_environment ? "environment only" : "point light only");
    }
    EXPECT_EQ(seen_on & all_features(), all_features()) << "every flag is on in some test scene";
    EXPECT_EQ(seen_off & all_features(), all_features()) << "every flag is off in some test scene";
}

}  // namespace
}  // namespace facet
