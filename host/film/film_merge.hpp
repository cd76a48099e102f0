// Films of one scene and settings holding disjoint sample ranges add up to one film:
// the sums of both halves are added and the ranges joined. What `facet merge` does with
// the films of a farm's tasks (`facet render --samples-from K`), and what several
// devices or MPI ranks do with their shares of a pass.
#pragma once

#include <string>
#include <vector>

#include "host/film/film_state.hpp"

namespace facet {

// Throws facet::Error naming both files and the first setting in which `b` differs from
// `a` (the scene's identity first when the scene files differ too, then size, seed, depths,
// strategy, sampler, then the identity): samples of different renders cannot be combined.
void check_films_combine(const FilmState& a, const std::string& a_path, const FilmState& b, const std::string& b_path);

// The sum of `films` (paths for messages, one each), added in the order given. Throws
// facet::Error when they differ in scene or settings, or when two hold a sample index in
// common (naming the files and the first index), or when there are none.
FilmState merge_films(const std::vector<FilmState>& films, const std::vector<std::string>& paths);

}  // namespace facet
