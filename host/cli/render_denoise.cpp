// `facet render --denoise`: the film at the end denoised (OIDN or facet's denoiser, as
// asked and found) and written beside the image, its error estimated from the
// half-images (denoise/denoise_error.hpp) and measured against --reference.
#include <fmt/format.h>

#include "host/cli/render_parts.hpp"
#include "host/denoise/denoise_error.hpp"
#include "host/denoise/denoise_choice.hpp"
#include "host/error.hpp"
#include "host/util/console.hpp"

namespace facet {

std::string write_denoised(const RenderJob& job, PassRecord& row, const ImageMetadata& extra, bool announce) {
    try {
        const FilmState film = job.session.film();
        const FilmHalves halves = film_halves(film);
        if (!job.session.aovs()) throw Error("denoise: the render has no AOVs");
        const DenoiseRun d = run_denoiser(
            job.opt.denoise, job.opt.oidn, std::uint32_t(film.width), std::uint32_t(film.height), halves,
            *job.session.aovs(), [&] { return job.session.denoised(); },
            [](const std::string& w) { say(stderr, "facet: warning: {}\n", w); });
        row.denoised_estimate = estimate_denoised_error(halves, d.image);
        if (job.reference) row.denoised_reference = compare_images(d.image.rgb, job.reference->rgb, job.opt.reference);
        ImageMetadata meta = extra;
        meta.strings.push_back({"facet:denoiser", d.denoiser});
        meta.floats.push_back({"facet:denoised_rmse_estimate", float(row.denoised_estimate->rmse)});
        write_image(job, job.plan.denoised, d.image.rgb, true, meta);
        if (announce && !job.opt.quiet) {
            std::string against;
            if (row.denoised_reference)
                against = fmt::format("; against the reference {:.4g}, noisy {:.4g}", row.denoised_reference->rmse,
                                      row.reference ? row.reference->rmse : std::nan(""));
            say(stdout, "denoised {} and {} ({}, {:.2f} s; RMSE ~{:.4g} estimated, noisy ~{:.4g}{})\n",
                job.plan.denoised, job.plan.denoised_png, d.words, d.image.seconds, row.denoised_estimate->rmse,
                row.estimate.rmse, against);
        }
        return d.denoiser;
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        return "";
    }
}

}  // namespace facet
