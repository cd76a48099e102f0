// Every program variant the feature list allows builds (kernels/shared/feature_flags.h): all
// 2^12 combinations take hours on PoCL, so the path tracer and the AOV program are built
// with no feature, each feature alone, every feature, and the combinations the demo scenes
// use. The kernel source assembler (host/cl/kernel_source.cpp) inlines a file at every
// include, so a variant that disables the block where a file is first included still has
// it wherever else it is included.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/features.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

std::vector<FeatureMask> variants() {
    std::vector<FeatureMask> masks = {0, all_features()};
    for (FeatureMask bit = 1; bit <= all_features(); bit <<= 1)
        if (all_features() & bit) masks.push_back(bit);
    for (const char* file : {"cornell_box.json", "material_grid.json", "spheres_sky.json", "furnace_sphere.json",
                             "glass_metal_sky.json", "gltf_materials.gltf"})
        masks.push_back(scene_features(load_scene(test::scenes_dir() + "/" + file)));
    std::vector<FeatureMask> unique;
    std::set<FeatureMask> seen;
    for (FeatureMask m : masks)
        if (seen.insert(m).second) unique.push_back(m);
    return unique;
}

TEST(KernelVariants, EveryFeatureAloneAllAndTheDemoScenesBuild) {
    for (const char* entry : {"kernels/integrator/path.cl", "kernels/aov/aov.cl"}) {
        double total = 0.0;
        const std::vector<FeatureMask> masks = variants();
        for (FeatureMask mask : masks) {
            try {
                const ProgramBuild build = build_program(test::context(), entry, feature_prelude(mask));
                total += build.seconds;
            } catch (const Error& e) {
                ADD_FAILURE() << entry << " with " << describe_features(mask) << ": " << e.what();
            }
        }
        std::printf("%s: %zu variants, %.2f s to build (%.2f s each)\n", entry, masks.size(), total,
                    total / double(masks.size()));
    }
}

}  // namespace
}  // namespace facet
