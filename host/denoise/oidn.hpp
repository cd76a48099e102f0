// Intel Open Image Denoise (OIDN), loaded at run time when it is installed: facet builds
// and runs without it. Debian 12 does not package it; PyPI's `pyoidn` wheel ships
// libOpenImageDenoise.so.2 with its CPU device and trained weights. OIDN runs on the CPU
// (it has no OpenCL device). Each half-image is denoised on its own, as facet's denoiser
// does, so that the denoised error can be estimated (denoise/denoise_error.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/denoise/denoiser.hpp"

namespace facet {

// The OIDN library to load: `given` (a --oidn path) when not empty, else $FACET_OIDN, else
// libOpenImageDenoise.so.2 of a `pyoidn` installed in $VIRTUAL_ENV, ~/.local or the
// system's Python folders, else "libOpenImageDenoise.so.2" when the dynamic loader finds
// it; empty when none is found. `looked` (if given) receives the places looked in.
std::string find_oidn(const std::string& given, std::string* looked = nullptr);

// Denoises both halves of `halves` with OIDN's "RT" filter (hdr, with the albedo and
// normal AOVs) on its default device. Throws facet::Error naming `library` and OIDN's
// own message when it cannot be loaded or fails.
DenoisedImage denoise_oidn(const std::string& library, std::uint32_t width, std::uint32_t height,
                           const FilmHalves& halves, const AovImages& features);

}  // namespace facet
