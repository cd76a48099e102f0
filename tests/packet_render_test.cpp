// Issue 29's packet paths (kernels/integrator/packet_paths.cl: eight paths a work-item in
// float8 lanes, its formulas the lane-generic bodies of kernels/lanes/, other BSDFs per lane)
// against the scalar form (render_pass, one path a work-item): the same samples of the Cornell
// box, of Lambertian spheres and of every other model, glass included, so the same image up to
// the order of a few additions. Every pixel channel must agree to 1e-4
// relative, no sample may be rejected, and the images' means must agree to 1e-6. The bench
// (`facet_bench --only packet`) times the two. And the policy that picks packets
// (host/render/packet_paths.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/features.hpp"
#include "host/render/packet_paths.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/texture.hpp"
#include "kernels/shared/render_layout.h"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

// Sets an environment variable for a scope, restoring what was there.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* was = std::getenv(name)) had_ = true, was_ = was;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (had_) setenv(name_, was_.c_str(), 1);
        else unsetenv(name_);
    }

private:
    const char* name_;
    bool had_ = false;
    std::string was_;
};

// A tree of this node width (4 or 8), quantised (8-wide) or not.
BvhOptions nodes(int width, int quantised) {
    BvhOptions o;
    o.width = width;
    o.quantised = quantised;
    return o;
}

bool packets_here() {
    ClContext& ctx = test::context();
    return packet_paths_for(ctx.desc(), ctx.device().getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>(),
                            feature::kAREA_LIGHTS, true, FC_SAMPLER_SOBOL, false);
}

// Renders `scene` at 37x29 in passes of 1, 2 and 21 samples by packet_pass, in packets of
// `packet_width` (FACET_PACKET_WIDTH: both widths run on any CPU that runs packets), and by
// render_pass, and compares the images. The tree is the one `facet render` builds for such a
// scene on CPUs that run packets unless `bvh_options` say otherwise: 8-wide with float boxes,
// the nodes the packets' rays are traced through together (kernels/trace/packet_trace.cl), its
// SAH the packets' in the smallest trees (packet_tree_options); on 4-wide nodes they are
// traced one by one.
void expect_packets_match_the_scalar_kernel(Scene scene, const char* name, const char* packet_width,
                                            std::optional<BvhOptions> bvh_options = std::nullopt) {
    if (!packets_here()) GTEST_SKIP() << "this device runs no packets (not a CPU with 8-wide vectors)";
    // 37 wide: the last work-item of a row has 5 pixels (at 16: 5)
    const std::uint32_t width = 37, height = 29, spp = 24;
    scene.settings.width = width;
    scene.settings.height = height;
    if (!bvh_options) {
        bvh_options = nodes(8, 0);
        packet_tree_options(*bvh_options, scene.vertices.size() / 3, true);
    }
    const Bvh bvh = build_bvh(scene.vertices, *bvh_options);
    ScopedEnv lanes("FACET_PACKET_WIDTH", packet_width);
    Renderer packets(test::context(), scene, bvh);
    ASSERT_TRUE(packets.stats().packet_paths) << name << " on this CPU should run packets";
    ASSERT_EQ(packets.stats().packet_width, std::uint32_t(std::stoi(packet_width)));
    for (std::uint32_t pass : {1u, 2u, 21u}) packets.render(pass);
    std::vector<float> scalar_image;
    {
        ScopedEnv off("FACET_PACKET_PATHS", "0");
        Renderer scalar(test::context(), scene, bvh);
        ASSERT_FALSE(scalar.stats().packet_paths);
        for (std::uint32_t pass : {1u, 2u, 21u}) scalar.render(pass);
        scalar_image = scalar.image();
    }
    double rejected = 0.0;
    const std::vector<float> packet_image = packets.image(&rejected);
    ASSERT_EQ(packet_image.size(), scalar_image.size());
    double mean_scalar = 0.0, mean_packet = 0.0;
    int differ = 0;
    for (std::size_t k = 0; k < packet_image.size(); ++k) {
        const double a = scalar_image[k], b = packet_image[k];
        mean_scalar += a;
        mean_packet += b;
        if (!(std::fabs(a - b) <= 1e-4 * std::max(1e-3, std::fabs(a))) && differ++ < 5)
            ADD_FAILURE() << "value " << k << ": scalar " << a << ", packet " << b;
    }
    mean_scalar /= double(packet_image.size());
    mean_packet /= double(packet_image.size());
    std::printf("[ packet   ] %s %ux%u %u spp, packets of %s: means %.7f (scalar) / %.7f (packet), %d values differ\n",
                name, width, height, spp, packet_width, mean_scalar, mean_packet, differ);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(rejected, 0.0);
    EXPECT_GT(mean_scalar, 0.01);  // a lit image, not two black ones
    EXPECT_NEAR(mean_packet, mean_scalar, 1e-6 * mean_scalar);
}

