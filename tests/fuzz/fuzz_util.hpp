// Shared by the libFuzzer harnesses (tests/fuzz/CMakeLists.txt, docs/robustness.md):
// a private folder on tmpfs for the files a harness writes (facet's loaders read
// files, as users run them, so each input goes through the same path as `facet render`),
// and the invariants every scene that loads without an error must keep.
//
// Outcome of one input: a scene that loads and keeps the invariants, or a facet::Error.
// Anything else is a finding: another exception escapes (std::terminate), a sanitizer
// report, a crash, a hang (-timeout) or too much memory (-rss_limit_mb); a broken
// invariant calls abort() with a message.
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "host/scene/material.hpp"
#include "host/scene/scene.hpp"

namespace facet::fuzz {

// A folder of this process, on /dev/shm when there is one; removed at exit.
struct WorkDir {
    std::string path;
    WorkDir() {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path base = fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0
                                  ? fs::path("/dev/shm")
                                  : fs::temp_directory_path();
        path = (base / ("facet_fuzz_" + std::to_string(::getpid()))).string();
        fs::create_directories(path);
    }
    ~WorkDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

inline const std::string& work_dir() {
    static const WorkDir dir;
    return dir.path;
}

// Writes `bytes` as `name` in work_dir() and returns its path.
inline std::string write_file(const std::string& name, std::string_view bytes) {
    const std::string path = work_dir() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) {
        std::fprintf(stderr, "fuzz harness: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

[[noreturn]] inline void broken(const char* what) {
    std::fprintf(stderr, "fuzz harness: a loaded scene breaks an invariant: %s\n", what);
    std::abort();
}

inline bool finite3(const float v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// What the renderer relies on in every scene load_scene returns.
inline void check_scene(const Scene& s) {
    if (s.vertices.size() != 3 * s.shading.size()) broken("3 vertices a triangle");
    if (s.shading.empty() && s.spheres.empty() && s.instances.empty())
        broken("at least one triangle, sphere or instance");
    for (const FcSphere& sp : s.spheres) {
        if (!finite3(sp.center) || !(sp.radius > 0.0f) || !std::isfinite(sp.radius)) broken("finite spheres");
        if (sp.material < 0 || std::size_t(sp.material) >= s.materials.size()) broken("material index in range");
        if (sp.light >= int(s.lights.size())) broken("light index in range");
    }
    for (const glm::vec3& v : s.vertices)
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) broken("finite vertices");
    for (const FcTriShading& sh : s.shading) {
        if (sh.material < 0 || std::size_t(sh.material) >= s.materials.size()) broken("material index in range");
        if (!finite3(sh.n0) || !finite3(sh.n1) || !finite3(sh.n2)) broken("finite shading normals");
        if (sh.light >= int(s.lights.size())) broken("light index in range");
    }
    if (s.material_names.size() != s.materials.size()) broken("a name per material");
    for (const Material& m : s.materials)
        if (!validate_material(m).empty()) broken(("valid materials: " + validate_material(m)).c_str());
    const RenderSettings& r = s.settings;
    if (r.width < 1 || r.width > 16384 || r.height < 1 || r.height > 16384) broken("image size in [1, 16384]");
    if (r.spp < 1 || r.max_depth < 1 || r.rr_depth < 0) broken("spp, max_depth >= 1, rr_depth >= 0");
    const FcCamera cam = make_camera(s.camera, float(r.width) / float(r.height));
    if (!finite3(cam.eye) || !finite3(cam.forward) || !finite3(cam.right) || !finite3(cam.up)) broken("finite camera");
    if (s.light_cdf.size() != s.lights.size() + 1) broken("a cdf entry per light, plus one");
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        if (!(s.light_cdf[i + 1] >= s.light_cdf[i])) broken("non-decreasing light cdf");
        if (!std::isfinite(s.lights[i].pick_pdf)) broken("finite light pick pdf");
    }
    if (!s.lights.empty() && s.light_cdf.back() != 1.0f) broken("light cdf ends at 1");
    for (const FcLight& l : s.lights) {
        if (!finite3(l.p0) || !finite3(l.e1) || !finite3(l.e2) || !finite3(l.color)) broken("finite lights");
        if ((l.type == FC_LIGHT_SPOT || l.type == FC_LIGHT_DIRECTIONAL) &&
            !(std::fabs(glm::length(glm::vec3(l.e1[0], l.e1[1], l.e1[2])) - 1.0f) < 1e-3f))
            broken("unit spot and directional light directions");
    }
    const EnvironmentMap& e = s.environment;
    for (float t : e.texels)
        if (!std::isfinite(t) || t < 0.0f) broken("finite, non-negative environment texels");
    for (float d : e.distribution)
        if (!std::isfinite(d)) broken("finite environment distribution");
    if (!finite3(e.params.scale) || !std::isfinite(e.params.total)) broken("finite environment scale and total");
    if (e.params.width > 0 && e.texels.size() != 4 * std::size_t(e.params.width) * std::size_t(e.params.height))
        broken("4 floats an environment texel");
}

}  // namespace facet::fuzz
