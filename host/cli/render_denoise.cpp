// `facet render --denoise`: the film at the end denoised and written beside the image,
// its error estimated from the half-images (denoise/denoise_error.hpp) and measured
// against --reference.
#include <fmt/format.h>

#include "host/cli/render_parts.hpp"
#include "host/denoise/denoise_error.hpp"
#include "host/error.hpp"
#include "host/util/console.hpp"

namespace facet {

std::string write_denoised(const RenderJob& job, PassRecord& row, const ImageMetadata& extra) {
    try {
        if (job.opt.denoise == "oidn")
            throw Error("--denoise oidn: Intel Open Image Denoise is not supported by this build");
        const DenoisedImage d = job.session.denoised();
        const FilmState film = job.session.film();
        const FilmHalves halves =
            film_halves(film.sums, std::size_t(film.width) * std::size_t(film.height), film.samples);
        row.denoised_estimate = estimate_denoised_error(halves, d);
        if (job.reference) row.denoised_reference = compare_images(d.rgb, job.reference->rgb, job.opt.reference);
        ImageMetadata meta = extra;
        meta.strings.push_back({"facet:denoiser", "facet"});
        meta.floats.push_back({"facet:denoised_rmse_estimate", float(row.denoised_estimate->rmse)});
        write_image(job, job.plan.denoised, d.rgb, true, meta);
        if (!job.opt.quiet) {
            std::string against;
            if (row.denoised_reference)
                against = fmt::format("; against the reference {:.4g}, noisy {:.4g}", row.denoised_reference->rmse,
                                      row.reference ? row.reference->rmse : std::nan(""));
            say(stdout, "denoised {} and {} (facet's denoiser, {:.2f} s; RMSE ~{:.4g} estimated, noisy ~{:.4g}{})\n",
                job.plan.denoised, job.plan.denoised_png, d.seconds, row.denoised_estimate->rmse, row.estimate.rmse,
                against);
        }
        return "facet";
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        return "";
    }
}

}  // namespace facet
