// `facet render --denoise`: the film at the end denoised and written beside the image.
#include <fmt/format.h>

#include "host/cli/render_parts.hpp"
#include "host/error.hpp"
#include "host/util/console.hpp"
#include "host/util/strings.hpp"

namespace facet {

bool write_denoised(const RenderJob& job, const ImageMetadata& extra) {
    try {
        if (job.opt.denoise == "oidn")
            throw Error("--denoise oidn: Intel Open Image Denoise is not supported by this build");
        const DenoisedImage d = job.session.denoised();
        ImageMetadata meta = extra;
        meta.strings.push_back({"facet:denoiser", "facet"});
        write_image(job, job.plan.denoised, d.rgb, true, meta);
        if (!job.opt.quiet)
            say(stdout, "denoised {} and {} (facet's denoiser, {:.2f} s)\n", job.plan.denoised, job.plan.denoised_png,
                d.seconds);
        return true;
    } catch (const Error& e) {
        say(stderr, "facet: error: {}\n", e.what());
        return false;
    }
}

}  // namespace facet
