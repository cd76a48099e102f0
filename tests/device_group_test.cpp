// render/device_group.hpp: several devices (here: two contexts on the test device, as
// CI has one OpenCL device) render the image of one device, up to the order of the float
// sums; shares follow the measured speeds; a failing device is dropped and its samples
// rendered by the others; resume and --samples-from continue at the right indices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "host/bvh/bvh.hpp"
#include "host/film/error_metrics.hpp"
#include "host/render/device_group.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/lit_scene.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

std::vector<ClContext> contexts(int n) {
    const char* sel = std::getenv("FACET_TEST_DEVICE");
    std::vector<ClContext> out;
    for (int i = 0; i < n; ++i) out.push_back(ClContext::create(sel ? sel : ""));
    return out;
}

void expect_same_image(const std::vector<float>& got, const std::vector<float>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got[i], want[i], 1e-5f * std::max(1.0f, want[i])) << i;
}

struct Fixture {
    Scene scene = test::lit_scene(16);
    Bvh bvh = build_bvh(scene.vertices);
    std::vector<float> one_device(std::uint64_t spp) {
        Renderer r(test::context(), scene, bvh);
        r.render(std::uint32_t(spp));
        return r.image();
    }
};

TEST(DeviceGroup, TwoDevicesRenderTheImageOfOne) {
    Fixture f;
    const std::vector<float> want = f.one_device(12);
    DeviceGroup group(contexts(2), f.scene, f.bvh);
    ASSERT_EQ(group.devices().size(), 2u);
    render_fixed(group, 12, 4);
    EXPECT_EQ(group.stats().samples_per_pixel, 12u);
    EXPECT_EQ(group.samples(), (SampleRanges{{0, 12}}));
    expect_same_image(group.image(), want);
    for (const DeviceShare& d : group.devices()) {
        EXPECT_GT(d.pixel_samples, 0u) << "both devices take a share of a 4-sample pass";
        EXPECT_GT(d.samples_per_s(), 0.0);
    }
    EXPECT_EQ(group.devices()[0].pixel_samples + group.devices()[1].pixel_samples, 12u * 256u);
    const FilmHalves h = group.halves();
    EXPECT_EQ(h.samples[0], 6u);
    EXPECT_EQ(h.samples[1], 6u);
}

// The progressive render's estimate after each pass (DeviceGroup::estimate, which streams
// over the devices' films instead of building the halves) is the halves' estimate bit for
// bit: two devices, then on a restored film, then with a device dropped.
TEST(DeviceGroup, EstimateIsTheEstimateOfItsHalves) {
    Fixture f;
    auto expect_same_estimate = [](const DeviceGroup& g) {
        const FilmHalves h = g.halves();
        const ErrorMetrics want = estimate_error(h.rgb[0], h.rgb[1], h.samples[0], h.samples[1]);
        const ErrorMetrics got = g.estimate();
        EXPECT_TRUE(std::isfinite(want.mse) && want.mse > 0.0) << want.mse;
        EXPECT_EQ(got.mse, want.mse);
        EXPECT_EQ(got.rmse, want.rmse);
        EXPECT_EQ(got.relmse, want.relmse);
    };
    DeviceGroup group(contexts(2), f.scene, f.bvh);
    render_fixed(group, 6, 3);
    expect_same_estimate(group);
    DeviceGroup resumed(contexts(2), f.scene, f.bvh);
    resumed.restore(group.accumulation(), group.samples(), 1.0);
    render_fixed(resumed, 5, 5);
    expect_same_estimate(resumed);
    int launches = 0;
    resumed.before_launch = [&](std::size_t device) {
        if (device == 1 && ++launches == 2) throw std::runtime_error("CL_OUT_OF_RESOURCES (injected)");
    };
    // Passes of 4 samples, dealt by the devices' measured rates: device 1 gets none of a pass
    // only if it ran below a seventh of device 0's rate (with passes of 2, a third: under a
    // loaded machine it could miss its second launch and never be dropped).
    render_fixed(resumed, 12, 4);
    EXPECT_TRUE(resumed.devices()[1].dropped);
    expect_same_estimate(resumed);
}

TEST(DeviceGroup, FailingDeviceIsDroppedAndItsSamplesRenderedByTheOthers) {
    Fixture f;
    const std::vector<float> want = f.one_device(12);
    std::vector<std::string> warnings;
    DeviceGroup group(contexts(2), f.scene, f.bvh, false, 0, [&](const std::string& w) { warnings.push_back(w); });
    int launches = 0;
    // Device 1 fails in the second pass, after device 0 has launched its share of it.
    group.before_launch = [&](std::size_t device) {
        if (device == 1 && ++launches == 2) throw std::runtime_error("CL_OUT_OF_RESOURCES (injected)");
    };
    render_fixed(group, 12, 4);
    EXPECT_EQ(group.stats().samples_per_pixel, 12u);
    expect_same_image(group.image(), want);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("dropped"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("injected"), std::string::npos) << warnings[0];
    EXPECT_TRUE(group.devices()[1].dropped);
    EXPECT_FALSE(group.devices()[0].dropped);
}

TEST(DeviceGroup, EveryDeviceFailingIsAnError) {
    Fixture f;
    DeviceGroup group(contexts(2), f.scene, f.bvh, false, 0, [](const std::string&) {});
    group.before_launch = [](std::size_t) { throw Error("injected failure"); };
    EXPECT_NE(test::error_of([&] { render_fixed(group, 4, 4); }).find("every OpenCL device failed"), std::string::npos);
}

TEST(DeviceGroup, ResumeAndSamplesFromContinueAtTheirIndices) {
    Fixture f;
    const std::vector<float> want = f.one_device(10);
    DeviceGroup first(contexts(1), f.scene, f.bvh);
    render_fixed(first, 4, 2);
    // Resumed on two devices: samples 4..9.
    DeviceGroup second(contexts(2), f.scene, f.bvh);
    second.restore(first.accumulation(), first.samples(), first.stats().render_seconds);
    EXPECT_EQ(second.finished_spp(), 4u);
    render_fixed(second, 6, 3);
    EXPECT_EQ(second.samples(), (SampleRanges{{0, 10}}));
    expect_same_image(second.image(), want);
    // Samples from 4 on, alone: the other part of the same image.
    DeviceGroup rest(contexts(1), f.scene, f.bvh, false, 4);
    render_fixed(rest, 6, 6);
    EXPECT_EQ(rest.samples(), (SampleRanges{{4, 10}}));
    std::vector<float> sums = first.accumulation();
    const std::vector<float> more = rest.accumulation();
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i] += more[i];
    expect_same_image(film_mean(film_halves(sums, 256, {{0, 10}}, true)), want);
    // Samples from 2 would repeat the film's 2 and 3.
    DeviceGroup overlapping(contexts(1), f.scene, f.bvh, false, 2);
    EXPECT_NE(
        test::error_of([&] { overlapping.restore(first.accumulation(), first.samples(), 0.0); }).find("would repeat"),
        std::string::npos);
}

TEST(DeviceGroup, DeviceListsSelectContexts) {
    EXPECT_EQ(ClContext::create_many("0,0").size(), 2u);
    EXPECT_GE(ClContext::create_many("all").size(), 1u);
    EXPECT_NE(test::error_of([] { ClContext::create_many("0,99"); }).find("no device with that index"),
              std::string::npos);
    EXPECT_NE(test::error_of([] { ClContext::create_many("0,"); }).find("empty entry"), std::string::npos);
}

}  // namespace
}  // namespace facet