TEST(PacketRender, SameImageAsTheScalarKernel) {
    for (const char* w : {"8", "16"})
        expect_packets_match_the_scalar_kernel(load_scene(test::scenes_dir() + "/cornell_box.json"), "Cornell box", w);
    // In a tree this small every ray of a packet stays in it to the leaves
    // (packet_trace_min_for); in larger ones the rays left fewer than FC_PACKET_TRACE_MIN in a
    // node finish its subtree one by one, and their hits must be the same.
    for (const char* fewest : {"4", "16"}) {
        ScopedEnv handed("FACET_PACKET_TRACE_MIN", fewest);
        expect_packets_match_the_scalar_kernel(load_scene(test::scenes_dir() + "/cornell_box.json"),
                                               "Cornell box, subtrees handed to single rays", "16");
    }
    // ...and on the tree of the blocked SAH, which larger scenes and GPUs get
    expect_packets_match_the_scalar_kernel(load_scene(test::scenes_dir() + "/cornell_box.json"),
                                           "Cornell box, blocked SAH", "16", nodes(8, 0));
}

// The Cornell box on the other node layouts: quantised 8-wide nodes (rays traced in packets,
// the boxes decoded per child) and 4-wide ones (rays traced one by one).
TEST(PacketRender, SameImageAsTheScalarKernelOnEveryNodeLayout) {
    const Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    for (const char* w : {"8", "16"}) {
        expect_packets_match_the_scalar_kernel(scene, "Cornell box, quantised 8-wide nodes", w, nodes(8, 1));
        expect_packets_match_the_scalar_kernel(scene, "Cornell box, 4-wide nodes", w, nodes(4, 0));
    }
}

// Every material of `scene` Lambertian, its diffuse colour kept (a black one made grey).
void make_lambertian(Scene& scene) {
    for (Material& m : scene.materials) {
        m.diffuse_model = FC_DIFFUSE_LAMBERT;
        m.specular_model = FC_SPECULAR_NONE;
        m.metallic = 0.0f;
        if (m.diffuse == glm::vec3(0.0f)) m.diffuse = glm::vec3(0.5f);
    }
}

// Spheres (their own surface and ray offsets) with Lambertian materials: material_grid with
// every material turned Lambertian, its diffuse colour kept. Rays escape past the backdrop.
TEST(PacketRender, SameImageAsTheScalarKernelWithSpheres) {
    Scene scene = load_scene(test::scenes_dir() + "/material_grid.json");
    make_lambertian(scene);
    ASSERT_EQ(scene_features(scene), feature::kAREA_LIGHTS | feature::kSPHERES);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "material_grid, Lambertian", w);
}

// Lit by the environment alone: spheres_sky's sun and sky (a map sampled per lane by
// env_sample, met by escaping rays), its spheres Lambertian, with the map read at the
// nearest texel and bilinearly.
TEST(PacketRender, SameImageAsTheScalarKernelUnderTheSky) {
    Scene scene = load_scene(test::scenes_dir() + "/spheres_sky.json");
    make_lambertian(scene);
    ASSERT_EQ(scene_features(scene), feature::kENVIRONMENT | feature::kSPHERES);
    ASSERT_TRUE(lights_in_packets(scene));
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "spheres_sky, Lambertian", w);
    set_environment_filter(scene.environment, FC_ENV_FILTER_BILINEAR);
    expect_packets_match_the_scalar_kernel(scene, "spheres_sky, Lambertian, bilinear sky", "16");
}

