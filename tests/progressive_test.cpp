// The progressive schedule's rules (render/schedule.hpp) without a device, the driver
// (render/progressive.hpp) on a fake target that sleeps in place of a kernel, and the
// driver on the real renderer (PoCL).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/render/schedule.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

ScheduleState state(std::uint64_t target, std::uint64_t done, double render_s, std::uint32_t last) {
    ScheduleState s;
    s.target_spp = target;
    s.done_spp = done;
    s.render_s = render_s;
    s.last_pass = last;
    return s;
}

TEST(Progressive, FirstPassIsOneSample) {
    EXPECT_EQ(next_pass_samples(state(1000, 0, 0.0, 0)), 1u);
    ScheduleState s = state(1000, 0, 0.0, 0);
    s.time_limit_s = 0.0;  // even with no time at all, one sample per pixel
    EXPECT_EQ(next_pass_samples(s), 1u);
}

TEST(Progressive, PassIsATenthOfTheTimeSoFar) {
    // 100 spp/s after 10 s: a pass of 1 s is 100 samples.
    EXPECT_EQ(next_pass_samples(state(1u << 20, 1000, 10.0, 100)), 100u);
}

TEST(Progressive, PassAtMostDoubles) {
    EXPECT_EQ(next_pass_samples(state(1u << 20, 1000, 10.0, 30)), 60u);
    EXPECT_EQ(next_pass_samples(state(1u << 20, 1, 0.001, 1)), 2u);
}

TEST(Progressive, PassClampedTo50msAnd2s) {
    // 100 spp/s: a tenth of 0.01 s is below 50 ms (5 samples); a tenth of 100 s is above 2 s (200).
    EXPECT_EQ(next_pass_samples(state(1u << 20, 1, 0.01, 1000)), 5u);
    EXPECT_EQ(next_pass_samples(state(1u << 20, 10000, 100.0, 1000)), 200u);
    // Slower than one sample per pixel in 50 ms: still one sample.
    EXPECT_EQ(next_pass_samples(state(1u << 20, 1, 10.0, 1)), 1u);
}

TEST(Progressive, PassLongEnoughToHideTheHostsWork) {
    // 100 spp/s after 1 s: a tenth would be 10 samples; 21.1 ms of host work between passes
    // asks for at least 0.0211 * 0.95 / 0.05 = 0.4009 s, 40 samples.
    ScheduleState s = state(1u << 20, 100, 1.0, 100);
    EXPECT_EQ(next_pass_samples(s), 10u);
    s.host_s = 0.0211;
    EXPECT_EQ(next_pass_samples(s), 40u);
    // Still at most twice the last pass, and within max_pass_s (2 s: 200 samples).
    s.last_pass = 10;
    EXPECT_EQ(next_pass_samples(s), 20u);
    s.last_pass = 1000;
    s.host_s = 1.0;
    EXPECT_EQ(next_pass_samples(s), 200u);
    // A share of 1 leaves the rule out.
    ScheduleRules rules;
    rules.max_host_share = 1.0;
    EXPECT_EQ(next_pass_samples(s, rules), 10u);
}

TEST(Progressive, PassCutToTheTarget) {
    EXPECT_EQ(next_pass_samples(state(1030, 1000, 10.0, 100)), 30u);
    EXPECT_EQ(next_pass_samples(state(1000, 1000, 10.0, 100)), 0u);
    EXPECT_TRUE(schedule_done(state(1000, 1000, 10.0, 100)));
}

TEST(Progressive, PassCutToTheTimeLeft) {
    ScheduleState s = state(1u << 20, 1000, 10.0, 100);
    s.time_limit_s = 10.5;  // 0.5 s left at 100 spp/s
    EXPECT_EQ(next_pass_samples(s), 50u);
    s.time_limit_s = 10.001;  // less than one sample's time left: still one
    EXPECT_EQ(next_pass_samples(s), 1u);
    s.time_limit_s = 10.0;
    EXPECT_TRUE(schedule_done(s));
    EXPECT_EQ(next_pass_samples(s), 0u);
    EXPECT_DOUBLE_EQ(schedule_remaining_s(s), 0.0);
}

