// Reading Beer-Lambert absorption (Material::attenuation): glTF's KHR_materials_volume and
// the JSON keys attenuation_color / attenuation_distance, with their errors. The rendering
// is VolumeRender's (volume_render_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/error.hpp"
#include "host/readers/load_scene.hpp"
#include "tests/gltf_test_util.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

const Material& material_named(const Scene& s, const std::string& name) {
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        if (s.material_names[i] == name) return s.materials[i];
    throw Error("no material " + name);
}

TEST(MaterialVolume, GltfVolumeGivesTheCoefficient) {
    test::TempDir d;
    const Scene s = load_scene(d.write(
        "glass.gltf", test::one_triangle_gltf(R"("extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
        "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationColor": [0.5, 0.25, 1], "attenuationDistance": 2}})")));
    const Material& m = material_named(s, "glass");
    EXPECT_EQ(m.specular_model, FC_SPECULAR_DIELECTRIC);
    EXPECT_NEAR(m.attenuation.x, std::log(2.0) / 2.0, 1e-6);
    EXPECT_NEAR(m.attenuation.y, std::log(4.0) / 2.0, 1e-6);
    EXPECT_EQ(m.attenuation.z, 0.0f);
    for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_materials_volume"), std::string::npos) << w;
}

TEST(MaterialVolume, GltfVolumeWithoutTransmissionIsIgnoredWithAWarning) {
    test::TempDir d;
    const Scene s = load_scene(d.write("paint.gltf", test::one_triangle_gltf(R"("extensions": {"KHR_materials_volume":
        {"attenuationColor": [0.5, 0.5, 0.5], "attenuationDistance": 1}})")));
    EXPECT_EQ(material_named(s, "glass").attenuation, glm::vec3(0.0f));
    bool warned = false;
    for (const std::string& w : s.warnings) warned = warned || w.find("KHR_materials_volume") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(MaterialVolume, GltfBadValuesNameTheKey) {
    test::TempDir d;
    const std::string transmit = R"("KHR_materials_transmission": {"transmissionFactor": 1}, )";
    for (const auto& [volume, key] :
         {std::pair<std::string, std::string>{R"({"attenuationColor": [2, 0, 0], "attenuationDistance": 1})",
                                              "attenuationColor"},
          {R"({"attenuationColor": [1, 1], "attenuationDistance": 1})", "attenuationColor"},
          {R"({"attenuationDistance": -1})", "attenuationDistance"}}) {
        const std::string path = d.write(
            "bad.gltf",
            test::one_triangle_gltf(R"("extensions": {)" + transmit + R"("KHR_materials_volume": )" + volume + "}"));
        try {
            load_scene(path);
            ADD_FAILURE() << volume << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("KHR_materials_volume." + key), std::string::npos) << e.what();
        }
    }
}

TEST(MaterialVolume, JsonKeys) {
    test::TempDir d;
    const std::string shapes =
        R"(, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "g"}]})";
    const Scene s = load_scene(d.write("ok.json", R"({"materials": {"g": {"model": "dielectric",
        "attenuation_color": [0.5, 1, 1], "attenuation_distance": 0.5}})" +
                                                      shapes));
    EXPECT_NEAR(material_named(s, "g").attenuation.x, std::log(2.0) / 0.5, 1e-6);
    const std::pair<std::string, std::string> bad[] = {
        {R"("model": "dielectric", "attenuation_color": [0.5, 1, 1])", "needs both"},
        {R"("model": "ggx", "attenuation_color": [0.5, 1, 1], "attenuation_distance": 1)", "transmissive"},
        {R"("model": "dielectric", "attenuation_color": [1.5, 1, 1], "attenuation_distance": 1)", "at most 1"},
        {R"("model": "dielectric", "attenuation_color": [0.5, 1, 1], "attenuation_distance": 0)",
         "attenuation_distance"}};
    for (const auto& [keys, words] : bad) {
        const std::string path = d.write("bad.json", R"({"materials": {"g": {)" + keys + "}}" + shapes);
        try {
            load_scene(path);
            ADD_FAILURE() << keys << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("materials.g.attenuation"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace facet
