// The render session (render/session.hpp): its stop rules without a device
// (render/session_rules.hpp: --spp, --time and the noise threshold, whichever ends
// first), and a session on PoCL: --time alone renders past the scene's spp, a fixed spp
// renders exactly those samples (the warm-up launch leaves none behind).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>

#include "host/readers/load_scene.hpp"
#include "host/render/session.hpp"
#include "host/render/session_rules.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

StopRequest request(std::optional<std::uint64_t> spp, std::optional<double> time_s) {
    StopRequest r;
    r.spp = spp;
    r.scene_spp = 64;
    r.time_limit_s = time_s;
    return r;
}

TEST(RenderSession, SppAloneIsTheTarget) {
    const StopRules rules = resolve_stop_rules(request(256, std::nullopt));
    EXPECT_EQ(rules.spp, 256u);
    EXPECT_TRUE(rules.spp_bounded);
    EXPECT_FALSE(rules.time_limit_s);
    EXPECT_EQ(rules.shown_spp(), 256u);
}

TEST(RenderSession, NeitherTakesTheScenesSpp) {
    const StopRules rules = resolve_stop_rules(request(std::nullopt, std::nullopt));
    EXPECT_EQ(rules.spp, 64u);
    EXPECT_TRUE(rules.spp_bounded);
}

TEST(RenderSession, TimeAloneIsTheStopOverTheScenesSpp) {
    const StopRules rules = resolve_stop_rules(request(std::nullopt, 20.0));
    EXPECT_FALSE(rules.spp_bounded);
    EXPECT_EQ(rules.spp, kUnboundedSpp);
    EXPECT_EQ(rules.shown_spp(), 0u) << "the progress line shows no spp target";
    EXPECT_EQ(*rules.time_limit_s, 20.0);
    EXPECT_LT(rules.spp, std::uint64_t{1} << 32) << "sample indices stay below 2^32";
}

TEST(RenderSession, SppAndTimeWhicheverEndsFirst) {
    const StopRules rules = resolve_stop_rules(request(16, 20.0));
    EXPECT_EQ(rules.spp, 16u);
    EXPECT_TRUE(rules.spp_bounded);
    EXPECT_EQ(*rules.time_limit_s, 20.0);
}

TEST(RenderSession, ConvergedFromTheMinimumSppOn) {
    StopRequest r = request(1024, std::nullopt);
    EXPECT_FALSE(resolve_stop_rules(r).converged(64, 0.0)) << "no threshold, never converged";
    r.noise_threshold = 0.01;
    const StopRules rules = resolve_stop_rules(r);
    EXPECT_FALSE(rules.converged(kMinAdaptiveSpp - 1, 0.001)) << "too few samples to judge";
    EXPECT_TRUE(rules.converged(kMinAdaptiveSpp, 0.01));
    EXPECT_FALSE(rules.converged(512, 0.011));
}

TEST(RenderSession, TileModeRendersTheMinimumUniformlyFirst) {
    StopRequest r = request(1024, std::nullopt);
    r.noise_threshold = 0.01;
    EXPECT_EQ(resolve_stop_rules(r).uniform_spp(), 1024u);
    r.adaptive = AdaptiveMode::tiles;
    EXPECT_EQ(resolve_stop_rules(r).uniform_spp(), kMinAdaptiveSpp);
    r.spp = 8;
    EXPECT_EQ(resolve_stop_rules(r).uniform_spp(), 8u);
}

SessionOptions on_test_device() {
    SessionOptions opt;
    if (const char* device = std::getenv("FACET_TEST_DEVICE")) opt.device = device;
    return opt;
}

Scene small_cornell() {
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    scene.settings.width = scene.settings.height = 16;
    scene.settings.spp = 4;  // as a scene file's render.spp
    return scene;
}

TEST(RenderSession, FixedSppRendersExactlyThoseSamples) {
    const Scene scene = small_cornell();
    SessionOptions opt = on_test_device();
    opt.stop.spp = 6;
    RenderSession session(scene, opt);
    int passes = 0;
    SessionHooks hooks;
    hooks.on_pass = [&](const SessionPass& p) {
        ++passes;
        EXPECT_EQ(p.target_spp, 6u);
    };
    const SessionOutcome out = session.run(hooks);
    EXPECT_EQ(out.spp, 6u);
    EXPECT_EQ(out.passes, passes);
    EXPECT_FALSE(out.interrupted);
    EXPECT_FALSE(out.tiles);
    // Samples 0-5, each once: the warm-up launch's sample was dropped.
    EXPECT_EQ(describe(session.group().samples()), "0-5");
    EXPECT_EQ(session.film().spp, 6u);
}

TEST(RenderSession, TimeAloneRendersPastTheScenesSpp) {
    const Scene scene = small_cornell();
    SessionOptions opt = on_test_device();
    opt.stop.time_limit_s = 0.5;
    RenderSession session(scene, opt);
    const auto start = std::chrono::steady_clock::now();
    const SessionOutcome out = session.run({});
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GT(out.spp, 4u) << "the scene's spp does not stop a render given --time alone";
    EXPECT_GE(session.group().stats().render_seconds, 0.5);
    EXPECT_LT(wall, 5.0);
}

}  // namespace
}  // namespace facet
