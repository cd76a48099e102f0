// The render settings' names (host/scene/render_names.hpp), generated from
// kernels/shared/render_layout.h's lists: each name maps to its constant and back.
#include <gtest/gtest.h>

#include "host/scene/render_names.hpp"

namespace facet {
namespace {

TEST(RenderNames, StrategiesAndSamplersRoundTrip) {
    EXPECT_EQ(setting_value(kStrategyNames, "mis"), FC_STRATEGY_MIS);
    EXPECT_EQ(setting_value(kStrategyNames, "light"), FC_STRATEGY_LIGHT);
    EXPECT_EQ(setting_value(kStrategyNames, "bsdf"), FC_STRATEGY_BSDF);
    EXPECT_EQ(setting_value(kSamplerNames, "sobol"), FC_SAMPLER_SOBOL);
    EXPECT_EQ(setting_value(kSamplerNames, "independent"), FC_SAMPLER_INDEPENDENT);
    EXPECT_FALSE(setting_value(kSamplerNames, "halton"));
    EXPECT_EQ(setting_name(kStrategyNames, FC_STRATEGY_BSDF), "bsdf");
    EXPECT_EQ(setting_name(kSamplerNames, 7), "7");
    EXPECT_EQ(setting_name_list(kStrategyNames), "mis, light or bsdf");
    EXPECT_EQ(setting_map(kSamplerNames).size(), std::size_t(FC_SAMPLER_COUNT));
    // The values film files store.
    EXPECT_EQ(FC_STRATEGY_MIS, 0);
    EXPECT_EQ(FC_SAMPLER_INDEPENDENT, 0);
    EXPECT_EQ(FC_SAMPLER_SOBOL, 1);
}

}  // namespace
}  // namespace facet