// A 4 x 4 checker of two colours, opaque.
TextureImage two_colour_checker() {
    std::vector<float> rgba;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const bool odd = ((x + y) & 1) != 0;
            rgba.insert(rgba.end(), {odd ? 0.9f : 0.2f, 0.6f, odd ? 0.1f : 0.8f, 1.0f});
        }
    return make_texture(4, 4, rgba);
}

// Textured Lambertian materials: material_grid made Lambertian, a 4 x 4 checker of two colours
// (repeating) on every material's base colour and on its lights' emission, so the spheres'
// colours (their uv from the normal), the backdrop's and the lights' light samples (read per
// lane at the sampled point) come from the texture, filtered by each path's ray cone.
TEST(PacketRender, SameImageAsTheScalarKernelTextured) {
    Scene scene = load_scene(test::scenes_dir() + "/material_grid.json");
    make_lambertian(scene);
    scene.textures.push_back(two_colour_checker());
    for (Material& m : scene.materials) {
        m.textures.base_color = 0;
        m.textures.emission = 0;
    }
    ASSERT_EQ(scene_features(scene), feature::kAREA_LIGHTS | feature::kSPHERES | feature::kTEXTURES);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "material_grid, textured", w);
}

// Cut-outs: the textured material_grid with every triangle's material (the backdrop's and
// the lights') cut out where the checker's alpha is below 0.5 (mask) or present with
// probability 0.6 (blend, the alpha test's own random numbers per ray): the closest and
// shadow rays pass the holes lane by lane, and a light's sample is weighted by its coverage
// at the sampled point. Spheres have no uv alpha.
TEST(PacketRender, SameImageAsTheScalarKernelCutOut) {
    Scene scene = load_scene(test::scenes_dir() + "/material_grid.json");
    make_lambertian(scene);
    std::vector<float> rgba;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) rgba.insert(rgba.end(), {0.7f, 0.6f, 0.5f, ((x + y) & 1) != 0 ? 0.2f : 1.0f});
    scene.textures.push_back(make_texture(4, 4, rgba));
    for (std::size_t k = 0; k < scene.materials.size(); ++k) {
        Material& m = scene.materials[k];
        m.textures.alpha = 0;
        m.alpha_mode = k % 2 == 0 ? FC_ALPHA_MASK : FC_ALPHA_BLEND;
        m.alpha = k % 2 == 0 ? 1.0f : 0.6f;
    }
    ASSERT_EQ(scene_features(scene) & feature::kALPHA, feature::kALPHA);
    ASSERT_EQ(scene_features(scene) & ~packet_features(), 0u);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "material_grid, cut out", w);
}

// Punctual lights (delta: no MIS, the shadow ray stopped short of a point light): the glTF
// test scene's point light beside its emitting triangles, its materials made Lambertian; then
// a spot and a directional light in its place, and the BSDF-only strategy, under which a
// delta light still counts.
TEST(PacketRender, SameImageAsTheScalarKernelWithPunctualLights) {
    Scene scene = load_scene(test::scenes_dir() + "/gltf_materials.gltf");
    make_lambertian(scene);
    ASSERT_EQ(scene_features(scene) & ~packet_features(), 0u) << describe_features(scene_features(scene));
    ASSERT_NE(scene_features(scene) & feature::kPUNCTUAL_LIGHTS, 0u);
    ASSERT_TRUE(lights_in_packets(scene));
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "gltf_materials, point light", w);
    ASSERT_FALSE(scene.punctual_lights.empty());
    for (PunctualLight& l : scene.punctual_lights) {
        l.type = FC_LIGHT_SPOT;  // down its default axis, -y
        l.inner_degrees = 20.0f;
        l.outer_degrees = 60.0f;
    }
    build_lights(scene);
    expect_packets_match_the_scalar_kernel(scene, "gltf_materials, spot light", "16");
    for (PunctualLight& l : scene.punctual_lights) {
        l.type = FC_LIGHT_DIRECTIONAL;
        l.direction = glm::vec3(0.3f, -1.0f, -0.4f);
    }
    build_lights(scene);
    expect_packets_match_the_scalar_kernel(scene, "gltf_materials, directional light", "16");
    scene.settings.strategy = FC_STRATEGY_BSDF;
    expect_packets_match_the_scalar_kernel(scene, "gltf_materials, directional light, BSDF sampling", "8");
}

