#include "host/denoise/denoise_choice.hpp"

#include <fmt/format.h>

#include "host/denoise/oidn.hpp"
#include "host/error.hpp"

namespace facet {

DenoiseRun run_denoiser(const std::string& asked, const std::string& oidn_library, std::uint32_t width,
                        std::uint32_t height, const FilmHalves& halves, const AovImages& features,
                        const std::function<DenoisedImage()>& facet_denoiser,
                        const std::function<void(const std::string&)>& warn) {
    if (asked != "facet") {
        std::string looked;
        const std::string library = find_oidn(oidn_library, &looked);
        if (library.empty() && asked == "oidn")
            throw Error(
                fmt::format("--denoise oidn: Intel Open Image Denoise not found (looked at {}); give --oidn LIBRARY or "
                            "`pip install pyoidn`",
                            looked));
        if (!library.empty()) {
            try {
                return {denoise_oidn(library, width, height, halves, features), "oidn",
                        fmt::format("Intel Open Image Denoise, {}", library)};
            } catch (const Error& e) {
                if (asked == "oidn") throw;
                warn(fmt::format("{}; denoising with facet's denoiser instead", e.what()));
            }
        }
    }
    return {facet_denoiser(), "facet", "facet's denoiser"};
}

}  // namespace facet