TEST(Progressive, RemainingTime) {
    ScheduleState s = state(2000, 1000, 10.0, 100);
    EXPECT_DOUBLE_EQ(schedule_remaining_s(s), 10.0);
    s.time_limit_s = 14.0;
    EXPECT_DOUBLE_EQ(schedule_remaining_s(s), 4.0);
    EXPECT_FALSE(std::isfinite(schedule_remaining_s(state(10, 0, 0.0, 0))));
}

TEST(Progressive, RowsPerLaunchFromSpeed) {
    // 1 ms for one sample over a row: 4 samples are 4 ms a row, 62 rows in 0.25 s.
    std::vector<double> cost(1000, 1e-3);
    EXPECT_EQ(rows_per_launch(cost, 0, 1000, 4, 1), 62u);
    EXPECT_EQ(rows_per_launch(cost, 980, 1000, 4, 1), 20u);  // the rows left
    std::vector<double> slow(1000, 1.0);                     // a row is too long: one row
    EXPECT_EQ(rows_per_launch(slow, 0, 1000, 4, 100), 1u);
    ScheduleRules rules;
    rules.max_launch_s = 0.025;
    EXPECT_EQ(rows_per_launch(cost, 0, 1000, 4, 1, rules), 6u);
    EXPECT_EQ(rows_per_launch(std::vector<double>(50, 1e-3), 0, 1000, 4, 1), 50u);  // the whole image fits
}

TEST(Progressive, RowsPerLaunchFollowTheDearRows) {
    // Cheap rows then dear ones: a launch stops where the measured cost fills it.
    std::vector<double> cost(200, 1e-4);
    for (std::size_t r = 100; r < 200; ++r) cost[r] = 1e-2;
    EXPECT_EQ(rows_per_launch(cost, 90, 1000, 1, 1), 10u + 24u);  // 10 rows of 0.1 ms, 24 of 10 ms
}

TEST(Progressive, FirstLaunchIsAProbeBand) {
    // Nothing measured yet: about 4096 pixels, at least one row, at most the image.
    EXPECT_EQ(rows_per_launch(std::vector<double>(1000, 0.0), 0, 64, 1, 0), 64u);
    EXPECT_EQ(rows_per_launch(std::vector<double>(2048, 0.0), 0, 2048, 1, 0), 2u);
    EXPECT_EQ(rows_per_launch(std::vector<double>(10, 0.0), 0, 100000, 1, 0), 1u);
    EXPECT_EQ(rows_per_launch(std::vector<double>(16, 0.0), 0, 16, 1, 0), 16u);
}

TEST(Progressive, LaunchesIntoUnmeasuredRowsGrowAtMostTwofold) {
    // The probe's rows were nearly free (sky, say): the rows below may not be.
    std::vector<double> cost(2048, 0.0);
    cost[0] = cost[1] = 1e-9;
    EXPECT_EQ(rows_per_launch(cost, 2, 2048, 1, 2), 4u);
    // Measured rows ahead are taken by their cost, without the growth cap.
    std::fill(cost.begin(), cost.end(), 1e-9);
    EXPECT_EQ(rows_per_launch(cost, 2, 2048, 1, 2), 2046u);
}

// A target whose launches sleep `us_per_sample` microseconds per pixel-sample, and
// which records the rows each pass covered.
class FakeTarget : public PassTarget {
public:
    FakeTarget(std::uint32_t w, std::uint32_t h, double us_per_sample, std::uint32_t free_rows = 0)
        : w_(w), h_(h), us_(us_per_sample), free_rows_(free_rows) {}
    std::uint32_t target_width() const override { return w_; }
    std::uint32_t target_height() const override { return h_; }
    std::uint64_t finished_spp() const override { return spp_; }
    void launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) override {
        if (rows_.empty()) rows_.assign(h_, 0);
        for (std::uint32_t r = row_begin; r < row_begin + row_count; ++r) rows_[r] += count;
        ++launches;
        const std::uint32_t dear =
            row_begin + row_count - std::max(row_begin, std::min(free_rows_, row_begin + row_count));
        std::this_thread::sleep_for(std::chrono::duration<double, std::micro>(us_ * w_ * dear * count));
    }
    void end_pass(std::uint32_t count, double) override {
        for (std::uint32_t r : rows_) EXPECT_EQ(r, spp_ + count) << "every row once per pass";
        spp_ += count;
        ++passes;
    }
    void reset() override {
        spp_ = 0;
        rows_.assign(h_, 0);
        ++resets;
    }
    int launches = 0, passes = 0, resets = 0;