// A bare model, as `facet render model.obj` first meets one: the default key light (two
// emitting triangles) and the uniform white environment (host/readers/default_lighting.hpp),
// so a light sample picks either.
TEST(PacketRender, SameImageAsTheScalarKernelForABareModel) {
    test::TempDir dir;
    Scene scene = load_scene(dir.write("tet.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                       "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"));
    ASSERT_EQ(scene_features(scene), feature::kAREA_LIGHTS | feature::kENVIRONMENT);
    ASSERT_TRUE(lights_in_packets(scene));
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "a bare tetrahedron", w);
}

// The lights packet_pass samples: emitting triangles, the environment and punctual lights
// (gltf_materials' point light), not an emitting sphere (furnace_sphere's).
TEST(PacketRender, LightsInPackets) {
    EXPECT_TRUE(lights_in_packets(load_scene(test::scenes_dir() + "/cornell_box.json")));
    EXPECT_TRUE(lights_in_packets(load_scene(test::scenes_dir() + "/spheres_sky.json")));
    EXPECT_FALSE(lights_in_packets(load_scene(test::scenes_dir() + "/furnace_sphere.json")));
    EXPECT_TRUE(lights_in_packets(load_scene(test::scenes_dir() + "/gltf_materials.gltf")));
}

// Which scenes packet_pass shades in its lanes alone: those whose materials are a Lambertian
// lobe each. Models that have no feature of their own (EON, the Lambert x (1 - F0) base, a
// material with no lobe) were once shaded as Lambertian there (an EON sphere came out 13 %
// too bright); they now run per lane, and the image is render_pass's.
TEST(PacketRender, LambertianMaterials) {
    EXPECT_TRUE(lambertian_materials(load_scene(test::scenes_dir() + "/cornell_box.json")));
    EXPECT_FALSE(lambertian_materials(load_scene(test::scenes_dir() + "/spheres_sky.json")));
    test::TempDir dir;
    auto sphere_of = [&](const std::string& file, const std::string& material, const std::string& unused) {
        return load_scene(dir.write(file,
                                    "{\"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n"
                                    " \"materials\": {\"m\": " +
                                        material + ", \"spare\": " + unused +
                                        "},\n"
                                        " \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], "
                                        "\"radius\": 1, \"material\": \"m\"},\n"
                                        "  {\"type\": \"quad\", \"corner\": [-3, -1, 3], \"edge1\": [6, 0, 0], "
                                        "\"edge2\": [0, 0, -6], \"material\": \"spare\"}],\n"
                                        " \"environment\": {\"constant\": [1, 1, 1]}}\n"));
    };
    const std::string lambert = "{\"model\": \"lambert\", \"diffuse\": [0.5, 0.5, 0.5]}";
    const std::string eon = "{\"model\": \"eon\", \"diffuse\": [0.8, 0.8, 0.8], \"roughness\": 1}";
    EXPECT_TRUE(lambertian_materials(sphere_of("lambert.json", lambert, lambert)));
    const Scene eon_sphere = sphere_of("eon.json", eon, lambert);
    ASSERT_EQ(scene_features(eon_sphere), feature::kENVIRONMENT | feature::kSPHERES);  // no feature says EON
    EXPECT_FALSE(lambertian_materials(eon_sphere));
    EXPECT_FALSE(lambertian_materials(sphere_of(
        "coupled.json", "{\"model\": \"lambert\", \"diffuse_model\": \"lambert_1mf0\", \"diffuse\": [0.5, 0.5, 0.5]}",
        lambert)));
    const Scene lobeless = sphere_of(
        "none.json", "{\"model\": \"lambert\", \"diffuse_model\": \"none\", \"diffuse\": [0.5, 0.5, 0.5]}", lambert);
    EXPECT_FALSE(lambertian_materials(lobeless));
    EXPECT_FALSE(lambertian_materials(sphere_of("coat.json", "{\"model\": \"lambert\", \"clearcoat\": 1}", lambert)));
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(eon_sphere, "an EON sphere", w);
    expect_packets_match_the_scalar_kernel(lobeless, "a sphere of no lobe", "16");
}

// Every material runs in packets, its BSDF per lane where it is more than a Lambertian lobe: material_grid's seven
// models (Lambert, Oren-Nayar, Cook-Torrance, Blinn-Phong and its normalised form, Ashikhmin-Shirley, compensated GGX)
// on spheres under an area light, under each strategy; spheres_sky's under the sun and sky.
TEST(PacketRender, SameImageAsTheScalarKernelWithEveryModel) {
    Scene scene = load_scene(test::scenes_dir() + "/material_grid.json");
    ASSERT_FALSE(lambertian_materials(scene));
    ASSERT_EQ(scene_features(scene) & ~packet_features(), 0u) << describe_features(scene_features(scene));
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "material_grid", w);
    scene.settings.strategy = FC_STRATEGY_LIGHT;
    expect_packets_match_the_scalar_kernel(scene, "material_grid, light sampling", "16");
    scene.settings.strategy = FC_STRATEGY_BSDF;
    expect_packets_match_the_scalar_kernel(scene, "material_grid, BSDF sampling", "8");
    const Scene sky = load_scene(test::scenes_dir() + "/spheres_sky.json");
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(sky, "spheres_sky", w);
}

