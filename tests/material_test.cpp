// The host side of materials (host/scene/material.cpp): presets, name tables,
// conversions, F0 presets, validation, descriptions. Named Models.* with the kernel
// tests of tests/models_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/error.hpp"
#include "host/scene/material.hpp"

namespace facet {
namespace {

TEST(Material, PresetsFollowTheTable) {
    struct Row {
        const char* name;
        int diffuse, specular;
    };
    const Row rows[] = {{"lambert", FC_DIFFUSE_LAMBERT, FC_SPECULAR_NONE},
                        {"oren_nayar", FC_DIFFUSE_OREN_NAYAR, FC_SPECULAR_NONE},
                        {"cook_torrance", FC_DIFFUSE_LAMBERT, FC_SPECULAR_MICROFACET},
                        {"blinn_phong", FC_DIFFUSE_LAMBERT, FC_SPECULAR_BLINN_PHONG},
                        {"blinn_phong_normalized", FC_DIFFUSE_LAMBERT, FC_SPECULAR_BLINN_PHONG_NORMALIZED},
                        {"ashikhmin_shirley", FC_DIFFUSE_ASHIKHMIN_SHIRLEY, FC_SPECULAR_ASHIKHMIN_SHIRLEY},
                        {"ggx", FC_DIFFUSE_LAMBERT_1MF0, FC_SPECULAR_MICROFACET},
                        {"microfacet", FC_DIFFUSE_LAMBERT_1MF0, FC_SPECULAR_MICROFACET},
                        {"conductor", FC_DIFFUSE_NONE, FC_SPECULAR_MICROFACET},
                        {"dielectric", FC_DIFFUSE_NONE, FC_SPECULAR_DIELECTRIC},
                        {"eon", FC_DIFFUSE_EON, FC_SPECULAR_NONE}};
    ASSERT_EQ(material_model_names().size(), std::size(rows));
    for (const Row& r : rows) {
        // conductor and dielectric: their own colours (dielectric_test.cpp checks them)
        if (r.diffuse == FC_DIFFUSE_NONE) {
            Material m = make_material(r.name);
            EXPECT_EQ(m.diffuse_model, r.diffuse) << r.name;
            EXPECT_EQ(m.specular_model, r.specular) << r.name;
            EXPECT_EQ(validate_material(m), "") << r.name;
            EXPECT_EQ(material_model_of(m), r.name);
            continue;
        }
        Material m = make_material(r.name);
        EXPECT_EQ(m.diffuse_model, r.diffuse) << r.name;
        EXPECT_EQ(m.specular_model, r.specular) << r.name;
        EXPECT_EQ(validate_material(m), "") << r.name;
        EXPECT_EQ(m.diffuse[1], 0.5f);
        EXPECT_EQ(specular_colour(m)[2], 0.04f);
        EXPECT_EQ(m.alpha_x, 0.3f);
        if (std::string(r.name) != "microfacet") {
            EXPECT_EQ(material_model_of(m), r.name);
        }
    }
    Material ct = make_material("cook_torrance");
    EXPECT_EQ(ct.ndf, FC_NDF_BECKMANN);
    EXPECT_EQ(ct.geometry, FC_G_COOK_TORRANCE);
    EXPECT_EQ(ct.fresnel, FC_FRESNEL_SCHLICK);
    Material ggx = make_material(std::string(kDefaultMaterialModel));
    EXPECT_EQ(ggx.ndf, FC_NDF_GGX);
    EXPECT_EQ(ggx.geometry, FC_G_SMITH_CORRELATED);
    EXPECT_FALSE(material_preset("phong").has_value());
    EXPECT_THROW(make_material("phong"), Error);
    // energy compensation: on for the GGX-based presets, off for the classic models
    for (const char* on : {"ggx", "microfacet", "conductor"}) EXPECT_TRUE(make_material(on).energy_compensation) << on;
    for (const char* off :
         {"lambert", "oren_nayar", "cook_torrance", "blinn_phong", "ashikhmin_shirley", "eon", "dielectric"})
        EXPECT_FALSE(make_material(off).energy_compensation) << off;
    try {
        make_material("phong");
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ashikhmin_shirley"), std::string::npos) << e.what();
    }
    ggx.ndf = FC_NDF_BECKMANN;
    EXPECT_EQ(material_model_of(ggx), "microfacet");
}

TEST(Material, EnumNameTables) {
    const MaterialEnum kinds[] = {MaterialEnum::Diffuse,  MaterialEnum::Specular, MaterialEnum::Ndf,
                                  MaterialEnum::Geometry, MaterialEnum::Fresnel,  MaterialEnum::Sampling};
    const int counts[] = {FC_DIFFUSE_COUNT, FC_SPECULAR_COUNT, FC_NDF_COUNT,
                          FC_G_COUNT,       FC_FRESNEL_COUNT,  FC_SAMPLE_COUNT};
    for (std::size_t k = 0; k < std::size(kinds); ++k) {
        const auto& names = enum_names(kinds[k]);
        ASSERT_EQ(int(names.size()), counts[k]) << enum_kind_name(kinds[k]);
        for (int v = 0; v < counts[k]; ++v) {
            EXPECT_EQ(names[v].value, v);
            std::string n = enum_to_name(kinds[k], v);
            EXPECT_EQ(enum_from_name(kinds[k], n), v) << n;
        }
        EXPECT_FALSE(enum_from_name(kinds[k], "nonsense").has_value());
        EXPECT_EQ(enum_to_name(kinds[k], 99), "invalid(99)");
    }
    EXPECT_EQ(enum_from_name(MaterialEnum::Geometry, "Smith_Correlated"), FC_G_SMITH_CORRELATED);
    EXPECT_EQ(enum_name_list(MaterialEnum::Sampling), "visible, all, spherical_cap or bounded");
    EXPECT_EQ(enum_name_list(MaterialEnum::Ndf), "beckmann, ggx or blinn_phong");
}

TEST(Material, RoughnessShininessConversions) {
    // lecture: m = sqrt(2/(2+s)); blog and Walter 2007: s = 2/m^2 - 2. One relation.
    for (float s : {0.0f, 1.0f, 10.0f, 20.2f, 100.0f, 1000.0f, 1e5f}) {
        float m = roughness_from_shininess(s);
        EXPECT_NEAR(m, std::sqrt(2.0f / (2.0f + s)), 1e-6f) << s;
        EXPECT_NEAR(shininess_from_roughness(m), s, 1e-4f * (s + 1.0f)) << s;
    }
    EXPECT_FLOAT_EQ(shininess_from_roughness(0.5f), 6.0f);
    EXPECT_FLOAT_EQ(shininess_from_roughness(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(roughness_from_shininess(-3.0f), 1.0f);
    EXPECT_LE(shininess_from_roughness(0.0f), 1e6f);
    EXPECT_TRUE(std::isfinite(shininess_from_roughness(NAN)));
    EXPECT_TRUE(std::isfinite(roughness_from_shininess(NAN)));
    EXPECT_TRUE(std::isfinite(roughness_from_shininess(INFINITY)));
}

TEST(Material, F0Presets) {
    struct Row {
        const char* name;
        float lin[3], srgb[3];  // the two columns of the table
    };
    const Row rows[] = {{"water", {0.02f, 0.02f, 0.02f}, {0.15f, 0.15f, 0.15f}},
                        {"plastic_low", {0.03f, 0.03f, 0.03f}, {0.21f, 0.21f, 0.21f}},
                        {"plastic_high", {0.05f, 0.05f, 0.05f}, {0.24f, 0.24f, 0.24f}},
                        {"ruby", {0.08f, 0.08f, 0.08f}, {0.31f, 0.31f, 0.31f}},
                        {"diamond", {0.17f, 0.17f, 0.17f}, {0.45f, 0.45f, 0.45f}},
                        {"iron", {0.56f, 0.57f, 0.58f}, {0.77f, 0.78f, 0.78f}},
                        {"copper", {0.95f, 0.64f, 0.54f}, {0.98f, 0.82f, 0.76f}},
                        {"gold", {1.00f, 0.71f, 0.29f}, {1.00f, 0.86f, 0.57f}},
                        {"aluminium", {0.91f, 0.92f, 0.92f}, {0.96f, 0.96f, 0.97f}},
                        {"silver", {0.95f, 0.93f, 0.88f}, {0.98f, 0.97f, 0.95f}}};
    for (const Row& r : rows) {
        auto f0 = f0_preset(r.name);
        ASSERT_TRUE(f0.has_value()) << r.name;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ((*f0)[c], r.lin[c]) << r.name;
            // the sRGB column decodes to the linear one within the table's rounding (0.015)
            EXPECT_NEAR(srgb_to_linear(r.srgb[c]), r.lin[c], 0.015f) << r.name;
        }
    }
    EXPECT_EQ(f0_preset("Gold"), f0_preset("gold"));
    EXPECT_EQ(f0_preset("aluminum"), f0_preset("aluminium"));
    EXPECT_EQ((*f0_preset("glass"))[0], 0.03f);
    EXPECT_EQ((*f0_preset("glass_high"))[0], 0.08f);
    EXPECT_FALSE(f0_preset("unobtainium").has_value());
    EXPECT_GE(f0_preset_names().size(), 10u);
}

TEST(Material, ValidateAndClamp) {
    Material m = make_material("ggx");
    EXPECT_EQ(validate_material(m), "");
    auto message = [](Material x) { return validate_material(x); };
    Material a = m;
    a.alpha_x = NAN;
    EXPECT_NE(message(a).find("alpha_x"), std::string::npos) << message(a);
    a = m, a.exponent_y = -1.0f;
    EXPECT_NE(message(a).find("exponent_y"), std::string::npos) << message(a);
    a = m, a.diffuse[1] = 1.5f;
    EXPECT_NE(message(a).find("diffuse"), std::string::npos) << message(a);
    a = m, a.f0[0] = -0.1f;
    EXPECT_NE(message(a).find("specular"), std::string::npos) << message(a);
    a = m, a.emission[2] = INFINITY;
    EXPECT_NE(message(a).find("emission"), std::string::npos) << message(a);
    a = m, a.ior = 0.0f;
    EXPECT_NE(message(a).find("ior"), std::string::npos) << message(a);
    a = m, a.sigma = NAN;
    EXPECT_NE(message(a).find("sigma"), std::string::npos) << message(a);
    a = m, a.geometry = FC_G_COUNT;
    EXPECT_NE(message(a).find("geometry"), std::string::npos) << message(a);
    a = m, a.emission[0] = 50.0f;
    EXPECT_EQ(message(a), "");

    a = m, a.exponent_x = 1e9f, a.alpha_y = -2.0f, a.sigma = 9.0f, a.alpha_x = NAN;
    clamp_material(a);
    EXPECT_EQ(a.exponent_x, 1e6f);
    EXPECT_EQ(a.alpha_y, 0.0f);
    EXPECT_LE(a.sigma, 1.5708f);
    EXPECT_TRUE(std::isnan(a.alpha_x));
}

TEST(Material, DescribeMaterial) {
    std::string s = describe_material(make_material("ggx"));
    EXPECT_EQ(s.rfind("ggx:", 0), 0u) << s;
    for (const char* part : {"lambert_1mf0", "D=ggx", "G=smith_correlated", "F=schlick", "alpha=(0.3, 0.3)"})
        EXPECT_NE(s.find(part), std::string::npos) << s;
    s = describe_material(make_material("ashikhmin_shirley"));
    EXPECT_NE(s.find("nu=20.2"), std::string::npos) << s;
    s = describe_material(make_material("oren_nayar"));
    EXPECT_NE(s.find("sigma=0.3"), std::string::npos) << s;
    EXPECT_EQ(s.find("specular"), std::string::npos) << s;
    EXPECT_EQ(s.find('\n'), std::string::npos);
    EXPECT_EQ(s.find("alpha_mode"), std::string::npos) << "opaque says nothing of alpha: " << s;
    Material cutout = make_material("lambert");
    cutout.alpha_mode = FC_ALPHA_MASK;
    cutout.alpha_cutoff = 0.25f;
    cutout.textures.alpha = 0;
    s = describe_material(cutout);
    EXPECT_NE(s.find("alpha_mode=mask alpha=1 cutoff=0.25 x texture A"), std::string::npos) << s;
}

}  // namespace
}  // namespace facet