private:
    std::uint32_t w_, h_;
    double us_;
    std::uint32_t free_rows_;  // the top rows cost nothing (sky)
    std::uint64_t spp_ = 0;
    std::vector<std::uint64_t> rows_;
};

TEST(Progressive, FixedPassesReachTheTargetExactly) {
    FakeTarget t(32, 16, 0.0);
    ProgressiveResult r = render_fixed(t, 10, 4);
    EXPECT_EQ(r.spp, 10u);
    EXPECT_EQ(t.passes, 3);  // 4 + 4 + 2
    EXPECT_FALSE(r.stopped);
}

TEST(Progressive, CallbackAfterEveryPass) {
    FakeTarget t(32, 16, 0.0);
    ProgressiveOptions opt;
    opt.target_spp = 40;
    std::vector<PassDone> seen;
    opt.on_pass = [&](const PassDone& d) { seen.push_back(d); };
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_EQ(r.spp, 40u);
    ASSERT_EQ(int(seen.size()), r.passes);
    EXPECT_EQ(seen.front().samples, 1u);
    EXPECT_EQ(seen.back().spp, 40u);
    EXPECT_TRUE(seen.back().last);
    for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
        EXPECT_FALSE(seen[i].last);
        EXPECT_LE(seen[i + 1].samples, 2 * seen[i].samples) << "at most doubling";
    }
}

TEST(Progressive, EveryLaunchBoundedFromTheFirst) {
    // 256x256 at 1 us a sample: one sample per pixel is 65 ms, in launches of <= 10 ms.
    FakeTarget t(256, 256, 1.0);
    ProgressiveOptions opt;
    opt.target_spp = 2;
    opt.rules.max_launch_s = 0.01;
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_EQ(r.spp, 2u);
    EXPECT_GT(r.launches, 6);
    EXPECT_LT(r.longest_launch_s, 0.05) << "sleeps overrun on a loaded machine, not 6x";
}

TEST(Progressive, CheapProbeRowsDoNotMakeALongLaunch) {
    // The top 32 rows are free, the 480 below take 123 ms a sample per pixel: sized from
    // the probe alone, the second launch would take all of it.
    FakeTarget t(256, 512, 1.0, 32);
    ProgressiveOptions opt;
    opt.target_spp = 1;
    opt.rules.max_launch_s = 0.005;
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_EQ(r.spp, 1u);
    EXPECT_LT(r.longest_launch_s, 0.05);
}

TEST(Progressive, StopDuringTheFirstPassDropsIt) {
    FakeTarget t(256, 256, 1.0);
    ProgressiveOptions opt;
    opt.target_spp = 100;
    opt.rules.max_launch_s = 0.005;
    opt.stop = [&] { return t.launches >= 2; };
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.spp, 0u);
    EXPECT_EQ(r.launches, 2);
    EXPECT_EQ(t.resets, 1);
}

TEST(Progressive, StopLaterFinishesThePass) {
    FakeTarget t(64, 64, 0.0);
    ProgressiveOptions opt;
    opt.target_spp = 1000;
    opt.fixed_pass = 3;
    opt.stop = [&] { return t.passes >= 2; };
    bool last_seen = false;
    opt.on_pass = [&](const PassDone& d) { last_seen = d.last; };
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.spp, 6u);
    EXPECT_TRUE(last_seen);
    EXPECT_EQ(t.resets, 0);
}

