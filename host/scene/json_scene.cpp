#include "host/scene/json_scene.hpp"

#include <cstdint>
#include <filesystem>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/error.hpp"
#include "kernels/shared/render_layout.h"
#include "host/scene/json_schema.hpp"
#include "host/util/wide_vector.hpp"
#include "host/scene/material.hpp"
#include "host/scene/sky.hpp"
#include "host/scene/load.hpp"
#include "host/scene/text_parse.hpp"

namespace facet {
namespace {

// "'a', 'b', 'c'" (or "none").
template <typename Range, typename Name>
std::string quoted_list(const Range& items, Name name) {
    std::string out;
    for (const auto& item : items) {
        if (!out.empty()) out.append(", ");
        out.append(fmt::format("'{}'", name(item)));
    }
    return out.empty() ? std::string("none") : out;
}

struct Loader {
    JsonReader r;
    std::string dir;
    Scene& scene;
    std::map<std::string, int> materials;  // JSON material name -> scene index
    int default_index = -1;

    int material_ref(const Json& v, const std::string& path) {
        const std::string name = r.string(v, path);
        auto it = materials.find(name);
        if (it == materials.end()) {
            const std::string known = quoted_list(materials, [](const auto& m) { return m.first; });
            r.fail(path, fmt::format("unknown material '{}' (defined: {})", name, known));
        }
        return it->second;
    }

    int optional_material(const Json& obj, const std::string& path) {
        if (obj.contains("material"))
            return material_ref(obj["material"], JsonReader::key(path, "material"));
        if (default_index < 0) default_index = add_material(scene, default_material(), "default");
        return default_index;
    }

    void camera(const Json& v, const std::string& path) {
        r.object(v, path, {"eye", "target", "up", "fov", "projection", "height"});
        CameraDesc& c = scene.camera;
        auto k = [&](const char* name) { return JsonReader::key(path, name); };
        if (v.contains("eye")) c.eye = r.vec3(v["eye"], k("eye"));
        if (v.contains("target")) c.target = r.vec3(v["target"], k("target"));
        if (v.contains("up")) c.up = r.vec3(v["up"], k("up"));
        if (v.contains("fov"))
            c.fov_y_degrees = r.number_in(v["fov"], k("fov"), 0, 180, true, true);
        if (v.contains("height")) {
            c.ortho_height = r.number_in(v["height"], k("height"), 0, 1e30, true);
        }
        if (v.contains("projection")) {
            const std::string p = r.string(v["projection"], k("projection"));
            if (p == "perspective")
                c.projection = FC_PROJECTION_PERSPECTIVE;
            else if (p == "orthographic")
                c.projection = FC_PROJECTION_ORTHOGRAPHIC;
            else
                r.fail(k("projection"), fmt::format("unknown projection '{}' (expected "
                                                    "'perspective' or 'orthographic')",
                                                    p));
        }
        const glm::vec3 forward = c.target - c.eye;
        if (!(glm::length(forward) > 0.0f)) r.fail(path, "eye and target are the same point");
        if (!std::isfinite(glm::length(forward)))
            r.fail(path, "eye and target are too far apart (their distance overflows a float)");
        if (!(glm::length(glm::cross(glm::normalize(forward), c.up)) > 1e-6f)) {
            r.fail(k("up"), "must be non-zero and not parallel to the view direction");
        }
    }

    void render(const Json& v, const std::string& path) {
        r.object(v, path, {"width", "height", "spp", "max_depth", "rr_depth", "seed", "strategy"});
        RenderSettings& s = scene.settings;
        auto k = [&](const char* name) { return JsonReader::key(path, name); };
        auto get = [&](const char* name, std::int64_t lo, std::int64_t hi, auto& out) {
            if (v.contains(name))
                out = static_cast<std::decay_t<decltype(out)>>(r.integer(v[name], k(name), lo, hi));
        };
        get("width", 1, 16384, s.width);
        get("height", 1, 16384, s.height);
        get("spp", 1, std::int64_t{1} << 24, s.spp);
        get("max_depth", 1, 1024, s.max_depth);
        get("rr_depth", 0, 1024, s.rr_depth);
        get("seed", 0, 0xffffffffLL, s.seed);
        if (v.contains("strategy")) {
            const std::string k = JsonReader::key(path, "strategy");
            const std::string name = r.string(v["strategy"], k);
            if (name == "mis") s.strategy = FC_STRATEGY_MIS;
            else if (name == "light") s.strategy = FC_STRATEGY_LIGHT;
            else if (name == "bsdf") s.strategy = FC_STRATEGY_BSDF;
            else r.fail(k, fmt::format("unknown strategy '{}' (expected mis, light or bsdf)", name));
        }
    }

