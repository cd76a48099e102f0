// TextureAlpha.*: the colour of an RGBA image is read as stored, whatever its alpha
// (glTF's OPAQUE ignores alpha; OpenImageIO would otherwise multiply it in on read),
// through load_texture and the kernels' texture lookup; the alpha itself is kept in the
// texels for cut-outs, and the MTL and JSON readers bind it (d, Tr, map_d; alpha_mode,
// alpha, alpha_cutoff, textures.alpha).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "host/readers/load_scene.hpp"
#include "host/readers/obj_reader.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/scene_test_util.hpp"
#include "tests/temp_dir.hpp"
#include "tests/texture_test_util.hpp"

namespace facet {
namespace {

// Writes a w x 1 8-bit PNG of `channels` channels (1: grey, 4: RGBA with unassociated alpha);
// false when this OpenImageIO writes no PNG.
bool write_png(const std::string& path, int w, int channels, const unsigned char* bytes) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec(w, 1, channels, OIIO::TypeDesc::UINT8);
    if (channels == 4) spec.attribute("oiio:UnassociatedAlpha", 1);
    return out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, bytes) && out->close();
}

float srgb_decode(int byte) {
    const float e = float(byte) / 255.0f;
    return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

// A 2 x 1 RGBA PNG: texel 0 of alpha 0, texel 1 of alpha 128. Each texel's colour comes back
// as stored (sRGB decoded), not darkened by its alpha; before the fix texel 0 read black.
TEST(TextureAlpha, RgbaColourReadAsStored) {
    test::TempDir dir;
    const std::string png = dir.path("rgba.png");
    const unsigned char bytes[8] = {200, 100, 50, 0, 10, 220, 30, 128};
    {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(png);
        if (!out) GTEST_SKIP() << "this OpenImageIO writes no PNG";
        OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1);  // the bytes as given (no division by alpha)
        ASSERT_TRUE(out->open(png, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, bytes));
        ASSERT_TRUE(out->close());
    }
    const TextureImage t = load_texture(png, TextureSpace::Color, "test");
    ASSERT_EQ(t.format, FC_TEXEL_RGBA8_SRGB);
    const std::vector<cl_float4> got =
        test::texture_lookup(t, {{{0.25f, 0.5f, 0.0f, 0.0f}}, {{0.75f, 0.5f, 0.0f, 0.0f}}});
    for (int texel = 0; texel < 2; ++texel)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[std::size_t(texel)].s[c], srgb_decode(bytes[4 * texel + c]), 1e-5f)
                << "texel " << texel << " channel " << c;
}

// The file's alpha reaches the texels' A (as stored, linear), and has_alpha says it was there;
// a grey image has none (A = 1). Before cut-outs A was always 1.
TEST(TextureAlpha, AlphaChannelKeptInTexels) {
    test::TempDir dir;
    const unsigned char rgba[8] = {200, 100, 50, 0, 10, 220, 30, 128};
    const unsigned char grey[2] = {0, 255};
    if (!write_png(dir.path("rgba.png"), 2, 4, rgba)) GTEST_SKIP() << "this OpenImageIO writes no PNG";
    ASSERT_TRUE(write_png(dir.path("grey.png"), 2, 1, grey));
    const TextureImage t = load_texture(dir.path("rgba.png"), TextureSpace::Color, "test");
    EXPECT_TRUE(t.has_alpha);
    EXPECT_FLOAT_EQ(t.texels[3], 0.0f);
    EXPECT_NEAR(t.texels[7], 128.0f / 255.0f, 1e-6f);
    const TextureImage g = load_texture(dir.path("grey.png"), TextureSpace::Data, "test");
    EXPECT_FALSE(g.has_alpha);
    EXPECT_FLOAT_EQ(g.texels[3], 1.0f);
    EXPECT_FLOAT_EQ(g.texels[4], 1.0f);  // texel 1's grey in R
}

// MTL: d < 1 (or Tr > 0 without d) is BLEND of alpha d; map_d binds an alpha texture, its A
// where the image has alpha, its grey (R) otherwise; glass (illum 7) stays opaque.
TEST(TextureAlpha, MtlDissolveTrAndMapD) {
    test::TempDir dir;
    const unsigned char rgba[8] = {0, 0, 0, 0, 0, 0, 0, 255};
    const unsigned char grey[2] = {0, 255};
    if (!write_png(dir.path("rgba.png"), 2, 4, rgba)) GTEST_SKIP() << "this OpenImageIO writes no PNG";
    ASSERT_TRUE(write_png(dir.path("grey.png"), 2, 1, grey));
    dir.write("m.mtl",
              "newmtl solid\nKd 1 1 1\n"
              "newmtl veil\nd 0.25\n"
              "newmtl tr\nTr 0.25\n"
              "newmtl both\nTr 0.9\nd 0.5\n"
              "newmtl leaf\nmap_d grey.png\n"
              "newmtl decal\nmap_d rgba.png\n"
              "newmtl glass\nillum 7\nd 0.5\n");
    std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    for (const char* m : {"solid", "veil", "tr", "both", "leaf", "decal", "glass"})
        obj += std::string("usemtl ") + m + "\nf 1/1 2/2 3/3\n";
    Scene s;
    load_obj(dir.write("m.obj", obj), s);
    ASSERT_EQ(s.triangle_count(), 7u);
    auto mat = [&](std::size_t t) { return s.materials[std::size_t(s.shading[t].material)]; };
    EXPECT_EQ(mat(0).alpha_mode, FC_ALPHA_OPAQUE);
    EXPECT_EQ(mat(1).alpha_mode, FC_ALPHA_BLEND);
    EXPECT_FLOAT_EQ(mat(1).alpha, 0.25f);
    EXPECT_EQ(mat(2).alpha_mode, FC_ALPHA_BLEND);
    EXPECT_FLOAT_EQ(mat(2).alpha, 0.75f);
    EXPECT_FLOAT_EQ(mat(3).alpha, 0.5f) << "d wins over Tr";
    EXPECT_EQ(mat(4).alpha_mode, FC_ALPHA_BLEND);
    ASSERT_GE(mat(4).textures.alpha, 0);
    EXPECT_EQ(mat(4).textures.alpha_channel, 0) << "a grey map_d is read from R";
    EXPECT_FLOAT_EQ(mat(4).alpha, 1.0f);
    ASSERT_GE(mat(5).textures.alpha, 0);
    EXPECT_EQ(mat(5).textures.alpha_channel, 3) << "an RGBA map_d is read from A";
    EXPECT_EQ(mat(6).alpha_mode, FC_ALPHA_OPAQUE) << "glass refracts instead";
    for (const std::string& w : s.warnings) EXPECT_EQ(w.find("map_d"), std::string::npos) << w;
}

