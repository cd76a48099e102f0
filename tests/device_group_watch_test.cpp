// render/device_group_watch.hpp: when the job is ending under rank 0 (mpirun's SIGTERM
// after a rank died) and the main thread is stuck, the watch saves the film as of the
// last pass end and ends the process with the status its save returns; a main thread
// that reaches its final writes first makes it stand down. Death tests: the watch ends
// the process.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "host/bvh/bvh.hpp"
#include "host/render/device_group.hpp"
#include "host/render/device_group_watch.hpp"
#include "host/render/progressive.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/lit_scene.hpp"

namespace facet {
namespace {

// A group that has finished one pass of `spp` samples, and a watch that sees a SIGTERM;
// the main thread then stands down after `stuck_s` seconds (it was stuck until then).
void watch_a_stuck_render(std::uint32_t spp, double stuck_s) {
    const Scene scene = test::lit_scene(8);
    const Bvh bvh = build_bvh(scene.vertices);
    const char* sel = std::getenv("FACET_TEST_DEVICE");
    std::vector<ClContext> contexts;
    contexts.push_back(ClContext::create(sel ? sel : ""));
    DeviceGroup group(std::move(contexts), scene, bvh);
    render_fixed(group, spp, spp);
    DeviceGroupWatch watch(
        group, [] { return SIGTERM; },
        [&](const DeviceGroupWatch::Lost& lost) {
            std::fprintf(stderr, "saved %llu spp, samples %s, waiting %d: %s\n",
                         static_cast<unsigned long long>(group.stats().samples_per_pixel),
                         describe(group.samples()).c_str(), int(lost.waiting), lost.why.c_str());
            return kExitRankLost;
        });
    std::this_thread::sleep_for(std::chrono::duration<double>(stuck_s));
    watch.stand_down();
    std::this_thread::sleep_for(std::chrono::duration<double>(0.5));
    std::exit(0);
}

TEST(DeviceGroupWatch, SavesTheLastPassWhenTheMainThreadIsStuck) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(watch_a_stuck_render(3, 30.0), testing::ExitedWithCode(kExitRankLost),
                "saved 3 spp, samples 0-2, waiting 0: the job is ending \\(signal 15");
}

TEST(DeviceGroupWatch, StandsDownWhenTheMainThreadWritesInTime) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(watch_a_stuck_render(2, 0.0), testing::ExitedWithCode(0), "^$");
}

}  // namespace
}  // namespace facet