    // A material: a named model's preset (material.hpp), then its parameters. One
    // "roughness" knob serves every model: microfacet alpha, Phong-style exponent
    // (through the lecture's m = sqrt(2 / (2 + s))) and Oren-Nayar's sigma.
    void material(const std::string& name, const Json& v, const std::string& path) {
        r.object(v, path,
                 {"model", "diffuse", "specular", "f0", "emission", "two_sided_emission", "roughness",
                  "roughness_x", "roughness_y", "shininess", "shininess_x", "shininess_y", "sigma", "ior",
                  "eta", "k", "diffuse_model", "specular_model", "ndf", "geometry", "fresnel", "sampling",
                  "conductor", "transmittance"});
        auto k = [&](const char* key) { return JsonReader::key(path, key); };
        auto put = [](float out[3], glm::vec3 c) {
            out[0] = c.x;
            out[1] = c.y;
            out[2] = c.z;
        };
        std::string model = v.contains("model") ? r.string(v["model"], k("model")) : "lambert";
        std::optional<FcMaterial> preset = material_preset(model);
        if (!preset) {
            std::string known;
            for (std::string_view n : material_model_names()) known += (known.empty() ? "'" : ", '") + std::string(n) + "'";
            r.fail(k("model"), fmt::format("unknown model '{}' (known: {})", model, known));
        }
        FcMaterial m = *preset;
        if (v.contains("diffuse")) put(m.diffuse, r.color(v["diffuse"], k("diffuse")));
        if (v.contains("specular")) put(m.specular, r.color(v["specular"], k("specular")));
        if (v.contains("f0")) {
            if (v["f0"].is_string()) {
                std::string preset_name = r.string(v["f0"], k("f0"));
                std::optional<std::array<float, 3>> f0 = f0_preset(preset_name);
                if (!f0) {
                    std::string known;
                    for (std::string_view n : f0_preset_names()) known += (known.empty() ? "" : ", ") + std::string(n);
                    r.fail(k("f0"), fmt::format("unknown F0 preset '{}' (known: {})", preset_name, known));
                }
                for (int c = 0; c < 3; ++c) m.specular[c] = (*f0)[c];
            } else {
                put(m.specular, r.color(v["f0"], k("f0")));
            }
        }
        if (v.contains("emission")) put(m.emission, r.color(v["emission"], k("emission")));
        // Roughness (alpha) and shininess (the Phong exponent) are one parameter in two
        // units; each sets both fields, for both axes or, with _x/_y, for one. Applied in
        // the order written: roughness, then shininess; the pair, then each axis.
        struct Lobe { const char* key; double hi; bool is_roughness; };
        for (const Lobe& p : {Lobe{"roughness", 1.0, true}, Lobe{"shininess", 1e6, false}}) {
            auto set = [&](float value, float& alpha, float& exponent) {
                alpha = p.is_roughness ? value : roughness_from_shininess(value);
                exponent = p.is_roughness ? shininess_from_roughness(value) : value;
            };
            const std::string key = p.key, kx = key + "_x", ky = key + "_y";
            if (v.contains(key)) {
                float value = r.number_in(v[key], k(key.c_str()), 0, p.hi);
                set(value, m.alpha_x, m.exponent_x);
                set(value, m.alpha_y, m.exponent_y);
                if (p.is_roughness) m.roughness = value;
            }
            if (v.contains(kx)) set(r.number_in(v[kx], k(kx.c_str()), 0, p.hi), m.alpha_x, m.exponent_x);
            if (v.contains(ky)) set(r.number_in(v[ky], k(ky.c_str()), 0, p.hi), m.alpha_y, m.exponent_y);
        }
        if (v.contains("sigma")) m.roughness = r.number_in(v["sigma"], k("sigma"), 0, 1.5707963);
        if (v.contains("ior")) m.ior = r.number_in(v["ior"], k("ior"), 1e-3, 100);
        if (v.contains("conductor")) {
            // A metal's complex index, with its Schlick F0 beside it for "fresnel": "schlick".
            std::string metal = r.string(v["conductor"], k("conductor"));
            std::optional<ConductorIndex> c = conductor_preset(metal);
            if (!c) {
                std::string known;
                for (std::string_view n : conductor_preset_names()) known += (known.empty() ? "" : ", ") + std::string(n);
                r.fail(k("conductor"), fmt::format("unknown conductor '{}' (known: {})", metal, known));
            }
            std::array<float, 3> f0 = *f0_preset(metal);
            for (int c3 = 0; c3 < 3; ++c3) m.eta[c3] = c->eta[c3], m.k[c3] = c->k[c3], m.specular[c3] = f0[c3];
            m.fresnel = FC_FRESNEL_CONDUCTOR;
        }
        if (v.contains("transmittance")) put(m.specular, r.color(v["transmittance"], k("transmittance")));
        if (v.contains("eta")) put(m.eta, r.color(v["eta"], k("eta")));
        if (v.contains("k")) put(m.k, r.color(v["k"], k("k")));
        auto choice = [&](const char* key, MaterialEnum kind, fc_int& field) {
            if (!v.contains(key)) return;
            std::string value = r.string(v[key], k(key));
            std::optional<int> e = enum_from_name(kind, value);
            if (!e) r.fail(k(key), fmt::format("unknown {} '{}' (expected {})", enum_kind_name(kind), value, enum_name_list(kind)));
            field = *e;
        };
        choice("diffuse_model", MaterialEnum::Diffuse, m.diffuse_model);
        choice("specular_model", MaterialEnum::Specular, m.specular_model);
        choice("ndf", MaterialEnum::Ndf, m.ndf);
        choice("geometry", MaterialEnum::Geometry, m.geometry);
        choice("fresnel", MaterialEnum::Fresnel, m.fresnel);
        choice("sampling", MaterialEnum::Sampling, m.sampling);
        if (v.contains("two_sided_emission") && r.boolean(v["two_sided_emission"], k("two_sided_emission")))
            m.flags |= FC_MAT_TWO_SIDED_EMISSION;
        for (int c = 0; c < 3; ++c) {
            if (m.diffuse[c] > 1.0f || m.specular[c] > 1.0f) {
                scene.warnings.push_back(fmt::format("{}: {}: a reflectance above 1 creates energy", r.file(), path));
                break;
            }
        }
        for (int c = 0; c < 3; ++c) m.diffuse[c] = std::min(m.diffuse[c], 1.0f), m.specular[c] = std::min(m.specular[c], 1.0f);
        if (std::string problem = validate_material(m); !problem.empty()) r.fail(path, problem);
        materials[name] = add_material(scene, m, name);
    }

