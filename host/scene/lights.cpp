// The scene's light table: every light, with the probability that next-event
// estimation picks it, in proportion to an estimate of its emitted power:
//   area light       pi * area * luminance(Le) (x 2 when two-sided)
//   sphere light     pi * 4 pi r^2 * luminance(Le) (x 2 when two-sided)
//   point light      4 pi * I, with intensity I = pi * luminance(c)
//   spot light       2 pi (1 - (cos_inner + cos_outer) / 2) * I
//   directional      pi * luminance(c) * pi R^2 (R: the scene's bounding radius)
//   environment      pi * mean luminance * 4 pi R^2 (the flux onto the bounding sphere)
// Only the ratios matter; they steer samples, never the estimate's expectation.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "host/scene/scene.hpp"
#include "host/util/color.hpp"
#include "host/util/math.hpp"
#include "host/util/vec3.hpp"
#include "host/util/wide_vector.hpp"

namespace facet {
namespace {

// The area light of triangle t of material m: edges ordered so that cross(e1, e2) points
// to the side its shading normals face (the emitting side), whose unit normal, emission
// and two-sidedness are stored with it (scene_layout.h).
FcLight triangle_light(const Scene& scene, std::size_t t, float area, const Material& m) {
    const glm::vec3* v = &scene.vertices[3 * t];
    const FcTriShading& sh = scene.shading[t];
    glm::vec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
    const glm::vec3 shading_n = glm::vec3(sh.n0[0], sh.n0[1], sh.n0[2]) + glm::vec3(sh.n1[0], sh.n1[1], sh.n1[2]) +
                                glm::vec3(sh.n2[0], sh.n2[1], sh.n2[2]);
    if (glm::dot(wide_cross(e1, e2), glm::dvec3(shading_n)) < 0.0) std::swap(e1, e2);
    FcLight light{};
    store(light.p0, v[0]);
    store(light.e1, e1);
    store(light.e2, e2);
    light.type = FC_LIGHT_AREA_TRIANGLE;
    light.prim = static_cast<fc_int>(t);
    light.area = area;
    store(light.color, m.emission);
    light.flags = m.two_sided_emission ? FC_MAT_TWO_SIDED_EMISSION : 0u;
    store(light.n, unit_or(wide_cross(e1, e2), glm::vec3(0.0f, 0.0f, 1.0f)));
    return light;
}

// The light of analytic sphere `s` (scene_layout.h says what its fields hold).
FcLight sphere_light(const FcSphere& s, const Material& m) {
    FcLight light{};
    light.type = FC_LIGHT_SPHERE;
    light.prim = s.prim;
    store(light.p0, glm::vec3(s.center[0], s.center[1], s.center[2]));
    light.e1[0] = s.radius;
    light.e1[1] = (s.flags & FC_SPHERE_INWARD) ? -1.0f : 1.0f;
    light.e1[2] = m.two_sided_emission ? 1.0f : 0.0f;
    store(light.color, m.emission);
    light.area = float(4.0 * kPi * double(s.radius) * double(s.radius));
    return light;
}

FcLight punctual_light(const PunctualLight& p, double* power, double radius) {
    FcLight l{};
    l.type = p.type;
    l.prim = -1;
    store(l.p0, p.position);
    store(l.e1, glm::normalize(p.direction));
    store(l.color, p.color);
    l.cos_inner = std::cos(glm::radians(p.inner_degrees));
    l.cos_outer = std::cos(glm::radians(std::max(p.outer_degrees, p.inner_degrees)));
    if (l.cos_outer >= l.cos_inner) l.cos_outer = l.cos_inner - 1e-6f;  // a hard edge
    double intensity = kPi * luminance(p.color);
    if (p.type == FC_LIGHT_DIRECTIONAL) *power = intensity * kPi * radius * radius;
    else if (p.type == FC_LIGHT_SPOT)
        *power = 2.0 * kPi * (1.0 - 0.5 * (double(l.cos_inner) + double(l.cos_outer))) * intensity;
    else *power = 4.0 * kPi * intensity;
    return l;
}

double bounding_radius(const Scene& scene) {
    if (scene.vertices.empty() && scene.spheres.empty() && scene.instances.empty()) return 1.0;
    const double r = double(scene_bounds(scene).radius());
    return r > 0.0 && std::isfinite(r) ? r : 1.0;
}

}  // namespace

void build_lights(Scene& scene) {
    scene.lights.clear();
    scene.environment_light = -1;
    std::vector<double> power;
    for (std::size_t t = 0; t < scene.shading.size(); ++t) {
        FcTriShading& sh = scene.shading[t];
        sh.light = -1;
        if (sh.material < 0 || static_cast<std::size_t>(sh.material) >= scene.materials.size()) continue;
        const Material& m = scene.materials[static_cast<std::size_t>(sh.material)];
        const double lum = luminance(m.emission);
        if (!(lum > 0.0)) continue;
        const glm::vec3* v = &scene.vertices[3 * t];
        const float area = static_cast<float>(triangle_area(v[0], v[1], v[2]));
        if (!(area > 0.0f) || !std::isfinite(area)) continue;
        const double sides = m.two_sided_emission ? 2.0 : 1.0;
        sh.light = static_cast<fc_int>(scene.lights.size());
        scene.lights.push_back(triangle_light(scene, t, area, m));
        power.push_back(kPi * double(area) * lum * sides);
    }
    for (FcSphere& s : scene.spheres) {
        s.light = -1;
        if (s.material < 0 || static_cast<std::size_t>(s.material) >= scene.materials.size()) continue;
        const Material& m = scene.materials[static_cast<std::size_t>(s.material)];
        const double lum = luminance(m.emission);
        if (!(lum > 0.0)) continue;
        FcLight l = sphere_light(s, m);
        if (!(l.area > 0.0f) || !std::isfinite(l.area)) continue;
        s.light = static_cast<fc_int>(scene.lights.size());
        scene.lights.push_back(l);
        power.push_back(kPi * double(l.area) * lum * (m.two_sided_emission ? 2.0 : 1.0));
    }
    const double radius = bounding_radius(scene);
    for (const PunctualLight& p : scene.punctual_lights) {
        double w = 0.0;
        FcLight l = punctual_light(p, &w, radius);
        if (!(w > 0.0) || !std::isfinite(w)) continue;
        scene.lights.push_back(l);
        power.push_back(w);
    }
    if (scene.environment.params.enabled && scene.environment.mean_luminance > 0.0) {
        FcLight l{};
        l.type = FC_LIGHT_ENVIRONMENT;
        l.prim = -1;
        scene.environment_light = static_cast<int>(scene.lights.size());
        scene.lights.push_back(l);
        power.push_back(kPi * scene.environment.mean_luminance * 4.0 * kPi * radius * radius);
    }
    double total = 0.0;
    for (double p : power) total += p;
    // pick_pdf is exactly the cdf step the kernel's binary search selects with.
    scene.light_cdf.assign(1, 0.0f);
    double running = 0.0;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        running += power[i];
        scene.light_cdf.push_back(i + 1 == scene.lights.size() ? 1.0f : static_cast<float>(running / total));
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        scene.lights[i].pick_pdf = scene.light_cdf[i + 1] - scene.light_cdf[i];
}

}  // namespace facet
