// `facet render`: the command line applied to the scene and to the session's options.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/util/console.hpp"
#include "host/cli/render_parts.hpp"
#include "host/error.hpp"
#include "host/readers/default_lighting.hpp"
#include "host/scene/smooth_normals.hpp"
#include "host/util/strings.hpp"

namespace facet {

double RenderJob::since_start() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void apply_overrides(const RenderOptions& opt, Scene& scene) {
    RenderSettings& s = scene.settings;
    if (opt.spp) s.spp = *opt.spp;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.max_depth) s.max_depth = *opt.max_depth;
    if (opt.seed) s.seed = *opt.seed;
    if (opt.strategy) s.strategy = *opt.strategy;
    if (opt.sampler) s.sampler = *opt.sampler;
    if (opt.env_plain)
        scene.environment.sampling =
            *opt.env_plain != 0 ? EnvironmentSampling::plain : EnvironmentSampling::compensated;
    apply_environment_choice({opt.env, opt.env_rotation, opt.env_strength}, scene);
    if (opt.smooth_normals) smooth_normals(scene, *opt.smooth_normals);
    if (opt.filter) s.filter = *opt.filter;
    if (opt.filter_radius) s.filter_radius = *opt.filter_radius;
    if (opt.clamp) s.clamp = *opt.clamp;
    if (opt.caustic_guide) s.caustic_guide = *opt.caustic_guide;
    if (opt.roulette_gain) s.roulette_gain = *opt.roulette_gain;
    CameraDesc& c = scene.camera;
    auto vec = [](const std::vector<float>& v) { return glm::vec3(v[0], v[1], v[2]); };
    if (opt.eye.size() == 3) c.eye = vec(opt.eye);
    if (opt.target.size() == 3) c.target = vec(opt.target);
    if (opt.up.size() == 3) c.up = vec(opt.up);
    if (opt.fov) c.fov_y_degrees = *opt.fov;
    if (opt.aperture) c.aperture = *opt.aperture;
    if (opt.focus_distance) c.focus_distance = *opt.focus_distance;
    const glm::vec3 forward = c.target - c.eye;
    if (!(glm::length(forward) > 0.0f) || !std::isfinite(glm::length(forward)))
        throw Error("--eye and --target: the camera needs two distinct points at a finite distance");
    if (!(glm::length(glm::cross(glm::normalize(forward), c.up)) > 1e-6f))
        throw Error("--up: must be non-zero and not parallel to the view direction (--target minus --eye)");
}

void check_render_options(const RenderOptions& opt, const OutputPlan& plan) {
    if (opt.adaptive_tiles() && (!opt.film.empty() || !opt.resume.empty()))
        throw Error(
            "--adaptive tiles: its bands of rows hold different sample counts, which a film cannot hold: "
            "no --film or --resume");
    if (opt.adaptive_tiles() && opt.denoise != "none")
        throw Error("--denoise: the denoiser reads the film's two half-images, which --adaptive tiles does not keep");
    if (!opt.aov.empty() && lower(std::filesystem::path(plan.image).extension().string()) != ".exr")
        throw Error(fmt::format("--aov: the layers go into the EXR, but --out {} is not one", plan.image));
    for (std::size_t i = 0; i < opt.aov.size(); ++i)
        if (std::find(opt.aov.begin(), opt.aov.begin() + std::ptrdiff_t(i), opt.aov[i]) !=
            opt.aov.begin() + std::ptrdiff_t(i))
            throw Error(
                fmt::format("--aov: {} is named twice (each layer once: its channels would repeat)", opt.aov[i]));
}

SessionOptions session_options(const RenderOptions& opt, std::chrono::steady_clock::time_point start) {
    SessionOptions s;
    if (opt.spp) s.stop.spp = std::uint64_t(*opt.spp);
    s.stop.time_limit_s = opt.time_limit;
    s.stop.noise_threshold = opt.noise_threshold;
    s.stop.adaptive = opt.adaptive_tiles() ? AdaptiveMode::tiles : AdaptiveMode::global;
    s.device = opt.device;
    s.generic = opt.generic;
    s.samples_from = opt.samples_from;
    s.aovs = !opt.aov.empty();
    s.denoise = opt.denoise != "none";
    if (!opt.resume.empty()) s.resume = read_film(opt.resume);
    s.resume_path = opt.resume;
    s.start = start;
    s.warn = [](const std::string& w) { say(stderr, "facet: warning: {}\n", w); };
    return s;
}

std::vector<ImageLayer> aov_layers(const RenderOptions& opt, const std::optional<AovImages>& aovs) {
    std::vector<ImageLayer> layers;
    if (!aovs) return layers;
    for (const std::string& name : opt.aov) {
        if (name == "albedo") layers.push_back({"albedo", {"R", "G", "B"}, aovs->albedo});
        else if (name == "normal") layers.push_back({"normal", {"X", "Y", "Z"}, aovs->normal});
        else if (name == "depth") layers.push_back({"depth", {"Z"}, aovs->depth});
    }
    return layers;
}

}  // namespace facet
