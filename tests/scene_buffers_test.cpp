// SceneBuffers.*: the device memory check counts every array of kernels/shared/scene_arrays.h
// (host/render/scene_buffers.hpp).
#include <gtest/gtest.h>

#include <string>

#include "host/bvh/bvh.hpp"
#include "host/render/scene_buffers.hpp"
#include "tests/lit_scene.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

TEST(SceneBuffers, MemoryCheckCoversEveryArrayOfTheList) {
    const Scene s = test::lit_scene(4);
    const Bvh bvh = build_bvh(s.vertices);
    const DeviceScene dev = compile(s, bvh);
    const std::vector<BufferNeed> needs = scene_buffer_needs(dev, 1000);
    const char* whats[] = {
#define FC_WHAT(device_type, host_type, name, what, kind) what,
        FC_SCENE_ARRAYS(FC_WHAT)
#undef FC_WHAT
    };
    ASSERT_EQ(needs.size(), kSceneArrayCount + 1);
    std::size_t total = 0;
    for (std::size_t i = 0; i < kSceneArrayCount; ++i) {
        EXPECT_EQ(needs[i].what, whats[i]);
        EXPECT_EQ(needs[i].bytes, dev.arrays()[i].bytes.size()) << whats[i];
        total += needs[i].bytes;
    }
    EXPECT_EQ(total, dev.bytes());
    EXPECT_EQ(needs.back().what, "image");
    EXPECT_EQ(needs.back().bytes, 1000u);
}

TEST(SceneBuffers, MemoryCheckNamesTheArrayTooLarge) {
    // Each array of the list, in turn the one too large for one allocation.
    for (std::size_t i = 0; i < kSceneArrayCount; ++i) {
        std::vector<BufferNeed> needs(kSceneArrayCount + 1);
        for (std::size_t k = 0; k < needs.size(); ++k) needs[k] = {"array " + std::to_string(k), 16};
        needs[i].bytes = 4096;
        DeviceDesc d;
        d.name = "tiny";
        d.max_alloc = 1024;
        d.global_mem = 1 << 20;
        const std::string msg = test::error_of([&] { check_device_memory(d, needs); });
        EXPECT_NE(msg.find("array " + std::to_string(i) + " need"), std::string::npos) << msg;
    }
    DeviceDesc d;
    d.name = "small";
    d.max_alloc = 1 << 20;
    d.global_mem = 100;
    const Scene s = test::lit_scene(4);
    const DeviceScene dev = compile(s, build_bvh(s.vertices));
    EXPECT_NE(test::error_of([&] { check_device_memory(d, scene_buffer_needs(dev, 16)); }).find("out of device memory"),
              std::string::npos);
}

}  // namespace
}  // namespace facet
