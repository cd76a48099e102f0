// Small helpers several test files share.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "host/error.hpp"
#include "host/render/renderer.hpp"

namespace facet::test {

// The message of the facet::Error that `f` throws; empty when it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// Per pixel and channel, a render's estimate (the mean of its two halves) and that
// estimate's variance, estimated from the halves: E[(h0 - h1)^2] / 4.
struct PixelEstimates {
    std::vector<double> mean, var;
};
inline PixelEstimates pixel_estimates(const Renderer::Halves& h) {
    PixelEstimates out;
    for (std::size_t i = 0; i < h.rgb[0].size(); ++i) {
        const double a = double(h.rgb[0][i]), b = double(h.rgb[1][i]);
        out.mean.push_back(0.5 * (a + b));
        out.var.push_back(0.25 * (a - b) * (a - b));
    }
    return out;
}

}  // namespace facet::test
