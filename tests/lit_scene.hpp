// A diffuse box lit by an emitting quad, with a sphere inside: noisy enough that sample
// indices matter (the film, merge and device tests tell sample ranges apart with it).
#pragma once

#include "host/scene/scene.hpp"

namespace facet::test {

inline Scene lit_scene(int size) {
    Scene scene;
    Material white = default_material();
    white.diffuse = glm::vec3(0.7f);
    Material light = default_material();
    light.emission = glm::vec3(5.0f);
    int w = add_material(scene, white, "white");
    int l = add_material(scene, light, "light");
    add_sphere(scene, glm::vec3(0.0f), 2.0f, 2, w, /*inward=*/true);
    add_quad(scene, glm::vec3(-0.3f, 1.5f, -0.3f), glm::vec3(0.6f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 0.6f), l);
    add_sphere(scene, glm::vec3(0.3f, -0.5f, 0.0f), 0.4f, 2, w, /*inward=*/false);
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 1.5f);
    scene.camera.target = glm::vec3(0.0f);
    scene.settings.width = size;
    scene.settings.height = size;
    scene.settings.max_depth = 8;
    scene.source_path = "lit_scene";
    return scene;
}

}  // namespace facet::test
