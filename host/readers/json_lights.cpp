// JSON scene files: punctual lights (docs/lights.md) and the environment
// (docs/environment.md).
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/error.hpp"
#include "host/readers/environment_file.hpp"
#include "host/readers/json_loader.hpp"
#include "host/scene/sky.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {

namespace {

// Colours that become radiance: at most FC_MAX_RADIANCE, so the image stays finite.
void check_radiance(JsonReader& r, const glm::vec3& c, const std::string& key) {
    for (int i = 0; i < 3; ++i)
        if (!(c[i] <= FC_MAX_RADIANCE))
            r.fail(key,
                   fmt::format("must be at most {:g} (got {:g}): the image would overflow", FC_MAX_RADIANCE, c[i]));
}

}  // namespace

void JsonLoader::light(const Json& v, const std::string& path) {
    r.object(v, path, {"type", "position", "direction", "color", "inner", "outer"});
    r.require(v, path, "type");
    auto k = [&](const char* key) { return JsonReader::key(path, key); };
    const std::string type = r.string(v["type"], k("type"));
    PunctualLight l;
    if (type == "point") l.type = FC_LIGHT_POINT;
    else if (type == "spot") l.type = FC_LIGHT_SPOT;
    else if (type == "directional") l.type = FC_LIGHT_DIRECTIONAL;
    else r.fail(k("type"), fmt::format("unknown light type '{}' (expected point, spot or directional)", type));
    if (l.type != FC_LIGHT_DIRECTIONAL) {
        r.require(v, path, "position");
        l.position = r.vec3(v["position"], k("position"));
        for (int c = 0; c < 3; ++c)
            if (std::fabs(l.position[c]) > 1e18f) r.fail(k("position"), "coordinates must be within +-1e18");
    }
    if (l.type != FC_LIGHT_POINT) {
        r.require(v, path, "direction");
        l.direction = r.vec3(v["direction"], k("direction"));
        if (!(glm::length(l.direction) > 0.0f)) r.fail(k("direction"), "must not be zero");
        if (!std::isfinite(glm::length(l.direction)))
            r.fail(k("direction"), "is too long to normalise in float; give a unit vector");
    }
    r.require(v, path, "color");
    l.color = r.color(v["color"], k("color"));
    check_radiance(r, l.color, k("color"));
    if (v.contains("inner")) l.inner_degrees = r.number_in(v["inner"], k("inner"), 0, 180);
    if (v.contains("outer")) l.outer_degrees = r.number_in(v["outer"], k("outer"), 0, 180);
    if (l.outer_degrees < l.inner_degrees) r.fail(k("outer"), "must not be smaller than 'inner'");
    scene.punctual_lights.push_back(l);
}

namespace {

// "sky": {"elevation", "azimuth", "turbidity", "width"}: the generated sun and sky.
EnvironmentMap sun_sky(const JsonReader& r, const Json& sky, const std::string& sp) {
    r.object(sky, sp, {"elevation", "azimuth", "turbidity", "width"});
    auto k = [&](const char* key) { return JsonReader::key(sp, key); };
    SunSkyParams params;
    if (sky.contains("elevation"))
        params.elevation_degrees = double(r.number_in(sky["elevation"], k("elevation"), -10, 90));
    if (sky.contains("azimuth")) params.azimuth_degrees = double(r.number_in(sky["azimuth"], k("azimuth"), -360, 360));
    if (sky.contains("turbidity")) params.turbidity = double(r.number_in(sky["turbidity"], k("turbidity"), 1.7, 10));
    int width = 1024;
    if (sky.contains("width")) width = int(r.integer(sky["width"], k("width"), 8, 16384));
    return sun_sky_environment(params, width);
}

}  // namespace

// The environment: a map file, a constant radiance or the generated sun and sky, with
// a radiance scale and a rotation.
void JsonLoader::environment(const Json& v, const std::string& path) {
    r.object(v, path, {"file", "constant", "sky", "scale", "rotate", "sampling", "filter"});
    auto k = [&](const char* key) { return JsonReader::key(path, key); };
    int sources = int(v.contains("file")) + int(v.contains("constant")) + int(v.contains("sky"));
    if (sources != 1) r.fail(path, "give exactly one of 'file', 'constant' or 'sky'");
    glm::vec3 scale(1.0f);
    if (v.contains("scale")) {
        scale = v["scale"].is_number() ? glm::vec3(r.number_in(v["scale"], k("scale"), 0, 1e30))
                                       : r.color(v["scale"], k("scale"));
    }
    glm::mat3 map_to_world(1.0f);
    if (v.contains("rotate")) map_to_world = glm::mat3(transform(Json{{"rotate", v["rotate"]}}, path));
    const glm::mat3 world_to_map = glm::transpose(map_to_world);
    if (v.contains("constant")) {
        const glm::vec3 constant = r.color(v["constant"], k("constant")) * scale;
        check_radiance(r, constant, k("constant"));
        scene.environment = constant_environment(constant);
    } else if (v.contains("file")) {
        const std::string full = existing_file(v["file"], k("file"), "environment map");
        try {
            scene.environment = load_environment_map(full, scale, world_to_map, scene.warnings);
        } catch (const Error& e) {
            r.fail(k("file"), e.what());
        }
    } else {
        scene.environment = sun_sky(r, v["sky"], k("sky"));
        set_environment_scale(scene.environment, scale);
    }
    set_environment_rotation(scene.environment, world_to_map);
    // A map is read at the nearest texel unless the scene asks for bilinear lookups
    // (docs/environment.md, "Lookup: nearest or bilinear": the same error per sample, and
    // on a sky-lit scene a quarter fewer samples per second).
    int filter = FC_ENV_FILTER_NEAREST;
    if (v.contains("filter")) {
        const std::string name = r.string(v["filter"], k("filter"));
        if (name == "nearest") filter = FC_ENV_FILTER_NEAREST;
        else if (name == "bilinear") filter = FC_ENV_FILTER_BILINEAR;
        else r.fail(k("filter"), fmt::format("unknown filter '{}' (expected nearest or bilinear)", name));
    }
    if (scene.environment.params.width > 0) set_environment_filter(scene.environment, filter);
    if (v.contains("sampling")) {
        const std::string name = r.string(v["sampling"], k("sampling"));
        if (name == "plain") scene.environment.sampling = EnvironmentSampling::plain;
        else if (name == "compensated") scene.environment.sampling = EnvironmentSampling::compensated;
        else r.fail(k("sampling"), fmt::format("unknown sampling '{}' (expected compensated or plain)", name));
    }
}

}  // namespace facet
