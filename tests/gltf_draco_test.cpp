// KHR_draco_mesh_compression (host/readers/gltf_draco.hpp): Khronos' 2CylinderEngine, as
// Debian's assimp-testmodels ships it both Draco-compressed and plain, reads as the same
// model (Draco quantises positions to 14 bits here, so to within that step), and renders
// the same image; a corrupt bitstream is an error naming the file and the extension.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "host/bvh/bvh.hpp"
#include "host/error.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/temp_dir.hpp"

namespace facet {
namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models/glTF2";
const std::filesystem::path kDraco = kModels / "draco/2CylinderEngine.gltf";
const std::filesystem::path kPlain = kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// The mean image of `scene` from its framed camera, 48 x 48 at 16 spp.
std::vector<float> render_mean(Scene scene) {
    scene.settings.width = scene.settings.height = 48;
    scene.settings.max_depth = 3;
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, 16, 8);
    return r.image();
}

TEST(GltfDraco, ReadsAsItsUncompressedCopy) {
    if (!std::filesystem::exists(kDraco) || !std::filesystem::exists(kPlain))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const Scene draco = load_scene(kDraco.string());
    const Scene plain = load_scene(kPlain.string());
    // Quantised positions collapse a few slivers to zero area (dropped with a warning): 15
    // of the 110338 triangles here.
    EXPECT_NEAR(double(draco.placed_triangle_count()), double(plain.placed_triangle_count()),
                1e-3 * double(plain.placed_triangle_count()));
    const Bounds a = scene_bounds(draco), b = scene_bounds(plain);
    const float size = glm::length(b.hi - b.lo);
    EXPECT_LT(glm::length(a.lo - b.lo), 1e-3f * size);
    EXPECT_LT(glm::length(a.hi - b.hi), 1e-3f * size);
    for (const std::string& w : draco.warnings) EXPECT_EQ(w.find("KHR_draco"), std::string::npos) << w;
    // Same camera for both (the plain one's framing), then the images agree pixel by pixel
    // up to the quantisation's sub-pixel shifts at edges: the mean within 1 %, 95 % of the
    // pixels within 5 %.
    Scene d = draco;
    d.camera = plain.camera;
    const std::vector<float> x = render_mean(d), y = render_mean(plain);
    ASSERT_EQ(x.size(), y.size());
    double sx = 0.0, sy = 0.0;
    std::size_t close = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += double(x[i]);
        sy += double(y[i]);
        if (std::fabs(double(x[i]) - double(y[i])) <= 0.05 * std::max(double(y[i]), 0.02)) ++close;
    }
    EXPECT_NEAR(sx / sy, 1.0, 0.01);
    EXPECT_GT(double(close) / double(x.size()), 0.95);
}

TEST(GltfDraco, CorruptBitstreamNamesTheExtension) {
    if (!std::filesystem::exists(kDraco)) GTEST_SKIP() << "assimp-testmodels is not installed";
    test::TempDir dir;
    std::filesystem::copy_file(kDraco, dir.dir() / "engine.gltf");
    std::ifstream in(kDraco.parent_path() / "2CylinderEngine.bin", std::ios::binary);
    std::string bin((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fill(bin.begin(), bin.begin() + std::ptrdiff_t(std::min<std::size_t>(bin.size(), 4096)), '\x5a');
    dir.write("2CylinderEngine.bin", bin);
    try {
        load_scene((dir.dir() / "engine.gltf").string());
        FAIL() << "a corrupt Draco bitstream was accepted";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("engine.gltf"), std::string::npos) << what;
        EXPECT_NE(what.find("KHR_draco_mesh_compression"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace facet
