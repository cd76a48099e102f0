// Image files through OpenImageIO: linear EXR with metadata, and a tone-mapped sRGB
// PNG for viewing. Writes go through write_file_safely (util/safe_write.hpp): the old
// file or the complete, read-back new one, never a torn one.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "host/image/tonemap.hpp"

namespace facet {

struct ImageMetadata {
    std::vector<std::pair<std::string, std::string>> strings;  // e.g. {"facet:device", "..."}
    std::vector<std::pair<std::string, float>> floats;         // e.g. {"facet:render_seconds", 1.5}
    std::vector<std::pair<std::string, int>> ints;             // e.g. {"facet:spp", 64}
};

// An extra layer of an EXR beside its R, G, B: channels "<name>.<channel>" (OpenEXR's
// layer convention, which compositors and denoisers read), e.g. {"albedo", {"R", "G", "B"}}.
struct ImageLayer {
    std::string name;
    std::vector<std::string> channels;
    std::vector<float> values;  // channels.size() floats a pixel, top row first
};

// Writes linear RGB floats (3 per pixel, top row first) as a 32-bit float EXR, so that
// images can serve as references at full precision (another float format when the
// extension says so: .hdr, .tif, .pfm, without the metadata EXR holds). `layers` go into
// the EXR after R, G, B; another format cannot hold them (facet::Error).
void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb,
               const ImageMetadata& meta = {}, const std::vector<ImageLayer>& layers = {});

// Writes an 8-bit sRGB PNG: radiance times 2^exposure, tone-mapped (image/tonemap.hpp:
// clamped to [0, 1] and sRGB-encoded, or the filmic curve).
void write_png(const std::string& path, int width, int height, const std::vector<float>& rgb, float exposure = 0.0f,
               ToneMap tonemap = ToneMap::Clip);

struct ImageRGB {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3 floats a pixel, top row first
    // The alpha channel as stored (unassociated, linear; 1 float a pixel), empty when the
    // file has none: what texture cut-outs read (docs/textures.md).
    std::vector<float> alpha;
    int spp = -1;  // facet:spp metadata, when the file has it
    // An 8-bit or 16-bit integer image in sRGB (PNG, JPEG...): its values were decoded to
    // linear, and `note` says so (such an image stops at 1: no sun, no highlights).
    bool decoded_srgb = false;
    int bits = 32;  // 8 or 16 for an integer file (its precision; textures store it compactly)
    std::string note;
};

// Reads any image OpenImageIO can (EXR, HDR, PNG...) as linear RGB floats: EXR and HDR
// as stored, integer images in sRGB (8-bit PNG, JPEG) decoded to linear with a note
// (ImageRGB::note). A one-channel image is
// replicated to grey. Alpha is read apart (ImageRGB::alpha), never multiplied into the colour (an RGBA PNG's
// texel of alpha 0 keeps its stored colour). Throws facet::Error naming the file on failure, and for images
// of more than 2^28 pixels (checked on the header, before reading).
ImageRGB read_image(const std::string& path);
// read_image of an image held in memory (an image embedded in a glTF or FBX file): `name`
// says where it came from in messages, and its extension which format it is; nothing is
// written to disk (so nothing is left behind by a signal, and no $TMPDIR is needed).
ImageRGB read_image_bytes(const std::string& name, const std::string& bytes);

// Cheap checks of a file's header before any reader allocates from it (read_image calls
// it first). OpenEXR: every attribute and the chunk-offset table must fit in the file,
// and the data window must hold at most 2^28 pixels. Throws facet::Error naming the file.
void check_image_header(const std::string& path);
// The same checks of a header held in memory: `head` the file's first bytes (64 KiB or all
// of it), `file_size` the whole file's size; `path` names it in messages.
void check_image_header_bytes(const std::string& path, const std::string& head, std::uintmax_t file_size);

// Reads a reference image for a render of width x height: the size must match, every
// texel must be finite and the file must hold linear radiance (an 8-bit sRGB image is
// tone-mapped and clipped at 1: refused), else facet::Error names the file and the problem.
ImageRGB read_reference(const std::string& path, int width, int height);

// Whether `path`'s extension names a format that holds linear floats and that this
// OpenImageIO can write (.exr, .hdr, .tif, .tiff, .pfm); `why` receives the reason if not.
bool can_write_float_image(const std::string& path, std::string* why = nullptr);

// The path with its extension replaced ("out/a.exr", ".png" -> "out/a.png").
std::string replace_extension(const std::string& path, const std::string& ext);

}  // namespace facet