// Refraction per lane: glass_metal_sky's smooth, rough, tinted and Beckmann dielectrics and
// rough conductors under the sun and sky (light found through glass by next-event estimation,
// rays leaving from the far side, roulette's eta_scale), then its water absorbing inside
// (Beer-Lambert on the segments that run through it), then every dielectric rough (in lanes).
TEST(PacketRender, SameImageAsTheScalarKernelWithGlass) {
    Scene scene = load_scene(test::scenes_dir() + "/glass_metal_sky.json");
    ASSERT_NE(scene_features(scene) & feature::kDIELECTRIC, 0u);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "glass_metal_sky", w);
    {
        // Its glass block stands on the floor, its bottom face in the floor's plane: rays down
        // through the glass meet both within an ulp, which a packet's visiting order decides
        // differently from a single ray's (kernels/trace/packet_trace.cl); traced one by one.
        ScopedEnv alone("FACET_PACKET_TRACE", "0");
        expect_packets_match_the_scalar_kernel(load_scene(test::scenes_dir() + "/gltf_materials.gltf"),
                                               "gltf_materials (glass, metal, point light)", "16");
    }
    bool absorbs = false;
    for (Material& m : scene.materials)
        if (m.specular_model == FC_SPECULAR_DIELECTRIC && !absorbs) {
            m.attenuation = glm::vec3(0.8f, 0.3f, 0.1f);
            absorbs = true;
        }
    ASSERT_NE(scene_features(scene) & feature::kVOLUME, 0u);
    expect_packets_match_the_scalar_kernel(scene, "glass_metal_sky, absorbing glass", "16");
    // Every dielectric rough, GGX and Beckmann in turn, one anisotropic: most packets meet rough
    // glass in several lanes at once, and evaluate and sample it in lanes
    // (kernels/bsdf/dielectric_lanes.cl) rather than lane by lane
    Scene rough = load_scene(test::scenes_dir() + "/glass_metal_sky.json");
    int k = 0;
    for (Material& m : rough.materials)
        if (m.specular_model == FC_SPECULAR_DIELECTRIC) {
            m.ndf = k % 2 ? FC_NDF_BECKMANN : FC_NDF_GGX;
            m.alpha_x = 0.1f + 0.05f * float(k);
            m.alpha_y = k == 2 ? 0.3f : m.alpha_x;
            ++k;
        }
    ASSERT_GE(k, 4);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(rough, "glass_metal_sky, rough glass", w);
}