// JSON: "alpha_mode" (opaque, mask, blend), "alpha", "alpha_cutoff" and textures.alpha, and
// errors that name the key's path.
TEST(TextureAlpha, JsonAlphaKeys) {
    test::TempDir dir;
    const unsigned char rgba[8] = {0, 0, 0, 0, 0, 0, 0, 255};
    if (!write_png(dir.path("rgba.png"), 2, 4, rgba)) GTEST_SKIP() << "this OpenImageIO writes no PNG";
    auto quad = [](const char* m) {
        return std::string(R"({"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], )") +
               R"("material": ")" + m + R"("})";
    };
    const Scene s = load_scene(test::scene(
        dir, "a.json",
        R"("materials": {"cut": {"alpha_mode": "mask", "alpha_cutoff": 0.3, "textures": {"alpha": "rgba.png"}},
                         "veil": {"alpha": 0.4}, "red": {"textures": {"alpha": {"file": "rgba.png", "channel": "r"}}}},
           "shapes": [)" +
            quad("cut") + ", " + quad("veil") + ", " + quad("red") + "]"));
    auto mat = [&](std::size_t t) { return s.materials[std::size_t(s.shading[t].material)]; };
    EXPECT_EQ(mat(0).alpha_mode, FC_ALPHA_MASK);
    EXPECT_FLOAT_EQ(mat(0).alpha_cutoff, 0.3f);
    EXPECT_EQ(mat(0).textures.alpha_channel, 3);
    EXPECT_EQ(mat(2).alpha_mode, FC_ALPHA_BLEND);
    EXPECT_FLOAT_EQ(mat(2).alpha, 0.4f);
    EXPECT_EQ(mat(4).alpha_mode, FC_ALPHA_BLEND) << "an alpha texture alone is blend";
    EXPECT_EQ(mat(4).textures.alpha_channel, 0);
    EXPECT_FALSE(test::contains(s.warnings, "spheres do not read")) << "no sphere, no warning";
    const Scene ball = load_scene(test::scene(dir, "ball.json",
                                              R"("materials": {"veil": {"alpha": 0.4}},
           "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "veil"}])"));
    EXPECT_TRUE(test::contains(ball.warnings, "material 'veil' has an alpha mode, which spheres do not read"));
    const struct {
        const char* material;
        const char* path;
    } bad[] = {{R"({"alpha": 1.5})", "materials.m.alpha"},
               {R"({"alpha_mode": "cutout"})", "materials.m.alpha_mode"},
               {R"({"alpha_cutoff": 0.5})", "materials.m.alpha_cutoff"},
               {R"({"textures": {"alpha": {"file": "rgba.png", "channel": "g"}}})", "materials.m.textures.alpha"}};
    int i = 0;
    for (const auto& b : bad) {
        const std::string name = "bad" + std::to_string(i++) + ".json";
        test::expect_error(
            [&] {
                load_scene(test::scene(
                    dir, name,
                    std::string(R"("materials": {"m": )") + b.material + "}, \"shapes\": [" + quad("m") + "]"));
            },
            {name + ": " + b.path});
    }
}

// glTF BLEND with a base colour texture: Debian's assimp-testmodels ClearCoatTest.gltf has one
// (Partial_Coating, whose PartialCoating_Alpha.png is the coverage): the texture is bound as the
// alpha texture, read from A, and its alpha reaches the texels.
TEST(TextureAlpha, GltfBlendReadsTheBaseColourAlpha) {
    const std::string file = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is missing (Debian's assimp-testmodels)";
    const Scene s = load_scene(file);
    for (const std::string& w : s.warnings) EXPECT_EQ(w.find("alphaMode"), std::string::npos) << w;
    int blend = 0;
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        if (m.alpha_mode == FC_ALPHA_OPAQUE) continue;
        ++blend;
        EXPECT_EQ(s.material_names[i], "Partial_Coating");
        EXPECT_EQ(m.alpha_mode, FC_ALPHA_BLEND);
        ASSERT_GE(m.textures.alpha, 0);
        EXPECT_EQ(m.textures.alpha, m.textures.base_color);
        EXPECT_EQ(m.textures.alpha_channel, 3);
        const TextureImage& t = s.textures[std::size_t(m.textures.alpha)];
        float lo = 1.0f, hi = 0.0f;
        for (std::size_t k = 0; k < std::size_t(t.width) * std::size_t(t.height); ++k)
            lo = std::min(lo, t.texels[4 * k + 3]), hi = std::max(hi, t.texels[4 * k + 3]);
        EXPECT_LT(lo, 0.5f) << t.path << ": some texels are cut away";
        EXPECT_GT(hi, 0.5f) << t.path;
    }
    EXPECT_EQ(blend, 1);
}

}  // namespace
}  // namespace facet
