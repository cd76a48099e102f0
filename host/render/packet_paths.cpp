#include "host/render/packet_paths.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "kernels/shared/render_layout.h"

namespace facet {

FeatureMask packet_features() {
    using namespace feature;
    return kAREA_LIGHTS | kPUNCTUAL_LIGHTS | kENVIRONMENT | kSPHERES | kTEXTURES | kALPHA | kOREN_NAYAR |
           kASHIKHMIN_SHIRLEY | kBLINN_PHONG | kMICROFACET | kBECKMANN | kMETALLIC | kCLEARCOAT | kSHEEN | kANISOTROPY |
           kCLEARCOAT_TEXTURES | kSHEEN_TEXTURES | kSPECULAR_TEXTURES | kCLEARCOAT_NORMAL | kDIELECTRIC | kVOLUME;
}

bool lights_in_packets(const Scene& scene) {
    for (const FcLight& l : scene.lights)
        if (l.type != FC_LIGHT_AREA_TRIANGLE && l.type != FC_LIGHT_ENVIRONMENT && l.type != FC_LIGHT_POINT &&
            l.type != FC_LIGHT_SPOT && l.type != FC_LIGHT_DIRECTIONAL)
            return false;
    return true;
}

bool lambertian_materials(const Scene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    mark_triangle_materials(scene, used);
    for (const FcSphere& s : scene.spheres)
        if (s.material >= 0 && std::size_t(s.material) < used.size()) used[std::size_t(s.material)] = true;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const bool layered = m.clearcoat > 0.0f || std::max(m.sheen.x, std::max(m.sheen.y, m.sheen.z)) > 0.0f;
        if (used[i] && (m.diffuse_model != FC_DIFFUSE_LAMBERT || m.specular_model != FC_SPECULAR_NONE || layered))
            return false;
    }
    return true;
}

bool packet_paths_for(const DeviceDesc& device, unsigned native_float_vector_width, FeatureMask features,
                      bool packet_lights, std::uint32_t sampler, bool generic) {
    const char* env = std::getenv("FACET_PACKET_PATHS");
    if (env && std::strcmp(env, "0") == 0) return false;
    const bool lit = (features & (feature::kAREA_LIGHTS | feature::kPUNCTUAL_LIGHTS | feature::kENVIRONMENT)) != 0;
    const bool covered =
        !generic && lit && (features & ~packet_features()) == 0 && packet_lights && sampler == FC_SAMPLER_SOBOL;
    if (env && std::strcmp(env, "1") == 0) return covered;
    return covered && (device.type & CL_DEVICE_TYPE_CPU) != 0 && native_float_vector_width >= 8;
}

std::uint32_t packet_width_for(unsigned native_float_vector_width) {
    if (const char* env = std::getenv("FACET_PACKET_WIDTH")) {
        if (std::strcmp(env, "8") == 0) return 8u;
        if (std::strcmp(env, "16") == 0) return 16u;
    }
    return native_float_vector_width >= 16 ? 16u : 8u;
}

bool packet_trace_for(std::size_t tree_triangles) {
    if (const char* env = std::getenv("FACET_PACKET_TRACE")) {
        if (std::strcmp(env, "0") == 0) return false;
        if (std::strcmp(env, "1") == 0) return true;
    }
    return tree_triangles <= kPacketTraceUpToTriangles;
}

std::uint32_t packet_trace_min_for(std::size_t tree_triangles) {
    if (const char* env = std::getenv("FACET_PACKET_TRACE_MIN")) {
        char* end = nullptr;
        const long n = std::strtol(env, &end, 10);
        if (end != env && *end == '\0' && n >= 1 && n <= 16) return static_cast<std::uint32_t>(n);
    }
    return tree_triangles <= kPacketTraceTogetherUpToTriangles ? 1u : 4u;
}

void packet_tree_options(BvhOptions& options, std::size_t triangles, bool packets) {
    if (!packets || !packet_trace_for(triangles) || packet_trace_min_for(triangles) != 1u) return;
    options.block_size = 1;
    options.intersection_cost = kPacketLeafTriangleCost;
}

const char* packet_paths_requirements() {
    return "packets need no instances, no emitting spheres, and the sobol sampler";
}

}  // namespace facet