// glTF's layers, metal and anisotropy per lane: material_grid's models with a clearcoat, a
// sheen, metallic mixes, anisotropic GGX, a perfect mirror (a delta BSDF: no light sample) and
// EON among them, and then every base colour textured (the textured material copied per lane);
// then gltf_materials' compensated lobes with metallic mixes (the plain base's lanes).
TEST(PacketRender, SameImageAsTheScalarKernelWithLayersAndMetal) {
    Scene scene = load_scene(test::scenes_dir() + "/material_grid.json");
    for (std::size_t k = 0; k < scene.materials.size(); ++k) {
        Material& m = scene.materials[k];
        if (m.emission != glm::vec3(0.0f)) continue;
        switch (k % 6) {
            case 0:
                m.clearcoat = 0.8f;
                m.clearcoat_alpha = 0.05f;
                break;
            case 1:
                m.sheen = glm::vec3(0.6f, 0.4f, 0.9f);
                m.sheen_roughness = 0.5f;
                break;
            case 2:
                if (m.specular_model == FC_SPECULAR_MICROFACET) m.metallic = 0.5f;
                break;
            case 3:
                if (m.specular_model == FC_SPECULAR_MICROFACET && m.ndf == FC_NDF_GGX) {
                    m.anisotropy = 0.8f;
                    m.anisotropy_rotation = 0.6f;
                }
                break;
            case 4:
                if (m.specular_model == FC_SPECULAR_MICROFACET) m.alpha_x = m.alpha_y = 0.0f;  // a mirror
                break;
            default:
                m.diffuse_model = FC_DIFFUSE_EON;
                m.eon_roughness = 0.6f;
                break;
        }
    }
    const FeatureMask f = scene_features(scene);
    ASSERT_EQ(f & ~packet_features(), 0u) << describe_features(f);
    ASSERT_EQ(f & (feature::kCLEARCOAT | feature::kSHEEN | feature::kMETALLIC | feature::kANISOTROPY),
              feature::kCLEARCOAT | feature::kSHEEN | feature::kMETALLIC | feature::kANISOTROPY);
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(scene, "material_grid, layered", w);
    scene.textures.push_back(two_colour_checker());
    for (Material& m : scene.materials) m.textures.base_color = 0;
    ASSERT_NE(scene_features(scene) & feature::kTEXTURES, 0u);
    expect_packets_match_the_scalar_kernel(scene, "material_grid, layered, textured", "16");
    // glTF's defaults, energy-compensated Schlick lobes, mixed with metal at fractional M and
    // at 1 (the plain base's compensated and metallic lanes); its rays traced one by one, as
    // in ...WithGlass (its glass block's bottom face lies in the floor's plane)
    Scene gltf = load_scene(test::scenes_dir() + "/gltf_materials.gltf");
    int mixed = 0;
    for (Material& m : gltf.materials)
        if (m.specular_model == FC_SPECULAR_MICROFACET && m.emission == glm::vec3(0.0f))
            m.metallic = ++mixed % 2 ? 0.4f : 1.0f;
    ASSERT_GE(mixed, 2);
    ScopedEnv alone("FACET_PACKET_TRACE", "0");
    for (const char* w : {"8", "16"}) expect_packets_match_the_scalar_kernel(gltf, "gltf_materials, metallic mixes", w);
}

