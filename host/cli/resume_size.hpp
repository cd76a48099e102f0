// `--resume FILM`: the image size comes from the film where --width or --height is not
// given; a given one that differs is refused by check_film_matches (film/film_state.hpp),
// which names both sizes.
#pragma once

#include "host/cli/commands.hpp"
#include "host/film/film_state.hpp"
#include "host/scene/scene.hpp"

namespace facet {

inline void take_film_size(const FilmState& film, const RenderOptions& opt, RenderSettings& settings) {
    if (!opt.width) settings.width = film.width;
    if (!opt.height) settings.height = film.height;
}

}  // namespace facet