TEST(Progressive, TimeLimitEndsTheRender) {
    FakeTarget t(64, 64, 1.0);  // 4 ms a sample per pixel
    ProgressiveOptions opt;
    opt.target_spp = 1u << 20;
    opt.time_limit_s = 0.2;
    auto start = std::chrono::steady_clock::now();
    ProgressiveResult r = render_progressive(t, opt);
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GE(r.render_s, 0.2);
    EXPECT_LT(wall, 1.0) << "the passes near the end are cut to the time left";
    EXPECT_GT(r.spp, 1u);
}

// A first launch slower than the rest (a driver compiling the kernel on first use) must
// not make a first pass that fits the time limit look longer than it: the warning is
// given only once the pass has, as measured, taken longer than the limit.
class SlowFirstLaunch : public FakeTarget {
public:
    using FakeTarget::FakeTarget;
    void launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) override {
        if (launches == 0) std::this_thread::sleep_for(std::chrono::milliseconds(60));
        FakeTarget::launch(count, row_begin, row_count);
    }
};

TEST(Progressive, FirstPassWithinTheTimeLimitIsNotWarned) {
    // The probe launch takes 60 ms; the whole pass ~60 ms; the limit 0.5 s. Extrapolated
    // from the probe band (16 of 256 rows) it would look like ~1 s.
    SlowFirstLaunch t(256, 256, 0.0);
    ProgressiveOptions opt;
    opt.target_spp = 1;
    opt.time_limit_s = 0.5;
    int warned = 0;
    opt.on_first_pass_estimate = [&](double) { ++warned; };
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_EQ(r.spp, 1u);
    EXPECT_LT(r.render_s, 0.5) << "a loaded machine: the premise failed";
    EXPECT_EQ(warned, 0);
}

TEST(Progressive, FirstPassLongerThanTheTimeLimitIsWarnedDuringIt) {
    // 256x256 at 1 us a sample: one sample per pixel is 65 ms, the limit 20 ms.
    FakeTarget t(256, 256, 1.0);
    ProgressiveOptions opt;
    opt.target_spp = 100;
    opt.time_limit_s = 0.02;
    opt.rules.max_launch_s = 0.005;
    int warned = 0, passes_when_warned = -1;
    double estimate = 0.0;
    opt.on_first_pass_estimate = [&](double s) {
        ++warned;
        passes_when_warned = t.passes;
        estimate = s;
    };
    ProgressiveResult r = render_progressive(t, opt);
    EXPECT_EQ(r.spp, 1u) << "the time limit ends the render after the first pass";
    EXPECT_EQ(warned, 1);
    EXPECT_EQ(passes_when_warned, 0) << "told during the pass, not after it";
    EXPECT_GT(estimate, 0.02);
}

// On PoCL: a pass in launches of one row gives the same image, bit for bit, as one launch.
TEST(Progressive, DriverBandsMatchOneLaunchOnTheDevice) {
    Scene scene;
    Material m = default_material();
    m.diffuse = glm::vec3(0.5f);
    m.emission = glm::vec3(1.0f);
    scene.materials.push_back(m);
    scene.material_names.push_back("furnace");
    add_sphere(scene, glm::vec3(0.0f), 1.0f, 3, 0, /*inward=*/true);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fov_y_degrees = 90.0f;
    scene.settings.width = 24;
    scene.settings.height = 16;
    scene.settings.max_depth = 8;
    Bvh bvh = build_bvh(scene.vertices);

    Renderer one(test::context(), scene, bvh);
    one.render(6);  // the renderer's own single launch
    Renderer banded(test::context(), scene, bvh);
    ProgressiveOptions opt;
    opt.target_spp = 6;
    opt.fixed_pass = 6;
    opt.rules.max_launch_s = 1e-9;  // one row a launch
    opt.rules.probe_pixels = 1;
    int passes = 0;
    opt.on_pass = [&](const PassDone&) { ++passes; };
    ProgressiveResult r = render_progressive(banded, opt);
    EXPECT_EQ(r.spp, 6u);
    EXPECT_EQ(banded.stats().samples_per_pixel, 6u);
    EXPECT_EQ(passes, r.passes);
    EXPECT_EQ(r.launches, 16);
    EXPECT_EQ(one.image(), banded.image());
}

}  // namespace
}  // namespace facet
