// `facet compare IMAGE REFERENCE`: error metrics of an image against a reference.
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/image/image_io.hpp"

namespace facet {

int run_compare(const CompareOptions& opt) {
    ImageRGB a = read_image(opt.image);
    ImageRGB b = read_image(opt.reference);
    if (a.width != b.width || a.height != b.height)
        throw Error(
            fmt::format("{} is {}x{} but {} is {}x{}", opt.image, a.width, a.height, opt.reference, b.width, b.height));
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        if (!std::isfinite(a.rgb[i]))
            throw Error(fmt::format("{}: texel {} (pixel {}) is not finite", opt.image, i % 3, i / 3));
    ErrorMetrics m = compare_images(a.rgb, b.rgb, opt.reference);
    for (const auto& [path, img] : {std::pair{opt.image, &a}, std::pair{opt.reference, &b}}) {
        double mean[3] = {0, 0, 0};
        for (std::size_t i = 0; i < img->rgb.size(); ++i) mean[i % 3] += double(img->rgb[i]);
        const double n = double(img->rgb.size() / 3);
        fmt::print("{}: {}x{}{}, mean ({:.6g}, {:.6g}, {:.6g})\n", path, img->width, img->height,
                   img->spp >= 0 ? fmt::format(", {} spp", img->spp) : std::string(), mean[0] / n, mean[1] / n,
                   mean[2] / n);
    }
    fmt::print("mse     {:.6e}\nrmse    {:.6e}\nrelmse  {:.6e}\n", m.mse, m.rmse, m.relmse);
    return kExitOk;
}

}  // namespace facet