TEST(PacketRender, PickedOnlyWhereTheKernelCoversTheProgram) {
    DeviceDesc cpu, gpu;
    cpu.type = CL_DEVICE_TYPE_CPU;
    gpu.type = CL_DEVICE_TYPE_GPU;
    using namespace feature;
    const FeatureMask area = kAREA_LIGHTS;
    EXPECT_TRUE(packet_paths_for(cpu, 8, area, true, FC_SAMPLER_SOBOL, false));
    EXPECT_TRUE(packet_paths_for(cpu, 8, area | kSPHERES, true, FC_SAMPLER_SOBOL, false));
    EXPECT_TRUE(packet_paths_for(cpu, 16, area, true, FC_SAMPLER_SOBOL, false));
    EXPECT_FALSE(packet_paths_for(cpu, 4, area, true, FC_SAMPLER_SOBOL, false));        // SSE only
    EXPECT_FALSE(packet_paths_for(gpu, 8, area, true, FC_SAMPLER_SOBOL, false));        // one path a work-item
    EXPECT_FALSE(packet_paths_for(cpu, 8, area, true, FC_SAMPLER_INDEPENDENT, false));  // the lanes' sampler is Sobol'
    EXPECT_FALSE(packet_paths_for(cpu, 8, area, true, FC_SAMPLER_SOBOL, true));         // the generic program
    EXPECT_FALSE(packet_paths_for(cpu, 8, area | kSPHERES, false, FC_SAMPLER_SOBOL, false));  // an emitting sphere
    EXPECT_FALSE(packet_paths_for(cpu, 8, all_features(), true, FC_SAMPLER_SOBOL, false));    // other materials, lights
    EXPECT_TRUE(packet_paths_for(cpu, 8, kENVIRONMENT, true, FC_SAMPLER_SOBOL, false));       // lit by the sky alone
    EXPECT_TRUE(packet_paths_for(cpu, 8, area | kENVIRONMENT | kSPHERES, true, FC_SAMPLER_SOBOL, false));
    EXPECT_FALSE(packet_paths_for(cpu, 8, 0, true, FC_SAMPLER_SOBOL, false));  // no light the lanes sample
    EXPECT_FALSE(packet_paths_for(cpu, 8, kSPHERES, true, FC_SAMPLER_SOBOL, false));
    // instances turn packets off; every other feature is covered
    const std::vector<std::string> names = feature_names();
    for (std::size_t bit = 0; bit < names.size(); ++bit) {
        SCOPED_TRACE(names[bit]);
        EXPECT_EQ(packet_paths_for(cpu, 8, area | (1u << bit), true, FC_SAMPLER_SOBOL, false),
                  names[bit] != "instances");
    }
    {
        ScopedEnv off("FACET_PACKET_PATHS", "0");
        EXPECT_FALSE(packet_paths_for(cpu, 8, area, true, FC_SAMPLER_SOBOL, false));
    }
    // the width: 16 where the native float vectors are 16 wide (AVX-512), else 8; the variable chooses
    EXPECT_EQ(packet_width_for(8), 8u);
    EXPECT_EQ(packet_width_for(16), 16u);
    EXPECT_EQ(packet_width_for(32), 16u);
    {
        ScopedEnv narrow("FACET_PACKET_WIDTH", "8");
        EXPECT_EQ(packet_width_for(16), 8u);
    }
    {
        ScopedEnv wide("FACET_PACKET_WIDTH", "16");
        EXPECT_EQ(packet_width_for(8), 16u);
    }
    // forced on (for the Oclgrind tier): any device, but only where the kernel covers the program
    ScopedEnv on("FACET_PACKET_PATHS", "1");
    EXPECT_TRUE(packet_paths_for(gpu, 1, area, true, FC_SAMPLER_SOBOL, false));
    EXPECT_FALSE(packet_paths_for(cpu, 8, all_features(), true, FC_SAMPLER_SOBOL, false));
    EXPECT_FALSE(packet_paths_for(cpu, 8, area, true, FC_SAMPLER_INDEPENDENT, false));
}

// The rays of a packet are traced together in small trees only (kPacketTraceUpToTriangles);
// FACET_PACKET_TRACE says so whatever the size.
TEST(PacketRender, RaysInPacketsInSmallTrees) {
    ScopedEnv unset_first("FACET_PACKET_TRACE", "");
    unsetenv("FACET_PACKET_TRACE");
    EXPECT_TRUE(packet_trace_for(32));
    EXPECT_TRUE(packet_trace_for(kPacketTraceUpToTriangles));
    EXPECT_FALSE(packet_trace_for(kPacketTraceUpToTriangles + 1));
    {
        ScopedEnv off("FACET_PACKET_TRACE", "0");
        EXPECT_FALSE(packet_trace_for(32));
    }
    {
        ScopedEnv on("FACET_PACKET_TRACE", "1");
        EXPECT_TRUE(packet_trace_for(1000000));
    }
}

