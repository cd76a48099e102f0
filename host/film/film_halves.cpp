#include "host/film/film_halves.hpp"

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/film/film_layout.hpp"

namespace facet {

FilmHalves film_halves(const std::vector<float>& sums, std::size_t pixels, const SampleRanges& samples,
                       bool second_moments) {
    if (sums.size() != film_floats(pixels))
        throw Error(fmt::format("a film of {} values does not hold {} pixels", sums.size(), pixels));
    FilmHalves h;
    h.samples[0] = even_samples(samples);
    h.samples[1] = odd_samples(samples);
    for (int k = 0; k < 2; ++k) {
        h.rgb[k].resize(3 * pixels);
        const float inv = h.samples[k] ? 1.0f / float(h.samples[k]) : 0.0f;
        const float* half = sums.data() + std::size_t(k) * pixels * 4;
        for (std::size_t i = 0; i < pixels; ++i) {
            for (int c = 0; c < 3; ++c) h.rgb[k][3 * i + c] = half[4 * i + c] * inv;
            h.rejected += double(half[4 * i + 3]);
        }
        if (!second_moments) continue;
        const float* squares = sums.data() + film_rgba_floats(pixels) + std::size_t(k) * pixels;
        h.square[k].assign(squares, squares + pixels);
        for (float& s : h.square[k]) s *= inv;
    }
    return h;
}

FilmHalves film_halves(const FilmState& film) {
    return film_halves(film.sums, std::size_t(film.width) * std::size_t(film.height), film.samples,
                       film.second_moments);
}

ErrorMetrics estimate_film_error(const std::vector<const std::vector<float>*>& films, std::size_t pixels,
                                 const SampleRanges& samples) {
    for (const std::vector<float>* f : films)
        if (f->size() != film_floats(pixels))
            throw Error(fmt::format("a film of {} values does not hold {} pixels", f->size(), pixels));
    const std::uint64_t n[2] = {even_samples(samples), odd_samples(samples)};
    const float inv[2] = {n[0] ? 1.0f / float(n[0]) : 0.0f, n[1] ? 1.0f / float(n[1]) : 0.0f};
    // One pixel's channel of half k: the films' sums added as DeviceGroup::accumulation()
    // adds them (from 0), then scaled as film_halves scales it.
    auto half = [&](int k, std::size_t i, int c) {
        float sum = 0.0f;
        for (const std::vector<float>* f : films) sum += (*f)[std::size_t(k) * pixels * 4 + 4 * i + std::size_t(c)];
        return sum * inv[k];
    };
    return estimate_error_streamed(3 * pixels, n[0], n[1], [&](std::size_t j, float& a, float& b) {
        a = half(0, j / 3, int(j % 3));
        b = half(1, j / 3, int(j % 3));
    });
}

std::vector<float> film_mean(const FilmHalves& h) {
    const std::uint64_t n = h.samples[0] + h.samples[1];
    std::vector<float> rgb(h.rgb[0].size(), 0.0f);
    if (n == 0) return rgb;
    const float w0 = float(h.samples[0]) / float(n), w1 = float(h.samples[1]) / float(n);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = w0 * h.rgb[0][i] + w1 * h.rgb[1][i];
    return rgb;
}

}  // namespace facet
