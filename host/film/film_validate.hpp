// The payload of a film checked before its samples are used (--resume, `facet merge`):
// its checksum says the bytes are those written, not that they make sense, and a film
// written by another program, or by a facet with a bug, must not turn into a broken
// image with exit 0.
#pragma once

#include <string>

#include "host/film/film_state.hpp"

namespace facet {

// Throws facet::Error naming `path`, the pixel and the value when the film's payload is
// not one a render can have written:
// - a value is NaN or infinite;
// - a pixel's count of rejected samples (A) is negative, not a whole number, or more
//   than the samples its half holds;
// - a half that holds no samples has a non-zero sum;
// - a half's total of a colour channel is negative (a filter with negative lobes,
//   Mitchell's, makes single pixels negative, never the light of the whole image).
void validate_film_payload(const FilmState& film, const std::string& path);

}  // namespace facet
