#include "host/render/features.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "host/bvh/bvh.hpp"
#include "host/util/strings.hpp"
#include "kernels/shared/feature_flags.h"

namespace facet {
namespace {

struct Feature {
    const char* name;
    int bit;
};

#define FC_FEATURE_ENTRY(name, bit) {#name, bit},
constexpr Feature kFeatures[] = {FC_FEATURE_LIST(FC_FEATURE_ENTRY)};
#undef FC_FEATURE_ENTRY

using namespace feature;

}  // namespace

FeatureMask all_features() {
    FeatureMask m = 0;
    for (const Feature& f : kFeatures) m |= 1u << f.bit;
    return m;
}

FeatureMask scene_features(const Scene& scene) {
    FeatureMask mask = 0;
    for (const FcLight& l : scene.lights) {
        if (l.type == FC_LIGHT_AREA_TRIANGLE || l.type == FC_LIGHT_SPHERE) mask |= kAREA_LIGHTS;
        else if (l.type == FC_LIGHT_ENVIRONMENT) mask |= kENVIRONMENT;
        else mask |= kPUNCTUAL_LIGHTS;
    }
    // Escaped rays see the environment even when it lights nothing (a black map).
    if (scene.environment.params.enabled) mask |= kENVIRONMENT;
    std::vector<bool> used(scene.materials.size(), false);
    mark_triangle_materials(scene, used);
    if (!scene.spheres.empty()) mask |= kSPHERES;
    if (!scene.instances.empty()) mask |= kINSTANCES;
    for (const FcSphere& s : scene.spheres)
        if (s.material >= 0 && std::size_t(s.material) < used.size()) used[std::size_t(s.material)] = true;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (!used[i]) continue;
        const Material& m = scene.materials[i];
        if (m.diffuse_model == FC_DIFFUSE_OREN_NAYAR) mask |= kOREN_NAYAR;
        if (m.diffuse_model == FC_DIFFUSE_ASHIKHMIN_SHIRLEY || m.specular_model == FC_SPECULAR_ASHIKHMIN_SHIRLEY)
            mask |= kASHIKHMIN_SHIRLEY;
        if (m.specular_model == FC_SPECULAR_BLINN_PHONG || m.specular_model == FC_SPECULAR_BLINN_PHONG_NORMALIZED)
            mask |= kBLINN_PHONG;
        if (m.specular_model == FC_SPECULAR_MICROFACET) {
            mask |= kMICROFACET;
            if (m.ndf == FC_NDF_BECKMANN) mask |= kBECKMANN;
        }
        if (m.specular_model == FC_SPECULAR_DIELECTRIC) {
            mask |= kDIELECTRIC;
            if (m.ndf == FC_NDF_BECKMANN) mask |= kBECKMANN;
        }
        if (m.textures.any()) mask |= kTEXTURES;
        if (m.metallic > 0.0f || m.textures.metallic_workflow) mask |= kMETALLIC;
        if (m.specular_model == FC_SPECULAR_DIELECTRIC &&
            (m.attenuation.x > 0.0f || m.attenuation.y > 0.0f || m.attenuation.z > 0.0f))
            mask |= kVOLUME;
        if (m.alpha_mode != FC_ALPHA_OPAQUE) mask |= kALPHA;
        if (material_is_anisotropic(m)) mask |= kANISOTROPY;
        if (m.specular_model != FC_SPECULAR_DIELECTRIC) {  // the layers go over non-dielectrics only
            if (m.clearcoat > 0.0f) mask |= kCLEARCOAT;
            if (std::max(m.sheen.x, std::max(m.sheen.y, m.sheen.z)) > 0.0f) mask |= kSHEEN;
            if (m.clearcoat > 0.0f && m.textures.any_clearcoat()) mask |= kCLEARCOAT_TEXTURES;
            if (m.clearcoat > 0.0f && (m.textures.clearcoat_normal >= 0 || m.textures.normal >= 0))
                mask |= kCLEARCOAT_NORMAL;
            if (std::max(m.sheen.x, std::max(m.sheen.y, m.sheen.z)) > 0.0f && m.textures.any_sheen())
                mask |= kSHEEN_TEXTURES;
            if (m.textures.specular_extension) mask |= kSPECULAR_TEXTURES;
        }
    }
    return mask;
}

std::vector<std::string> feature_prelude(FeatureMask mask) {
    std::vector<std::string> lines;
    for (const Feature& f : kFeatures)
        lines.push_back(fmt::format("#define FC_HAS_{} {}", f.name, (mask >> f.bit) & 1u));
    return lines;
}

std::vector<std::string> scene_program_prelude(const Scene& scene, const Bvh& bvh, bool generic) {
    std::vector<std::string> lines = generic ? std::vector<std::string>{} : feature_prelude(scene_features(scene));
    if (bvh.stats.width != 4) lines.push_back(bvh_prelude(bvh));
    return lines;
}

std::string describe_features(FeatureMask mask) {
    std::string out;
    for (const Feature& f : kFeatures) {
        if (!((mask >> f.bit) & 1u)) continue;
        if (!out.empty()) out += ' ';
        out += lower(f.name);
    }
    return out.empty() ? "none" : out;
}

std::vector<std::string> feature_names() {
    std::vector<std::string> out;
    for (const Feature& f : kFeatures) out.push_back(lower(f.name));
    return out;
}

}  // namespace facet
