#include "host/readers/default_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/error.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/sky.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

// The key light: a two-sided emissive square of side 2r (r the radius of the bounding
// sphere) centred at centre + r * (2 up + h), h the horizontal direction towards the
// camera (+z for a camera straight above or below), i.e. above the model and on the
// camera's side, turned to face the centre, emitting radiance 4 (white). From the framed
// camera (frame_camera) it lies above the top of the image. A white Lambertian surface facing it receives about
// 0.8 x 4 x (solid angle) and so looks roughly mid-grey to white.
void add_key_light(Scene& scene) {
    const Bounds bounds = scene_bounds(scene);
    const glm::vec3 center = bounds.center();
    float r = bounds.radius();
    if (!(r > 0.0f)) r = 1.0f;
    glm::vec3 h = scene.camera.eye - scene.camera.target;
    h.y = 0.0f;
    h = glm::length(h) > 0.0f ? glm::normalize(h) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 p = center + r * (glm::vec3(0.0f, 2.0f, 0.0f) + h);
    const glm::vec3 w = glm::normalize(center - p);                                  // facing the model
    const glm::vec3 v = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), h));  // horizontal, across w
    glm::vec3 u = glm::normalize(glm::cross(w, v));
    if (glm::dot(glm::cross(u, v), w) < 0.0f) u = -u;  // cross(e1, e2) along w
    Material m = default_material();
    m.diffuse = glm::vec3(0.0f);
    m.emission = glm::vec3(4.0f);
    m.two_sided_emission = true;
    const int material = add_material(scene, m, "default_light");
    add_quad(scene, p - r * u - r * v, 2.0f * r * u, 2.0f * r * v, material);
}

bool has_environment(const Scene& scene) {
    return scene.environment.params.width > 0 || scene.environment.mean_luminance > 0.0;
}

}  // namespace

bool has_emitter(const Scene& scene) {
    for (const FcTriShading& sh : scene.shading) {
        const Material& m = scene.materials[static_cast<std::size_t>(sh.material)];
        if (m.emission[0] > 0.0f || m.emission[1] > 0.0f || m.emission[2] > 0.0f) return true;
    }
    return false;
}

void add_default_lighting(Scene& scene) {
    if (!scene.punctual_lights.empty() || has_environment(scene)) return;
    if (has_emitter(scene)) {
        scene.lighting_note =
            "the file's only light is its emissive surfaces: if the image is dark, add an environment with "
            "--env white or --env sky";
        return;
    }
    add_key_light(scene);
    scene.environment = constant_environment(glm::vec3(kDefaultEnvironmentRadiance));
    scene.lighting_note = fmt::format(
        "the file has no lights: added a key light above and in front of the model and a uniform white "
        "environment of radiance {:g} (--env FILE.exr|sky|white|none, --env-strength to change it)",
        kDefaultEnvironmentRadiance);
}

void apply_environment_choice(const EnvironmentChoice& choice, Scene& scene) {
    if (choice.source.empty() && !choice.rotation_degrees && !choice.strength) return;
    if (choice.source.empty())
        throw Error("--env-rotation and --env-strength: give the environment they apply to with --env");
    const float strength = choice.strength ? *choice.strength : (choice.source == "sky" ? kDefaultSkyStrength : 1.0f);
    // Map-to-world is a rotation about +y by the given angle; world-to-map its inverse.
    const float angle = glm::radians(choice.rotation_degrees.value_or(0.0f));
    const glm::mat3 world_to_map =
        glm::transpose(glm::mat3(glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0.0f, 1.0f, 0.0f))));
    std::string what;
    if (choice.source == "none") {
        scene.environment = no_environment();
        what = "none (no environment)";
    } else if (choice.source == "white") {
        scene.environment = constant_environment(glm::vec3(strength));
        what = fmt::format("uniform white of radiance {:g}", strength);
    } else if (choice.source == "sky") {
        scene.environment = sun_sky_environment(SunSkyParams{}, 1024);
        set_environment_scale(scene.environment, glm::vec3(strength));
        what = fmt::format("the generated sun and sky (facet sky's defaults) scaled by {:g}", strength);
    } else {
        const std::string ext = lower(std::filesystem::path(choice.source).extension().string());
        if (ext != ".exr" && ext != ".hdr")
            throw Error(
                fmt::format("--env {}: expected an .exr or .hdr environment map, sky, white or none", choice.source));
        if (std::error_code ec; !std::filesystem::is_regular_file(choice.source, ec))
            throw Error(fmt::format("--env {}: no such file", choice.source));
        scene.environment = load_environment_map(choice.source, glm::vec3(strength), world_to_map, scene.warnings);
        what = fmt::format("the map {} scaled by {:g}", choice.source, strength);
    }
    set_environment_rotation(scene.environment, world_to_map);
    if (choice.rotation_degrees) what += fmt::format(", turned {:g} degrees about +y", *choice.rotation_degrees);
    const bool key = std::find(scene.material_names.begin(), scene.material_names.end(), "default_light") !=
                     scene.material_names.end();
    scene.lighting_note = (key ? "the file has no lights: added a key light above and in front of the model; " : "") +
                          ("environment: " + what + " (--env)");
    build_lights(scene);
    // load_scene's warning of a scene without lights, redone for the new environment.
    const std::string black = "the scene has no emitters; the image will be black";
    std::erase_if(scene.warnings, [&](const std::string& w) { return w.ends_with(black); });
    if (scene.lights.empty()) scene.warnings.push_back(fmt::format("{}: {}", scene.source_path, black));
}

}  // namespace facet
