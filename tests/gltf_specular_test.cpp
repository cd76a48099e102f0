// glTF's KHR_materials_specular (host/readers/gltf_material.cpp read_specular): the
// dielectric's F0 = min(F0(ior) specularColorFactor, 1) specularFactor and its F90 =
// specularFactor, on the untextured dielectric-metal mix; ignored with a warning on glass.
#include <gtest/gtest.h>

#include <string>

#include "host/error.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

bool warned(const Scene& s, const std::string& words) {
    for (const std::string& w : s.warnings)
        if (w.find(words) != std::string::npos) return true;
    return false;
}

TEST(GltfSpecular, FactorAndColourScaleTheDielectricF0) {
    test::TempDir d;
    for (double metallic : {0.0, 0.5}) {
        SCOPED_TRACE(metallic);
        const Scene s = load_scene(d.write("spec.gltf", test::one_triangle_gltf(R"("extensions": {
            "KHR_materials_ior": {"ior": 1.5},
            "KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [1, 0.5, 30]}})",
                                                                                metallic)));
        const Material& m = s.materials[0];  // "glass" (then the default key light's)
        ASSERT_EQ(s.material_names[0], "glass");
        EXPECT_NEAR(m.f0.x, 0.04f * 0.5f, 1e-6f);
        EXPECT_NEAR(m.f0.y, 0.02f * 0.5f, 1e-6f);
        EXPECT_NEAR(m.f0.z, 1.0f * 0.5f, 1e-6f);  // F0(ior) x 30 clamped to 1
        EXPECT_FLOAT_EQ(m.specular_f90, 0.5f);    // F90 = specularFactor
        EXPECT_FLOAT_EQ(m.metallic, float(metallic));
        EXPECT_FALSE(warned(s, "KHR_materials_specular"));
    }
}

TEST(GltfSpecular, IgnoredOnGlassAndBadValuesRefused) {
    test::TempDir d;
    const Scene glass = load_scene(d.write("glass.gltf", test::one_triangle_gltf(R"("extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_specular": {"specularFactor": 0.2}})")));
    EXPECT_TRUE(warned(glass, "KHR_materials_specular on a transmissive material"));
    try {
        load_scene(d.write("bad.gltf", test::one_triangle_gltf(R"("extensions": {
            "KHR_materials_specular": {"specularFactor": 2}})")));
        ADD_FAILURE() << "specularFactor 2 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("KHR_materials_specular.specularFactor"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace facet
