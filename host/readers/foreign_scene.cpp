// Scene files of other renderers, recognised by their extension and first bytes.
#include "host/readers/foreign_scene.hpp"

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

bool contains(std::string_view text, std::string_view word) { return text.find(word) != std::string_view::npos; }

// pbrt's directives as they open a line; v4 dropped WorldEnd and added ColorSpace,
// Option and Attribute.
std::string pbrt_kind(std::string_view ext, std::string_view head) {
    int directives = 0;
    for (std::string_view d : {"WorldBegin", "LookAt ", "Camera \"", "Shape \"", "Film \"", "Sampler \"",
                               "Integrator \"", "LightSource \"", "AreaLightSource \"", "Material \""})
        directives += contains(head, d) ? 1 : 0;
    if (ext != ".pbrt" && directives < 2) return "";
    if (contains(head, "WorldEnd")) return "a pbrt-v3 file";
    return "a pbrt-v4 file";
}

// <scene version="3.0.0"> (Mitsuba 3), "2.x" (Mitsuba 2) or "0.x" (Mitsuba 0.5/0.6).
std::string mitsuba_kind(std::string_view head) {
    const std::size_t scene = head.find("<scene");
    if (scene == std::string_view::npos) return "";
    const std::size_t version = head.find("version=", scene);
    if (version == std::string_view::npos || version + 9 >= head.size()) return "a Mitsuba scene";
    const char major = head[version + 9];
    if (major == '3') return "a Mitsuba 3 scene";
    if (major == '2') return "a Mitsuba 2 scene";
    if (major == '0') return "a Mitsuba 0.6 scene";
    return "a Mitsuba scene";
}

}  // namespace

std::string foreign_scene_kind(std::string_view ext, std::string_view head) {
    if (ext == ".xml" || contains(head.substr(0, 256), "<?xml")) return mitsuba_kind(head);
    if (ext == ".json" || ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb") return "";
    return pbrt_kind(ext, head);
}

std::string foreign_json_kind(const Json& root) {
    if (!root.is_object() || !root.contains("primitives")) return "";
    for (const char* key : {"bsdfs", "integrator", "renderer", "camera", "media"})
        if (root.contains(key)) return "a Tungsten scene";
    return "";
}

void refuse_foreign_scene(const std::string& path, const std::string& kind) {
    throw Error(
        fmt::format("{}: not a facet scene: this looks like {} (facet reads its own JSON scenes, "
                    "OBJ, PLY, glTF 2.0, STL, FBX, Collada, 3DS and other models; docs/scene-format.md)",
                    path, kind));
}

}  // namespace facet
