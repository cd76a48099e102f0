// Texels held to what the materials read them as, as the scene file's own values are
// (material.hpp: reflectances above 1 clamped with a warning): a float texture (EXR, HDR)
// can hold anything, and a base colour of -1 gave a black image of "dropped" samples, one
// of 100 a hundred times the light, silently.
#pragma once

#include "host/scene/scene.hpp"

namespace facet {

// For every texture a material binds, by what the binding reads (texture_binding.hpp):
// - base colour and specular colour (reflectances), roughness and metalness (fractions):
//   each channel clamped to 0..1;
// - emission (a multiplier of the material's emission): negatives raised to 0;
// - normal maps (tangent-space n = 2 v - 1): clamped to 0..1 and, where the vector is
//   more than 10 % off unit length (beyond 8-bit quantisation), renormalised (a zero
//   vector becomes the unperturbed normal).
// A texture bound in several roles meets all of their rules. The mip levels are rebuilt
// from the sanitised texels, and each texture changed gets one warning in
// scene.warnings naming its file, how many texels changed and their range.
void sanitise_textures(Scene& scene);

}  // namespace facet