// In the smallest trees every ray of a packet goes to the leaves with it; in larger ones the
// rays fewer than 4 in a node finish its subtree alone. FACET_PACKET_TRACE_MIN says how many
// whatever the size, from 1 to 16; another value is not read.
TEST(PacketRender, RaysHandedToSingleRayTraversalInLargerTrees) {
    ScopedEnv unset_first("FACET_PACKET_TRACE_MIN", "");
    unsetenv("FACET_PACKET_TRACE_MIN");
    EXPECT_EQ(packet_trace_min_for(32), 1u);
    EXPECT_EQ(packet_trace_min_for(kPacketTraceTogetherUpToTriangles), 1u);
    EXPECT_EQ(packet_trace_min_for(kPacketTraceTogetherUpToTriangles + 1), 4u);
    EXPECT_EQ(packet_trace_min_for(5858), 4u);
    for (const char* bad : {"0", "17", "4x", ""}) {
        ScopedEnv e("FACET_PACKET_TRACE_MIN", bad);
        EXPECT_EQ(packet_trace_min_for(32), 1u) << bad;
    }
    ScopedEnv e("FACET_PACKET_TRACE_MIN", "16");
    EXPECT_EQ(packet_trace_min_for(32), 16u);
    EXPECT_EQ(packet_trace_min_for(5858), 16u);
}

// The smallest trees, whose packets keep every ray to the leaves, are built with the packets'
// SAH: leaf triangles counted one by one, not in blocks of four, so the leaves are smaller.
TEST(PacketRender, SmallPacketTreesCountLeafTriangles) {
    ScopedEnv unset_first("FACET_PACKET_TRACE_MIN", "");
    unsetenv("FACET_PACKET_TRACE_MIN");
    const BvhOptions blocked = nodes(8, 0);
    BvhOptions o = blocked;
    packet_tree_options(o, 32, true);
    EXPECT_EQ(o.block_size, 1);
    EXPECT_EQ(o.intersection_cost, kPacketLeafTriangleCost);
    EXPECT_EQ(o.width, 8);  // the rest as it was
    // not where no packets run, nor in larger trees (their rays finish alone on blocks of four)
    for (auto [triangles, packets] :
         {std::pair<std::size_t, bool>{32, false}, {kPacketTraceTogetherUpToTriangles + 1, true}}) {
        BvhOptions same = blocked;
        packet_tree_options(same, triangles, packets);
        EXPECT_EQ(same.block_size, blocked.block_size) << triangles;
        EXPECT_EQ(same.intersection_cost, blocked.intersection_cost) << triangles;
    }
    {
        ScopedEnv handed("FACET_PACKET_TRACE_MIN", "4");  // rays handed over: blocked
        BvhOptions same = blocked;
        packet_tree_options(same, 32, true);
        EXPECT_EQ(same.block_size, blocked.block_size);
    }
    // the Cornell box: leaves of at most two triangles, where the blocked SAH fills blocks
    const Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    const Bvh packed = build_bvh(scene.vertices, o), blocks = build_bvh(scene.vertices, blocked);
    std::printf("[ packet   ] Cornell box: %zu leaves of at most %d triangles (blocked SAH: %zu of at most %d)\n",
                packed.stats.leaves, packed.stats.max_leaf_size, blocks.stats.leaves, blocks.stats.max_leaf_size);
    EXPECT_LE(packed.stats.max_leaf_size, 2);
    EXPECT_GT(packed.stats.leaves, blocks.stats.leaves);
    EXPECT_GT(blocks.stats.max_leaf_size, 2);
}

}  // namespace
}  // namespace facet
