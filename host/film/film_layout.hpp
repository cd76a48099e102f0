// The accumulation buffer as the kernel holds it (kernels/integrator/path.cl: render_pass)
// and a film stores it (docs/film-format.md), for an image of `pixels` pixels:
//   [0, 8 pixels)            two images of RGBA float sums: the even-indexed samples of
//                            each pixel, then the odd ones; A counts rejected samples
//   [8 pixels, 10 pixels)    the second moments: per pixel and half, the sum over the
//                            half's samples of r^2 + g^2 + b^2, even half first
// Each half's own variance comes from its sums and second moments, without reading the
// other half (host/denoise/denoise_variance.hpp). Every consumer sums the buffers of
// devices, ranks and films value by value, so the layout is one flat float array.
#pragma once

#include <cstddef>

namespace facet {

// Floats in the RGBA sums of both halves.
constexpr std::size_t film_rgba_floats(std::size_t pixels) { return 2 * pixels * 4; }
// Floats in the whole buffer: the RGBA sums, then the second moments.
constexpr std::size_t film_floats(std::size_t pixels) { return film_rgba_floats(pixels) + 2 * pixels; }

}  // namespace facet
