// Kernel specialisation: the features a scene uses (kernels/shared/feature_flags.h holds the
// closed list), and the prelude that builds a program with only those.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/scene/scene.hpp"
#include "kernels/shared/feature_flags.h"

namespace facet {

using FeatureMask = std::uint32_t;
struct Bvh;

// One mask a feature: feature::kAREA_LIGHTS is FC_HAS_AREA_LIGHTS's bit, and so on.
namespace feature {
#define FC_FEATURE_BIT(name, bit) inline constexpr FeatureMask k##name = 1u << bit;
FC_FEATURE_LIST(FC_FEATURE_BIT)
#undef FC_FEATURE_BIT
}  // namespace feature

// Every feature of the closed list.
FeatureMask all_features();

// The features `scene` uses: light types present, diffuse and specular lobes, and the
// Beckmann NDF of any material that some triangle uses.
FeatureMask scene_features(const Scene& scene);

// "#define FC_HAS_X 0|1" for every feature: the prelude of a specialised program.
std::vector<std::string> feature_prelude(FeatureMask mask);

// The prelude of a program that renders `scene` through `bvh`: feature_prelude of the
// scene's features (nothing for the generic program, which keeps them all) and the BVH's
// layout line unless it is the kernels' default 4-wide tree.
std::vector<std::string> scene_program_prelude(const Scene& scene, const Bvh& bvh, bool generic = false);

// "area_lights environment microfacet" (the features present), or "none".
std::string describe_features(FeatureMask mask);

// The names of every feature, lower case, in list order.
std::vector<std::string> feature_names();

}  // namespace facet
