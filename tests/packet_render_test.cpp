// Issue 29's packet form (kernels/bench/packet_render.cl: eight paths a work-item in float8
// lanes, its formulas the lane-generic bodies of kernels/lanes/) against the scalar form
// (render_pass, one path a work-item): the same samples of the Cornell box, so the same
// image up to the order of additions. Every pixel channel must agree to 1e-4 relative, no
// sample may be rejected, and the two images' means must agree to 1e-6. The bench
// (`facet_bench --only packet`) times the two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/film/film_layout.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/render/scene_buffers.hpp"
#include "host/scene/device_scene.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

TEST(PacketRender, SameImageAsTheScalarKernel) {
    ClContext& ctx = test::context();
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    const std::uint32_t size = 40, spp = 24;  // 24: each work-item's last packet is partly idle
    scene.settings.width = scene.settings.height = size;
    const Bvh bvh = build_bvh(scene.vertices, BvhOptions{});
    const std::size_t pixels = std::size_t(size) * size;

    // the packet form: one launch over every pixel, the film layout of render_pass
    const DeviceScene dev = compile(scene, bvh);
    const ProgramBuild build = build_program(ctx, "kernels/bench/packet_render.cl", scene_program_prelude(scene, bvh));
    cl::Kernel kernel(build.program, "packet_pass");
    const SceneBuffers buffers = upload_scene(ctx.context(), dev);
    const std::size_t floats = film_floats(pixels);
    cl::Buffer accum(ctx.context(), CL_MEM_READ_WRITE, floats * sizeof(float));
    ctx.queue().enqueueFillBuffer(accum, 0.0f, 0, floats * sizeof(float));
    kernel.setArg(bind_scene(kernel, buffers), accum);
    FcRenderParams p = dev.params;
    p.sample_begin = 0;
    p.sample_count = spp;
    p.row_begin = 0;
    p.row_count = size;
    ctx.queue().enqueueWriteBuffer(buffers.params, CL_TRUE, 0, sizeof p, &p);
    ctx.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(pixels));
    std::vector<float> sums(floats);
    ctx.queue().enqueueReadBuffer(accum, CL_TRUE, 0, floats * sizeof(float), sums.data());

    // the scalar form, through the renderer
    Renderer renderer(ctx, scene, bvh);
    render_fixed(renderer, spp);
    const Renderer::Halves h = renderer.halves();

    double mean_scalar = 0.0, mean_packet = 0.0, rejected = 0.0;
    int differ = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            const double a = 0.5 * (double(h.rgb[0][3 * i + c]) + double(h.rgb[1][3 * i + c]));
            const double b = (double(sums[4 * i + c]) + double(sums[4 * (pixels + i) + c])) / double(spp);
            mean_scalar += a;
            mean_packet += b;
            if (!(std::fabs(a - b) <= 1e-4 * std::max(1e-3, std::fabs(a))) && differ++ < 5)
                ADD_FAILURE() << "pixel " << i << " channel " << c << ": scalar " << a << ", packet " << b;
        }
        rejected += double(sums[4 * i + 3]) + double(sums[4 * (pixels + i) + 3]);
    }
    mean_scalar /= 3.0 * double(pixels);
    mean_packet /= 3.0 * double(pixels);
    std::printf("[ packet   ] Cornell box %u² %u spp: means %.7f (scalar) / %.7f (packet), %d channels differ\n", size,
                spp, mean_scalar, mean_packet, differ);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(rejected, 0.0);
    EXPECT_GT(mean_scalar, 0.01);  // a lit image, not two black ones
    EXPECT_NEAR(mean_packet, mean_scalar, 1e-6 * mean_scalar);
}

}  // namespace
}  // namespace facet
