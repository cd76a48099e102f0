#include "host/image/tonemap.hpp"

#include <algorithm>
#include <cmath>

namespace facet {
namespace {

float srgb_encode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// A logistic curve in stops about mid grey: d(s) = 1 / (1 + exp(c - k s)), with
// c = ln(0.539 / 0.461) so that d(0) = 0.461 = srgb_encode(0.18), and k = 0.6 so that
// the slope there, k d (1 - d), is the clip's (0.149 a stop).
float filmic(float linear) {
    constexpr float kMidGrey = 0.18f, kContrast = 0.6f;
    const float c = std::log(0.539f / 0.461f);
    const float stops = std::log2(linear / kMidGrey);
    return 1.0f / (1.0f + std::exp(c - kContrast * stops));
}

}  // namespace

float tonemap_display(ToneMap map, float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also NaN
    if (map == ToneMap::Filmic) return std::isinf(linear) ? 1.0f : filmic(linear);
    return srgb_encode(std::min(linear, 1.0f));
}

const char* tonemap_name(ToneMap map) { return map == ToneMap::Filmic ? "filmic" : "clip"; }

std::optional<ToneMap> tonemap_from_name(std::string_view name) {
    if (name == "clip") return ToneMap::Clip;
    if (name == "filmic") return ToneMap::Filmic;
    return std::nullopt;
}

}  // namespace facet