    glm::mat4 transform(const Json& v, const std::string& path) {
        r.object(v, path, {"scale", "rotate", "translate"});
        glm::vec3 scale(1.0f);
        if (v.contains("scale")) {
            const std::string p = JsonReader::key(path, "scale");
            scale = v["scale"].is_number() ? glm::vec3(static_cast<float>(r.number(v["scale"], p)))
                                           : r.vec3(v["scale"], p);
            if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f)
                r.fail(p, "must not be zero");
        }
        glm::mat4 rotation(1.0f);
        if (v.contains("rotate")) {
            const Json& rot = v["rotate"];
            const std::string p = JsonReader::key(path, "rotate");
            const bool list = rot.is_array() && !rot.empty() && rot[0].is_array();
            const std::size_t n = list ? rot.size() : 1;
            for (std::size_t i = 0; i < n; ++i) {
                const Json& one = list ? rot[i] : rot;
                const std::string pi = list ? JsonReader::index(p, i) : p;
                if (!one.is_array() || one.size() != 4) {
                    r.fail(pi,
                           "expected [angle_degrees, axis_x, axis_y, axis_z] (or a list of them)");
                }
                const float angle = static_cast<float>(r.number(one[0], JsonReader::index(pi, 0)));
                glm::vec3 axis;
                for (int a = 0; a < 3; ++a) {
                    const auto ai = static_cast<std::size_t>(a + 1);
                    axis[a] = static_cast<float>(r.number(one[ai], JsonReader::index(pi, ai)));
                }
                if (!(glm::length(axis) > 0.0f)) r.fail(pi, "rotation axis is zero");
                rotation = glm::rotate(glm::mat4(1.0f), glm::radians(angle), glm::normalize(axis)) *
                           rotation;
            }
        }
        glm::vec3 translate(0.0f);
        if (v.contains("translate"))
            translate = r.vec3(v["translate"], JsonReader::key(path, "translate"));
        return glm::translate(glm::mat4(1.0f), translate) * rotation *
               glm::scale(glm::mat4(1.0f), scale);
    }

