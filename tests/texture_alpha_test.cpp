// TextureAlpha.*: the colour of an RGBA image is read as stored, whatever its alpha
// (glTF's OPAQUE ignores alpha; OpenImageIO would otherwise multiply it in on read),
// through load_texture and the kernels' texture lookup.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"
#include "tests/texture_test_util.hpp"

namespace facet {
namespace {

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

}  // namespace
}  // namespace facet
