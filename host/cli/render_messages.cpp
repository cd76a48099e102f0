// `facet render`: what it prints before and after the session, and the report's summary.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/util/console.hpp"
#include "host/cli/render_parts.hpp"
#include "host/render/features.hpp"
#include "host/scene/pixel_filter.hpp"
#include "host/util/strings.hpp"
#include "host/scene/render_names.hpp"

namespace facet {
namespace {

// The camera line: where it is and what it sees, and, for a bare OBJ, that the camera
// was framed; then the light added to a bare model or chosen with --env
// (default_lighting.hpp), with how to choose.
std::string describe_camera(const RenderOptions& opt, const Scene& scene) {
    const CameraDesc& c = scene.camera;
    std::string line = fmt::format("camera   eye ({:g}, {:g}, {:g}), target ({:g}, {:g}, {:g}), ", c.eye.x, c.eye.y,
                                   c.eye.z, c.target.x, c.target.y, c.target.z);
    line += c.projection == FC_PROJECTION_ORTHOGRAPHIC ? fmt::format("orthographic, height {:g}", c.ortho_height)
                                                       : fmt::format("fov {:g} degrees", c.fov_y_degrees);
    if (c.projection == FC_PROJECTION_PERSPECTIVE && c.aperture > 0.0f)
        line += fmt::format(", lens radius {:g} focused at {:g}", c.aperture,
                            c.focus_distance > 0.0f ? c.focus_distance : glm::length(c.target - c.eye));
    if (!scene.camera_note.empty() && opt.eye.empty() && opt.target.empty())
        line += fmt::format(" ({}: --eye, --target to choose)", scene.camera_note);
    line += "\n";
    if (!scene.lighting_note.empty()) line += "light    " + scene.lighting_note + "\n";
    if (opt.smooth_normals) line += "normals  " + scene.normal_sources.back() + "\n";  // smooth_normals.hpp
    return line;
}

// Each rank's and device's share and speed, when there are several.
void print_device_shares(const DeviceGroup& group) {
    const std::vector<std::uint64_t>& ranks = group.rank_pixel_samples();
    if (ranks.size() > 1) {
        double all = 0.0;
        for (std::uint64_t n : ranks) all += double(n);
        for (std::size_t r = 0; r < ranks.size(); ++r)
            say(stdout, "rank     {}: {:.1f}% of the samples\n", r, all > 0.0 ? 100.0 * double(ranks[r]) / all : 0.0);
        say(stdout, "reduce   {:.3f} s summing the ranks' films to rank 0\n", group.reduce_seconds());
    }
    if (group.devices().size() < 2) return;
    double total = 0.0;
    for (const DeviceShare& d : group.devices()) total += double(d.pixel_samples);
    for (const DeviceShare& d : group.devices())
        say(stdout, "share    [{}] {}: {:.1f}% of the samples, {:.3f} Msamples/s{}\n", d.desc.index, d.desc.name,
            total > 0.0 ? 100.0 * double(d.pixel_samples) / total : 0.0, d.samples_per_s() * 1e-6,
            d.dropped ? " (dropped: failed)" : "");
}

ReportSummary summarise(const RenderJob& job, const SessionOutcome& outcome, std::uint64_t final_spp, double rejected) {
    const RenderOptions& opt = job.opt;
    const RenderSettings& s = job.scene.settings;
    const DeviceGroup& group = job.session.group();
    ReportSummary summary;
    summary.scene = job.scene.source_path;
    summary.device = group.description();
    summary.image = job.plan.image;
    summary.reference = opt.reference;
    summary.spp = final_spp;
    summary.width = group.width();
    summary.height = group.height();
    summary.wall_s = job.since_start();
    summary.render_s = group.stats().render_seconds;
    summary.compile_s = job.session.compile_seconds();
    summary.interrupted = outcome.interrupted;
    summary.rejected_samples = rejected;
    summary.stratified = s.sampler == FC_SAMPLER_SOBOL;
    summary.sampler = setting_name(kSamplerNames, s.sampler);
    summary.filter = pixel_filter_info(s.filter).name;
    summary.filter_radius = pixel_filter_radius(s.filter, s.filter_radius);
    summary.clamp = s.clamp;
    if (job.reference) summary.reference_spp = job.reference->spp;
    summary.noise_threshold = opt.noise_threshold.value_or(0.0);
    summary.converged = outcome.converged;
    summary.adaptive = !opt.noise_threshold ? "" : outcome.tiles ? "tiles" : "global";
    return summary;
}

}  // namespace

void print_header(const RenderJob& job) {
    const Scene& scene = job.scene;
    const DeviceGroup& group = job.session.group();
    const Bvh& bvh = job.session.bvh();
    if (const std::optional<AovImages>& aovs = job.session.aovs())
        say(stdout, "aovs     {} ({} spp) in {:.2f} s\n", name_list(job.opt.aov), job.session.aov_spp(), aovs->seconds);
    for (const DeviceShare& d : group.devices())
        if (!d.dropped) say(stdout, "device   [{}] {} / {}\n", d.desc.index, d.desc.platform, d.desc.name);
    say(stdout, "scene    {}: {} triangles, {}{} lights; BVH {} nodes in {:.3f} s\n", scene.source_path,
        scene.triangle_count(), scene.spheres.empty() ? "" : fmt::format("{} spheres, ", scene.spheres.size()),
        scene.lights.size(), bvh.stats.nodes, bvh.stats.build_seconds);
    say(stdout, "kernels  {} program ({}{}), built in {:.2f} s\n", job.opt.generic ? "generic" : "specialised",
        describe_features(group.stats().features),
        group.stats().packet_paths ? fmt::format("; paths in packets of {}", group.stats().packet_width)
                                   : std::string(),
        group.stats().compile_seconds);
    if (!job.opt.resume.empty())
        say(stdout, "resumed  {} spp from {}\n", group.stats().samples_per_pixel, job.opt.resume);
    say(stdout, "{}", describe_camera(job.opt, scene));
}

int finish_render(const RenderJob& job, const SessionOutcome& outcome, std::vector<PassRecord>& passes,
                  FilmOnError& film_on_error) {
    const RenderOptions& opt = job.opt;
    const std::string& out = job.plan.image;
    if (outcome.spp == 0) {
        say(stderr, "facet: interrupted before the first pass finished; nothing written\n");
        return kExitInterrupted;
    }
    if (outcome.interrupted)
        say(stderr,
            "facet: interrupted; writing the {} spp finished so far (further Ctrl-C is ignored until written)\n",
            outcome.spp);
    double rejected = 0.0;
    const std::vector<float> rgb = job.session.image(&rejected);
    ImageMetadata extra;
    const std::uint64_t final_spp = outcome.tiles ? std::uint64_t(outcome.mean_spp + 0.5) : outcome.spp;
    if (outcome.tiles) {
        // facet:spp stays the fewest samples of any pixel (the uniform passes).
        const std::vector<std::uint64_t>& bands = outcome.tiles->layout.spp;
        extra.strings.push_back({"facet:adaptive", "tiles"});
        extra.floats.push_back({"facet:mean_spp", float(outcome.mean_spp)});
        extra.ints.push_back({"facet:max_spp", int(*std::max_element(bands.begin(), bands.end()))});
    }
    bool written = write_final(job, rgb, outcome.interrupted, extra);
    std::string denoiser;
    if (!job.plan.denoised.empty() && !passes.empty()) {
        denoiser = write_denoised(job, passes.back(), extra);
        written = written && !denoiser.empty();
    }
    film_on_error.disarm();
    ReportSummary summary = summarise(job, outcome, final_spp, rejected);
    summary.denoiser = denoiser;
    fit_convergence(passes, summary);
    write_report_csv(job.plan.report, passes);
    write_report_json(job.plan.report_json, summary, passes);
    write_report_svg(job.plan.report_svg, passes, job.scene.source_path);
    if (!written) return kExitError;

    const double render_s = job.session.group().stats().render_seconds;
    if (outcome.interrupted) say(stderr, "facet: interrupted; wrote the {} spp finished so far\n", outcome.spp);
    if (summary.converged && !opt.quiet)
        say(stdout, "adaptive the error estimate (relMSE {:.3g}) reached --noise-threshold {} at {} spp{}\n",
            passes.back().estimate.relmse, *opt.noise_threshold, final_spp,
            outcome.tiles ? fmt::format(" (mean; every band of {} rows below it)", outcome.tiles->layout.band_rows)
                          : "");
    else if (opt.noise_threshold && !summary.converged && !opt.quiet && !passes.empty() &&
             !std::isfinite(passes.back().estimate.relmse))
        say(stdout,
            "adaptive no estimate: the error estimate needs at least 2 samples per pixel; --noise-threshold {} not "
            "reached at {} spp\n",
            *opt.noise_threshold, final_spp);
    if (std::none_of(rgb.begin(), rgb.end(), [](float v) { return v != 0.0f; }))
        say(stderr,
            "facet: warning: the image is black: no light reaches the camera (no emitters in view or lighting "
            "the visible surfaces; for an OBJ, --eye and --target choose another view)\n");
    if (rejected > 0)
        say(stderr, "facet: warning: {} samples were NaN, infinite or negative and were dropped\n", rejected);
    if (!summary.slope_warning.empty()) say(stderr, "facet: warning: {}\n", summary.slope_warning);
    say(stdout, "wrote    {} and {} ({} spp{}, {:.2f} s rendering, {:.2f} s in all)\n", out,
        replace_extension(out, ".png"), final_spp, outcome.tiles ? " mean" : "", render_s, job.since_start());
    if (!opt.quiet) print_device_shares(job.session.group());
    if (!opt.quiet) {
        if (std::isfinite(summary.slope))
            say(stdout, "report   {} (+ .json, .svg); RMSE ~ time^{:.2f} ({}{})\n", job.plan.report, summary.slope,
                summary.slope_source, summary.slope_judged ? "" : ", too short a run to judge");
        else
            say(stdout, "report   {} (+ .json, .svg); the run was too short to fit a convergence rate\n",
                job.plan.report);
    }
    return outcome.interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace facet
