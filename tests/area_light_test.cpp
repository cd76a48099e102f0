// Triangle lights (kernels/lights/area.cl, light.cl): near a light, renders with light
// sampling, BSDF sampling and MIS agree, so the MIS weight of a light that BSDF sampling
// hits uses the density light sampling had.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

// A white Lambertian floor under a small emitting triangle 0.15 above it: light
// sampling, BSDF sampling and MIS estimate the same image.
TEST(AreaLight, StrategiesAgreeNearTheLight) {
    Scene scene;
    Material floor = default_material();
    floor.diffuse = glm::vec3(0.8f);
    Material lamp = default_material();
    lamp.diffuse = glm::vec3(0.0f);
    lamp.emission = glm::vec3(5.0f);
    const int m_floor = add_material(scene, floor, "floor"), m_lamp = add_material(scene, lamp, "lamp");
    add_quad(scene, glm::vec3(-1.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(2.0f, 0.0f, 0.0f), m_floor);
    add_triangle(scene, glm::vec3(-0.2f, 0.15f, -0.2f), glm::vec3(0.25f, 0.15f, -0.1f), glm::vec3(0.0f, 0.15f, 0.25f),
                 glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), m_lamp);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 2.5f, 0.01f);
    scene.camera.target = glm::vec3(0.0f);
    scene.settings.width = scene.settings.height = 24;
    scene.settings.max_depth = 1;
    Bvh bvh = build_bvh(scene.vertices);
    const std::uint32_t spp = 256;
    struct Result {
        double sum = 0.0, var = 0.0;
    };
    auto render = [&](int strategy) {
        scene.settings.strategy = strategy;
        Renderer r(test::context(), scene, bvh);
        r.render(spp);
        const test::PixelEstimates e = test::pixel_estimates(r.halves());
        Result out;
        for (std::size_t i = 0; i < e.mean.size(); ++i) out.sum += e.mean[i], out.var += e.var[i];
        return out;
    };
    const Result mis = render(FC_STRATEGY_MIS), light = render(FC_STRATEGY_LIGHT), bsdf = render(FC_STRATEGY_BSDF);
    EXPECT_GT(mis.sum, 0.0);
    for (const Result* other : {&light, &bsdf}) {
        const double z = (other->sum - mis.sum) / std::sqrt(other->var + mis.var);
        EXPECT_LT(std::fabs(z), 4.0) << (other == &light ? "light" : "bsdf") << " sampling against MIS: " << other->sum
                                     << " vs " << mis.sum;
    }
}

}  // namespace
}  // namespace facet
