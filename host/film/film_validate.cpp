#include "host/film/film_validate.hpp"

#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/film/film_layout.hpp"

namespace facet {

void validate_film_payload(const FilmState& film, const std::string& path) {
    const std::size_t pixels = std::size_t(film.width) * std::size_t(film.height);
    if (film.sums.size() != film_floats(pixels))
        throw Error(fmt::format("{}: the film of {}x{} pixels holds {} values: corrupt", path, film.width, film.height,
                                film.sums.size()));
    const std::uint64_t half_samples[2] = {even_samples(film.samples), odd_samples(film.samples)};
    const char* half_name[2] = {"even", "odd"};
    const char* channel[4] = {"red", "green", "blue", "rejected-sample count"};
    for (int k = 0; k < 2; ++k) {
        const float* half = film.sums.data() + std::size_t(k) * pixels * 4;
        double total[3] = {0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::size_t x = i % std::size_t(film.width), y = i / std::size_t(film.width);
            auto refuse = [&](int c, const std::string& why) {
                throw Error(
                    fmt::format("{}: pixel ({}, {}) of the {}-sample half has the {} {}: {}; the film is "
                                "corrupt and cannot be continued or merged",
                                path, x, y, half_name[k], channel[c], half[4 * i + c], why));
            };
            for (int c = 0; c < 4; ++c) {
                const float v = half[4 * i + c];
                if (!std::isfinite(v)) refuse(c, "not a finite number");
                if (half_samples[k] == 0 && v != 0.0f) refuse(c, "but the half holds no samples");
                if (c < 3) total[c] += double(v);
            }
            const float rejected = half[4 * i + 3];
            if (rejected < 0.0f || rejected != std::floor(rejected))
                refuse(3, "a count is a non-negative whole number");
            if (double(rejected) > double(half_samples[k]))
                refuse(3, fmt::format("more than the {} samples the half holds", half_samples[k]));
        }
        for (int c = 0; c < 3; ++c)
            if (total[c] < 0.0)
                throw Error(
                    fmt::format("{}: the {}-sample half's {} light adds up to {:g}, below zero: the film is "
                                "corrupt and cannot be continued or merged",
                                path, half_name[k], channel[c], total[c]));
        // The second moments: sums of squares, so finite and not negative
        const float* squares = film.sums.data() + film_rgba_floats(pixels) + std::size_t(k) * pixels;
        for (std::size_t i = 0; i < pixels; ++i) {
            const float v = squares[i];
            if (std::isfinite(v) && v >= 0.0f && (half_samples[k] > 0 || v == 0.0f)) continue;
            throw Error(
                fmt::format("{}: pixel ({}, {}) of the {}-sample half has the second moment {}: {}; the film "
                            "is corrupt and cannot be continued or merged",
                            path, i % std::size_t(film.width), i / std::size_t(film.width), half_name[k], v,
                            half_samples[k] == 0 ? "but the half holds no samples"
                                                 : "a sum of squares is a finite number, not below zero"));
        }
    }
}

}  // namespace facet
