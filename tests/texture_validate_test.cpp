// TextureValidate.*: texels are held to what the materials read them as (texture_validate.hpp):
// a float base-colour texture of -1 and 100 is clamped to 0..1 with one warning naming the
// file, normal maps are renormalised, emission only loses its negatives.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "host/readers/load_scene.hpp"
#include "host/scene/texture.hpp"
#include "host/scene/texture_validate.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

// A PFM colour image of one row (PFM: "PF", size, negative scale = little endian).
void write_pfm_row(const std::string& path, const std::vector<float>& rgb) {
    std::ofstream f(path, std::ios::binary);
    f << "PF\n" << rgb.size() / 3 << " 1\n-1.0\n";
    f.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size() * sizeof(float)));
}

std::size_t warnings_naming(const Scene& s, const std::string& what) {
    std::size_t n = 0;
    for (const std::string& w : s.warnings) n += w.find(what) != std::string::npos;
    return n;
}

TEST(TextureValidate, FloatBaseColourIsClampedWithOneWarning) {
    test::TempDir d;
    write_pfm_row(d.path("wild.pfm"), {-1.0f, 0.5f, 100.0f, 0.25f, 0.5f, 0.75f});
    d.write("quad.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd wild.pfm\n");
    const std::string obj = d.write("quad.obj",
                                    "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\n"
                                    "vt 1 1\nvt 0 1\nusemtl tex\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    const Scene s = load_scene(obj);
    ASSERT_EQ(s.textures.size(), 1u);
    const std::vector<float>& t = s.textures[0].texels;
    EXPECT_EQ(t[0], 0.0f);  // -1
    EXPECT_EQ(t[1], 0.5f);
    EXPECT_EQ(t[2], 1.0f);   // 100
    EXPECT_EQ(t[4], 0.25f);  // the good texel kept
    EXPECT_EQ(t[6], 0.75f);
    for (float v : t) EXPECT_TRUE(v >= 0.0f && v <= 1.0f) << v;  // the mip levels too
    EXPECT_EQ(warnings_naming(s, "wild.pfm: 1 of its 2 texels"), 1u);
    EXPECT_EQ(warnings_naming(s, "from -1 to 100"), 1u);
}

TEST(TextureValidate, NormalMapsRenormalisedEmissionKeepsItsLight) {
    Scene s;
    Material m = default_material();
    m.textures.normal = 0;
    m.textures.emission = 1;
    s.materials.push_back(m);
    // Normals: flat (kept), too short (0.5, 0.5, 0.75: n = (0, 0, 0.5)), zero (0.5, 0.5, 0.5).
    s.textures.push_back(make_texture(3, 1, {0.5f, 0.5f, 1.0f, 1.0f, 0.5f, 0.5f, 0.75f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f}));
    s.textures.back().path = "normals.exr";
    s.textures.push_back(make_texture(2, 1, {50.0f, 2.0f, -3.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f}));
    s.textures.back().path = "glow.exr";
    sanitise_textures(s);
    const std::vector<float>& n = s.textures[0].texels;
    EXPECT_EQ(n[2], 1.0f);
    EXPECT_FLOAT_EQ(n[6], 1.0f);   // (0, 0, 0.5) -> (0, 0, 1)
    EXPECT_FLOAT_EQ(n[10], 1.0f);  // zero -> unperturbed
    const std::vector<float>& e = s.textures[1].texels;
    EXPECT_EQ(e[0], 50.0f);  // emission may exceed 1
    EXPECT_EQ(e[2], 0.0f);
    EXPECT_EQ(warnings_naming(s, "normals.exr: 2 of its 3 texels"), 1u);
    EXPECT_EQ(warnings_naming(s, "glow.exr: 1 of its 2 texels"), 1u);
    EXPECT_EQ(s.warnings.size(), 2u);
}

}  // namespace
}  // namespace facet
