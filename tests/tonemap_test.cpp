// image/tonemap.hpp: the clip is the sRGB transfer function below 1; the filmic curve keeps
// mid grey and its contrast, is monotone, and rolls highlights off below 1 instead of
// clipping them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "host/image/tonemap.hpp"

namespace facet {
namespace {

TEST(Tonemap, ClipIsSrgbBelowOne) {
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Clip, 0.0f), 0.0f);
    EXPECT_NEAR(tonemap_display(ToneMap::Clip, 0.18f), 0.4614f, 1e-4f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Clip, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Clip, 8.0f), 1.0f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Clip, -1.0f), 0.0f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Clip, std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(Tonemap, FilmicKeepsMidGreyAndRollsOffHighlights) {
    EXPECT_NEAR(tonemap_display(ToneMap::Filmic, 0.18f), 0.461f, 1e-3f);
    // The same contrast at mid grey as the clip: display units per stop.
    auto slope = [](ToneMap m) {
        return (tonemap_display(m, 0.18f * std::exp2(0.05f)) - tonemap_display(m, 0.18f * std::exp2(-0.05f))) / 0.1f;
    };
    EXPECT_NEAR(slope(ToneMap::Filmic), slope(ToneMap::Clip), 0.01f);
    float last = 0.0f;
    for (float stops = -12.0f; stops <= 12.0f; stops += 0.25f) {
        const float v = tonemap_display(ToneMap::Filmic, 0.18f * std::exp2(stops));
        EXPECT_GT(v, last) << stops;
        EXPECT_LT(v, 1.0f) << stops;
        last = v;
    }
    // Where the clip is already white (2.5 stops above mid grey) the filmic curve still
    // separates the next stops.
    EXPECT_LT(tonemap_display(ToneMap::Filmic, 1.0f), 0.85f);
    EXPECT_GT(tonemap_display(ToneMap::Filmic, 16.0f) - tonemap_display(ToneMap::Filmic, 4.0f), 0.05f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Filmic, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(tonemap_display(ToneMap::Filmic, std::numeric_limits<float>::infinity()), 1.0f);
}

TEST(Tonemap, Names) {
    EXPECT_EQ(tonemap_from_name("filmic"), ToneMap::Filmic);
    EXPECT_EQ(tonemap_from_name("clip"), ToneMap::Clip);
    EXPECT_FALSE(tonemap_from_name("aces"));
    EXPECT_STREQ(tonemap_name(ToneMap::Filmic), "filmic");
}

}  // namespace
}  // namespace facet