    void mesh(const Json& v, const std::string& path) {
        r.object(v, path, {"file", "material", "materials", "transform"});
        r.require(v, path, "file");
        const std::string file = r.string(v["file"], JsonReader::key(path, "file"));
        const std::string full = text::join_path(dir, file);
        std::error_code ec;
        if (!std::filesystem::exists(full, ec)) {   // a non-regular one: the reader says so
            r.fail(JsonReader::key(path, "file"),
                   fmt::format("mesh file '{}' not found (looked for '{}')", file, full));
        }
        ObjLoadOptions options;
        if (v.contains("material"))
            options.material_override =
                material_ref(v["material"], JsonReader::key(path, "material"));
        if (v.contains("materials")) {
            const std::string p = JsonReader::key(path, "materials");
            if (!v["materials"].is_object())
                r.fail(p, "expected an object {\"mtl name\": \"material\"}");
            for (const auto& item : v["materials"].items()) {
                options.material_map[item.key()] =
                    material_ref(item.value(), JsonReader::key(p, item.key()));
            }
        }
        if (v.contains("transform"))
            options.transform = transform(v["transform"], JsonReader::key(path, "transform"));
        try {
            load_obj(full, scene, options);
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}: {}", r.file(), path, e.what()));
        }
    }

    void shape(const Json& v, const std::string& path) {
        if (!v.is_object()) r.fail(path, "expected an object");
        r.require(v, path, "type");
        const std::string type = r.string(v["type"], JsonReader::key(path, "type"));
        auto k = [&](const char* key) { return JsonReader::key(path, key); };
        if (type == "sphere") {
            r.object(v, path, {"type", "center", "radius", "subdivisions", "material", "inward"});
            r.require(v, path, "center");
            r.require(v, path, "radius");
            const glm::vec3 center = r.vec3(v["center"], k("center"));
            const float radius = r.number_in(v["radius"], k("radius"), 0, 1e30, true);
            int subdivisions = 3;
            if (v.contains("subdivisions"))
                subdivisions =
                    static_cast<int>(r.integer(v["subdivisions"], k("subdivisions"), 0, 8));
            const bool inward = v.contains("inward") && r.boolean(v["inward"], k("inward"));
            add_sphere(scene, center, radius, subdivisions, optional_material(v, path), inward);
        } else if (type == "quad") {
            r.object(v, path, {"type", "corner", "edge1", "edge2", "material"});
            for (const char* key : {"corner", "edge1", "edge2"}) r.require(v, path, key);
            const glm::vec3 corner = r.vec3(v["corner"], k("corner"));
            const glm::vec3 e1 = r.vec3(v["edge1"], k("edge1"));
            const glm::vec3 e2 = r.vec3(v["edge2"], k("edge2"));
            if (!(glm::length(wide_cross(e1, e2)) > 0.0))
                r.fail(path, "edge1 and edge2 span no area");
            add_quad(scene, corner, e1, e2, optional_material(v, path));
        } else {
            r.fail(k("type"),
                   fmt::format("unknown shape type '{}' (expected 'sphere' or 'quad')", type));
        }
    }

    // A point, spot or directional light (docs/lights.md).
    void light(const Json& v, const std::string& path) {
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
        check_radiance(l.color, k("color"));
        if (v.contains("inner")) l.inner_degrees = r.number_in(v["inner"], k("inner"), 0, 180);
        if (v.contains("outer")) l.outer_degrees = r.number_in(v["outer"], k("outer"), 0, 180);
        if (l.outer_degrees < l.inner_degrees) r.fail(k("outer"), "must not be smaller than 'inner'");
        scene.punctual_lights.push_back(l);
    }

