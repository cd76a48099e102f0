// JSON scene files: the file's sections in order, the render settings and the camera.
#include "host/readers/json_scene.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <type_traits>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/error.hpp"
#include "host/readers/foreign_scene.hpp"
#include "host/readers/json_loader.hpp"
#include "host/readers/text_parse.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/scene/render_names.hpp"
#include "host/scene/settings_limits.hpp"

namespace facet {

void JsonLoader::camera(const Json& v, const std::string& path) {
    r.object(v, path, {"eye", "target", "up", "fov", "projection", "height", "aperture", "focus_distance"});
    CameraDesc& c = scene.camera;
    auto k = [&](const char* name) { return JsonReader::key(path, name); };
    if (v.contains("eye")) c.eye = r.vec3(v["eye"], k("eye"));
    if (v.contains("target")) c.target = r.vec3(v["target"], k("target"));
    if (v.contains("up")) c.up = r.vec3(v["up"], k("up"));
    if (v.contains("fov")) c.fov_y_degrees = r.number_in(v["fov"], k("fov"), 0, 180, true, true);
    if (v.contains("height")) c.ortho_height = r.number_in(v["height"], k("height"), 0, 1e30, true);
    // Thin-lens depth of field: the lens radius and the distance of the plane in focus.
    if (v.contains("aperture")) c.aperture = r.number_in(v["aperture"], k("aperture"), 0, 1e30);
    if (v.contains("focus_distance"))
        c.focus_distance = r.number_in(v["focus_distance"], k("focus_distance"), 0, 1e30, true);
    if (v.contains("projection")) {
        const std::string p = r.string(v["projection"], k("projection"));
        if (p == "perspective") c.projection = FC_PROJECTION_PERSPECTIVE;
        else if (p == "orthographic") c.projection = FC_PROJECTION_ORTHOGRAPHIC;
        else
            r.fail(k("projection"), fmt::format("unknown projection '{}' (expected "
                                                "'perspective' or 'orthographic')",
                                                p));
    }
    const glm::vec3 forward = c.target - c.eye;
    if (!(glm::length(forward) > 0.0f)) r.fail(path, "eye and target are the same point");
    if (!std::isfinite(glm::length(forward)))
        r.fail(path, "eye and target are too far apart (their distance overflows a float)");
    if (!(glm::length(glm::cross(glm::normalize(forward), c.up)) > 1e-6f))
        r.fail(k("up"), "must be non-zero and not parallel to the view direction");
}

void JsonLoader::render(const Json& v, const std::string& path) {
    r.object(v, path,
             {"width", "height", "spp", "max_depth", "rr_depth", "seed", "strategy", "sampler", "filter", "clamp",
              "caustic_guide", "roulette_gain"});
    RenderSettings& s = scene.settings;
    auto k = [&](const char* name) { return JsonReader::key(path, name); };
    auto get = [&](const char* name, SettingRange range, auto& out) {
        if (v.contains(name))
            out = static_cast<std::decay_t<decltype(out)>>(r.integer(v[name], k(name), range.lo, range.hi));
    };
    get("width", limits::kWidth, s.width);
    get("height", limits::kHeight, s.height);
    get("spp", limits::kSpp, s.spp);
    get("max_depth", limits::kMaxDepth, s.max_depth);
    get("rr_depth", limits::kRrDepth, s.rr_depth);
    get("seed", limits::kSeed, s.seed);
    if (v.contains("strategy")) {
        const std::string key = k("strategy");
        const std::string name = r.string(v["strategy"], key);
        if (const std::optional<int> value = setting_value(kStrategyNames, name)) s.strategy = *value;
        else r.fail(key, fmt::format("unknown strategy '{}' (expected {})", name, setting_name_list(kStrategyNames)));
    }
    if (v.contains("sampler")) {
        const std::string key = k("sampler");
        const std::string name = r.string(v["sampler"], key);
        if (const std::optional<int> value = setting_value(kSamplerNames, name)) s.sampler = *value;
        else r.fail(key, fmt::format("unknown sampler '{}' (expected {})", name, setting_name_list(kSamplerNames)));
    }
    if (v.contains("filter")) filter(v["filter"], k("filter"));
    if (v.contains("clamp")) s.clamp = r.number_in(v["clamp"], k("clamp"), 0, double(FC_MAX_RADIANCE), true);
    if (v.contains("caustic_guide"))
        s.caustic_guide = r.number_in(v["caustic_guide"], k("caustic_guide"), 0, double(limits::kMaxCausticGuide));
    if (v.contains("roulette_gain"))
        s.roulette_gain =
            r.number_in(v["roulette_gain"], k("roulette_gain"), 0, double(limits::kMaxRouletteGain), true);
}

// "filter": "tent" or {"type": "tent", "radius": 1.5} (scene/pixel_filter.hpp).
void JsonLoader::filter(const Json& v, const std::string& path) {
    RenderSettings& s = scene.settings;
    const bool is_object = v.is_object();
    if (is_object) {
        r.object(v, path, {"type", "radius"});
        r.require(v, path, "type");
    }
    const std::string type_path = is_object ? JsonReader::key(path, "type") : path;
    const std::string name = r.string(is_object ? v["type"] : v, type_path);
    const std::optional<int> code = pixel_filter_code(name);
    if (!code) r.fail(type_path, fmt::format("unknown filter '{}' (expected {})", name, pixel_filter_names()));
    s.filter = *code;
    if (is_object && v.contains("radius"))
        s.filter_radius = r.number_in(v["radius"], JsonReader::key(path, "radius"), 0, double(kMaxFilterRadius), true);
}

std::string JsonLoader::existing_file(const Json& v, const std::string& path, const char* what) {
    const std::string file = r.string(v, path);
    const std::string full = text::join_path(dir, file);
    std::error_code ec;
    if (!std::filesystem::exists(full, ec))  // a non-regular one: the reader says so
        r.fail(path, fmt::format("{} '{}' not found (looked for '{}')", what, file, full));
    return full;
}

namespace {

// Calls `each` for every element of the array root[name], if there is one.
template <typename F>
void for_each_in(JsonLoader& l, const Json& root, const char* name, F each) {
    if (!root.contains(name)) return;
    const Json& a = root[name];
    if (!a.is_array()) l.r.fail(name, "expected an array");
    for (std::size_t i = 0; i < a.size(); ++i) each(a[i], JsonReader::index(name, i));
}

}  // namespace

bool load_json_scene(const std::string& path, Scene& scene) {
    const std::string content = text::read_file(path, "scene file");
    const Json root = parse_json(path, content);
    if (std::string kind = foreign_json_kind(root); !kind.empty()) refuse_foreign_scene(path, kind);
    for (std::string& w : duplicate_json_keys(path, content)) scene.warnings.push_back(std::move(w));
    JsonLoader l{JsonReader(path), text::directory_of(path), scene, {}, -1};
    l.r.object(root, "", {"camera", "render", "materials", "meshes", "shapes", "lights", "environment"});
    if (root.contains("render")) l.render(root["render"], "render");
    if (root.contains("materials")) {
        const Json& mats = root["materials"];
        if (!mats.is_object()) l.r.fail("materials", "expected an object {\"name\": {...}}");
        for (const auto& item : mats.items())
            l.material(item.key(), item.value(), JsonReader::key("materials", item.key()));
    }
    for_each_in(l, root, "meshes", [&](const Json& v, const std::string& p) { l.mesh(v, p); });
    for_each_in(l, root, "shapes", [&](const Json& v, const std::string& p) { l.shape(v, p); });
    for_each_in(l, root, "lights", [&](const Json& v, const std::string& p) { l.light(v, p); });
    if (root.contains("environment")) l.environment(root["environment"], "environment");
    if (scene.triangle_count() == 0 && scene.spheres.empty())
        throw Error(fmt::format("{}: the scene has no geometry (no 'meshes' or 'shapes')", path));
    const bool has_camera = root.contains("camera");
    if (has_camera) l.camera(root["camera"], "camera");
    return has_camera;
}

}  // namespace facet
