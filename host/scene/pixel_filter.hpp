// The pixel reconstruction filters (kernels/camera/filter.cl): one list of their
// names, kernel codes and default radii, for the scene file's "filter" key and
// --filter. Radii are in pixels.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "kernels/shared/render_layout.h"

namespace facet {

struct PixelFilterInfo {
    int code;              // FC_FILTER_*
    const char* name;      // in the scene file and on the command line
    float default_radius;  // pixels
    const char* words;     // for --help and the docs
};

inline constexpr std::array<PixelFilterInfo, 4> kPixelFilters{{
    {FC_FILTER_BOX, "box", 0.5f, "box (uniform over the pixel at radius 0.5)"},
    {FC_FILTER_TENT, "tent", 1.0f, "tent (radius 1: the 1-pixel tent of Tungsten and Mitsuba 3)"},
    {FC_FILTER_GAUSSIAN, "gaussian", 1.5f, "gaussian (truncated, sigma = radius / 3)"},
    {FC_FILTER_MITCHELL, "mitchell", 2.0f, "mitchell (Mitchell-Netravali B = C = 1/3, negative lobes)"},
}};

// The largest filter radius, in pixels.
inline constexpr float kMaxFilterRadius = 16.0f;

inline std::optional<int> pixel_filter_code(std::string_view name) {
    for (const PixelFilterInfo& f : kPixelFilters)
        if (name == f.name) return f.code;
    return std::nullopt;
}

inline const PixelFilterInfo& pixel_filter_info(int code) {
    for (const PixelFilterInfo& f : kPixelFilters)
        if (f.code == code) return f;
    return kPixelFilters[0];
}

// "box, tent, gaussian or mitchell", for messages.
inline std::string pixel_filter_names() {
    std::string out;
    for (std::size_t i = 0; i < kPixelFilters.size(); ++i) {
        if (i > 0) out += i + 1 == kPixelFilters.size() ? " or " : ", ";
        out += kPixelFilters[i].name;
    }
    return out;
}

// The radius a render uses: the given one, or the filter's default when 0.
inline float pixel_filter_radius(int code, float radius) {
    return radius > 0.0f ? radius : pixel_filter_info(code).default_radius;
}

}  // namespace facet
