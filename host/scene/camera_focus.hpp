// Where a thin-lens camera focuses when its scene or command line gives a useless
// distance. A scene whose target is a step ahead of the eye (the Cornell box's is 1 mm)
// focuses there by default, and any aperture then blurs the whole image into a dark
// smear: probe_view() casts a grid of rays through the image on the host, and
// settle_focus() warns of a plane of focus nearer than anything in view or, when that
// plane came from the target, moves it to the surface at the image centre.
#pragma once

#include <optional>

#include "host/scene/scene.hpp"

namespace facet {

// Depths along the view direction (the thin lens's focus distance measures the same) of
// what a perspective camera sees: the nearest over a grid of rays through the image, and
// the surface at the image centre; empty when the rays miss everything.
struct ViewDepths {
    std::optional<float> nearest;
    std::optional<float> centre;
};

// Traces `grid` x `grid` rays from `camera`'s eye through an image of the given aspect
// ratio (width / height), against the scene's triangles, analytic spheres and instances.
ViewDepths probe_view(const Scene& scene, const CameraDesc& camera, float aspect, int grid = 17);

// For a perspective camera with an aperture, judged over the image's central square
// (probe_view with aspect 1, the same for any image size): a focus distance given (by the scene or
// --focus-distance) that is nearer than anything in view gets a warning in
// scene.warnings; one taken from the target (focus_distance 0) that is nearer than
// anything in view becomes the depth at the image centre (else the nearest depth), said
// in scene.warnings. Pinhole and orthographic cameras are left alone.
void settle_focus(Scene& scene);

}  // namespace facet
