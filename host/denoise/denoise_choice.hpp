// Which denoiser runs for --denoise auto|facet|oidn: OIDN for oidn, and for auto when it
// is found (facet's denoiser when it fails there); facet's denoiser for facet and
// otherwise. Used by `facet render --denoise` and `facet denoise`.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "host/denoise/denoiser.hpp"

namespace facet {

struct DenoiseRun {
    DenoisedImage image;
    std::string denoiser;  // "facet" or "oidn"
    std::string words;     // for messages: "facet's denoiser", "Intel Open Image Denoise, <library>"
};

// `asked`: auto, facet or oidn; `oidn_library`: --oidn (may be empty, oidn.hpp: find_oidn);
// `facet_denoiser` runs facet's denoiser; `warn` says why auto fell back. Throws
// facet::Error for oidn when OIDN is not found or fails.
DenoiseRun run_denoiser(const std::string& asked, const std::string& oidn_library, std::uint32_t width,
                        std::uint32_t height, const FilmHalves& halves, const AovImages& features,
                        const std::function<DenoisedImage()>& facet_denoiser,
                        const std::function<void(const std::string&)>& warn);

}  // namespace facet
