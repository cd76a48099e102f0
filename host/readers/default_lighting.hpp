// How a bare model (OBJ, PLY, glTF) is lit when its file brings no light, and the
// command line's choice of environment (`facet render --env`, docs/scene-format.md,
// "Bare meshes").
//
// A model with no emitters, punctual lights or environment gets a key light (a two-sided
// emissive square above and in front of it) and a uniform white environment of radiance
// kDefaultEnvironmentRadiance, so that it reads from every side: a default (0.8 grey)
// Lambertian surface open to that environment alone has radiance 0.8 x 0.5 = 0.4, so the
// side away from the key light is mid grey against a lighter grey background (0.5), not a
// silhouette, while the faces towards the key light reach white.
#pragma once

#include <optional>
#include <string>

#include "host/scene/scene.hpp"

namespace facet {

constexpr float kDefaultEnvironmentRadiance = 0.5f;
// The generated sky is in physical units (kcd/m^2: a sunlit white surface has radiance
// about 25); --env sky scales it by this unless --env-strength is given, which brings such
// a surface near 1 (as --exposure -5 would).
constexpr float kDefaultSkyStrength = 1.0f / 32.0f;

// Whether some triangle's material emits.
bool has_emitter(const Scene& scene);

// Adds the key light and the white environment when the scene has no emitter, punctual
// light or environment, and records what was added in scene.lighting_note; notes
// (without adding anything) a scene whose only light is emissive geometry. Call before
// build_lights.
void add_default_lighting(Scene& scene);

// --env SOURCE (an .exr or .hdr file, sky, white or none), --env-rotation DEGREES (about
// the vertical +y axis) and --env-strength X: replaces the scene's environment (none
// removes it) and rebuilds the lights. Warnings go to scene.warnings; throws facet::Error
// on an unknown source or an unreadable file.
struct EnvironmentChoice {
    std::string source;  // "" keeps the scene's
    std::optional<float> rotation_degrees, strength;
};
void apply_environment_choice(const EnvironmentChoice& choice, Scene& scene);

}  // namespace facet