    // Colours that become radiance: at most FC_MAX_RADIANCE, so the image stays finite.
    void check_radiance(const glm::vec3& c, const std::string& key) {
        for (int i = 0; i < 3; ++i)
            if (!(c[i] <= FC_MAX_RADIANCE))
                r.fail(key, fmt::format("must be at most {:g} (got {:g}): the image would overflow", FC_MAX_RADIANCE, c[i]));
    }

    // The environment: a map file, a constant radiance or the generated sun and sky
    // (docs/environment.md), with a radiance scale and a rotation.
    void environment(const Json& v, const std::string& path) {
        r.object(v, path, {"file", "constant", "sky", "scale", "rotate"});
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
            check_radiance(constant, k("constant"));
            scene.environment = constant_environment(constant);
        } else if (v.contains("file")) {
            const std::string file = r.string(v["file"], k("file"));
            const std::string full = text::join_path(dir, file);
            std::error_code ec;
            if (!std::filesystem::exists(full, ec))   // a non-regular one: the reader says so
                r.fail(k("file"), fmt::format("environment map '{}' not found (looked for '{}')", file, full));
            try {
                scene.environment = load_environment_map(full, scale, world_to_map, scene.warnings);
            } catch (const Error& e) {
                r.fail(k("file"), e.what());
            }
        } else {
            const Json& sky = v["sky"];
            const std::string sp = k("sky");
            r.object(sky, sp, {"elevation", "azimuth", "turbidity", "width"});
            SunSkyParams params;
            if (sky.contains("elevation")) params.elevation_degrees = double(r.number_in(sky["elevation"], JsonReader::key(sp, "elevation"), -10, 90));
            if (sky.contains("azimuth")) params.azimuth_degrees = double(r.number_in(sky["azimuth"], JsonReader::key(sp, "azimuth"), -360, 360));
            if (sky.contains("turbidity")) params.turbidity = double(r.number_in(sky["turbidity"], JsonReader::key(sp, "turbidity"), 1.7, 10));
            int width = 1024;
            if (sky.contains("width")) width = int(r.integer(sky["width"], JsonReader::key(sp, "width"), 8, 16384));
            scene.environment = sun_sky_environment(params, width);
            set_environment_scale(scene.environment, scale);
        }
        set_environment_rotation(scene.environment, world_to_map);
    }

    template <typename F>
    void array(const Json& root, const char* name, F each) {
        if (!root.contains(name)) return;
        const Json& a = root[name];
        if (!a.is_array()) r.fail(name, "expected an array");
        for (std::size_t i = 0; i < a.size(); ++i) each(a[i], JsonReader::index(name, i));
    }
};

}  // namespace

bool load_json_scene(const std::string& path, Scene& scene) {
    const std::string content = text::read_file(path, "scene file");
    const Json root = parse_json(path, content);
    for (std::string& w : duplicate_json_keys(path, content)) scene.warnings.push_back(std::move(w));
    Loader l{JsonReader(path), text::directory_of(path), scene, {}, -1};
    l.r.object(root, "", {"camera", "render", "materials", "meshes", "shapes", "lights", "environment"});
    if (root.contains("render")) l.render(root["render"], "render");
    if (root.contains("materials")) {
        const Json& mats = root["materials"];
        if (!mats.is_object()) l.r.fail("materials", "expected an object {\"name\": {...}}");
        for (const auto& item : mats.items()) {
            l.material(item.key(), item.value(), JsonReader::key("materials", item.key()));
        }
    }
    l.array(root, "meshes", [&](const Json& v, const std::string& p) { l.mesh(v, p); });
    l.array(root, "shapes", [&](const Json& v, const std::string& p) { l.shape(v, p); });
    l.array(root, "lights", [&](const Json& v, const std::string& p) { l.light(v, p); });
    if (root.contains("environment")) l.environment(root["environment"], "environment");
    if (scene.triangle_count() == 0) {
        throw Error(fmt::format("{}: the scene has no geometry (no 'meshes' or 'shapes')", path));
    }
    const bool has_camera = root.contains("camera");
    if (has_camera) l.camera(root["camera"], "camera");
    return has_camera;
}

}  // namespace facet
