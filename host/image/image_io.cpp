#include "host/image/image_io.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "host/error.hpp"
#include "host/util/safe_write.hpp"
#include "host/util/input_file.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;
// The longest side read. OpenImageIO decodes scanline files in chunks of up to 256 rows
// whatever the image's height, so a 1-row image claiming 2 million columns made it
// allocate 6.6 GB (fuzz_env_map, tests/fuzz/regressions/env_map/one_row_wide_oom.exr).
constexpr int kMaxImageSide = 65536;
// The most decoded bytes (float RGB) an image file may hold per byte of file: above any
// real compression of a real image (deflate stops near 1032:1 on half floats, 2064:1 as
// float), so a 117-byte .hdr or a small EXR that claims 16000x16000 is refused before
// the 3 GB are allocated. Images up to kSmallImageBytes decoded are not checked.
constexpr std::uint64_t kMaxDecodedPerFileByte = 8192;
constexpr std::uint64_t kSmallImageBytes = std::uint64_t(64) << 20;
// The most bytes an image may take decoded as float RGB: 2 GiB, about 13000 x 13000
// pixels (an 8K texture is 0.75 GiB). A 783 KB PNG of 16384 x 16384 one grey (deflate
// compresses it 340:1) needed about 12 GB before "std::bad_alloc"; it is refused from
// its header, before any pixel is decoded.
constexpr std::uint64_t kMaxDecodedImageBytes = std::uint64_t(2) << 30;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Writes `data` as `path`'s format into `tmp` (a temporary with the same extension).
void write_pixels(const std::string& tmp, const ImageSpec& spec, TypeDesc type, const void* data,
                  const std::string& path) {
    std::unique_ptr<ImageOutput> out = ImageOutput::create(tmp);
    if (!out) throw Error(fmt::format("{}: cannot write this image format: {}", path, OIIO::geterror()));
    errno = 0;
    if (!out->open(tmp, spec) || !out->write_image(type, data) || !out->close()) {
        // OpenImageIO's message may lack the system's reason ("File output failed").
        const int err = errno;
        const bool told = err == ENOSPC || err == EDQUOT || err == EIO || err == EFBIG || err == EROFS;
        throw Error(fmt::format("{}: writing the image failed: {}{}", path, out->geterror(),
                                told ? fmt::format(" ({})", std::strerror(err)) : std::string()));
    }
}

// Reads the written file back whole: an image writer that does not report a failed
// write (a full disk) still cannot make a torn file pass for a good one.
void verify_pixels(const std::string& tmp, const ImageSpec& spec, const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(tmp);
    if (!in) throw Error(fmt::format("{}: the written image cannot be read back: {}", path, OIIO::geterror()));
    const ImageSpec& got = in->spec();
    if (got.width != spec.width || got.height != spec.height || got.nchannels != spec.nchannels)
        throw Error(fmt::format("{}: the written image reads back as {}x{} with {} channels", path, got.width,
                                got.height, got.nchannels));
    std::vector<float> pixels(std::size_t(got.width) * std::size_t(got.height) * std::size_t(got.nchannels));
    if (!in->read_image(0, 0, 0, got.nchannels, TypeDesc::FLOAT, pixels.data()))
        throw Error(fmt::format("{}: the written image cannot be read back: {}", path, in->geterror()));
}

void write_image_file(const std::string& path, const ImageSpec& spec, TypeDesc type, const void* data) {
    write_file_safely(
        path, "image", [&](const std::string& tmp) { write_pixels(tmp, spec, type, data, path); },
        [&](const std::string& tmp) { verify_pixels(tmp, spec, path); });
}

// The sRGB transfer function's inverse (IEC 61966-2-1).
float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

void check_size(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * height * 3)
        throw Error(fmt::format("{}: image of {}x{} with {} values is inconsistent", path, width, height, rgb.size()));
}

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb, const ImageMetadata& meta,
               const std::vector<ImageLayer>& layers) {
    check_size(path, width, height, rgb);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<std::string> names = {"R", "G", "B"};
    for (const ImageLayer& l : layers) {
        if (l.channels.empty() || l.values.size() != pixels * l.channels.size())
            throw Error(fmt::format("{}: the {} layer of {} values does not fit a {}x{} image", path, l.name,
                                    l.values.size(), width, height));
        for (const std::string& c : l.channels) names.push_back(l.name + "." + c);
    }
    if (!layers.empty() && lower(fs::path(path).extension().string()) != ".exr")
        throw Error(fmt::format("{}: only an EXR holds extra layers ({}...): give a .exr name", path, names[3]));
    ImageSpec spec(width, height, int(names.size()), TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", "zip");
    spec.attribute("Software", "facet");
    for (const auto& [k, v] : meta.strings) spec.attribute(k, v);
    for (const auto& [k, v] : meta.floats) spec.attribute(k, v);
    for (const auto& [k, v] : meta.ints) spec.attribute(k, v);
    if (layers.empty()) return write_image_file(path, spec, TypeDesc::FLOAT, rgb.data());
    // Interleaved: R, G, B, then each layer's channels, pixel by pixel.
    std::vector<float> all(pixels * names.size());
    for (std::size_t i = 0; i < pixels; ++i) {
        float* out = &all[i * names.size()];
        for (int c = 0; c < 3; ++c) *out++ = rgb[3 * i + std::size_t(c)];
        for (const ImageLayer& l : layers)
            for (std::size_t c = 0; c < l.channels.size(); ++c) *out++ = l.values[i * l.channels.size() + c];
    }
    write_image_file(path, spec, TypeDesc::FLOAT, all.data());
}

void write_png(const std::string& path, int width, int height, const std::vector<float>& rgb, float exposure,
               ToneMap tonemap) {
    check_size(path, width, height, rgb);
    float scale = std::exp2(exposure);
    std::vector<std::uint8_t> bytes(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const float v = rgb[i] * scale;
        bytes[i] = std::uint8_t(std::lround(tonemap_display(tonemap, std::isnan(v) ? 0.0f : v) * 255.0f));
    }
    ImageSpec spec(width, height, 3, TypeDesc::UINT8);
    spec.attribute("Software", "facet");
    write_image_file(path, spec, TypeDesc::UINT8, bytes.data());
}

// read_image after the file's checks; the decoded size is checked against the file's.
static ImageRGB read_image_checked(const std::string& path, std::uint64_t file_size,
                                   OIIO::Filesystem::IOProxy* proxy = nullptr) {
    // Colours as stored: OpenImageIO multiplies an unassociated alpha (PNG, TGA, TIFF) into
    // the colour on read unless told not to, and facet reads R, G, B alone (alpha unused).
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (proxy) {  // the plugins take the proxy from the configuration (OpenImageIO 2.4)
        void* p = proxy;
        config.attribute("oiio:ioproxy", TypeDesc::PTR, &p);
    }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config, proxy);
    if (!in) throw Error(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
    const ImageSpec& spec = in->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
        throw Error(fmt::format("{}: empty image ({}x{}, {} channels)", path, spec.width, spec.height, spec.nchannels));
    // Checked before allocating: a header can claim any size (16384 x 16384 is 2^28).
    if (std::int64_t(spec.width) * spec.height > kMaxImagePixels)
        throw Error(fmt::format("{}: the image claims {}x{} pixels: at most 2^28 pixels are supported", path,
                                spec.width, spec.height));
    if (spec.width > kMaxImageSide || spec.height > kMaxImageSide)
        throw Error(fmt::format("{}: the image claims {}x{} pixels: at most {} pixels a side are supported", path,
                                spec.width, spec.height, kMaxImageSide));
    // R, G, B (or grey), then the alpha channel where the file has one (RGBA, grey + alpha);
    // the rest unused.
    const int alpha_at = spec.alpha_channel >= 1 && spec.alpha_channel <= 3 && spec.alpha_channel < spec.nchannels
                             ? spec.alpha_channel
                             : -1;
    const int channels = alpha_at >= 0 ? alpha_at : std::min(spec.nchannels, 3);
    const int stride = alpha_at >= 0 ? alpha_at + 1 : channels;
    const std::uint64_t decoded = std::uint64_t(spec.width) * std::uint64_t(spec.height) * 3u * sizeof(float);
    if (decoded > kSmallImageBytes && decoded / kMaxDecodedPerFileByte > file_size)
        throw Error(
            fmt::format("{}: the image claims {}x{} pixels ({} MiB decoded) but the file has only {} bytes: "
                        "it is truncated or corrupt",
                        path, spec.width, spec.height, decoded >> 20, file_size));
    if (decoded > kMaxDecodedImageBytes)
        throw Error(
            fmt::format("{}: the image claims {}x{} pixels, {} MiB decoded as float RGB: at most {} MiB "
                        "(about 13000x13000 pixels) are read",
                        path, spec.width, spec.height, decoded >> 20, kMaxDecodedImageBytes >> 20));
    std::vector<float> all(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(stride));
    if (!in->read_image(0, 0, 0, stride, TypeDesc::FLOAT, all.data()))
        throw Error(fmt::format("{}: cannot read pixels: {}", path, in->geterror()));
    ImageRGB img;
    img.width = spec.width;
    img.height = spec.height;
    img.spp = spec.get_int_attribute("facet:spp", -1);
    // Integer formats hold display-encoded values: sRGB unless the file says linear.
    const bool integer = spec.format.basetype == TypeDesc::UINT8 || spec.format.basetype == TypeDesc::UINT16;
    if (integer) img.bits = spec.format.basetype == TypeDesc::UINT8 ? 8 : 16;
    const std::string space = spec.get_string_attribute("oiio:ColorSpace", "sRGB");
    if (integer && space != "Linear" && space != "linear") {
        img.decoded_srgb = true;
        img.note = fmt::format(
            "{}: an {}-bit sRGB image, decoded to linear radiance; it stops at 1 (no sun, no highlights): "
            "an EXR or HDR image holds the light itself",
            path, spec.format.basetype == TypeDesc::UINT8 ? 8 : 16);
        for (std::size_t i = 0; i < all.size(); ++i)
            if (int(i % std::size_t(stride)) != alpha_at) all[i] = srgb_decode(all[i]);  // alpha is linear
    }
    if (alpha_at >= 0) {
        img.alpha.resize(std::size_t(spec.width) * spec.height);
        for (std::size_t i = 0; i < img.alpha.size(); ++i)
            img.alpha[i] = all[i * std::size_t(stride) + std::size_t(alpha_at)];
    }
    if (stride == 3) {  // already RGB: no second copy
        img.rgb = std::move(all);
        return img;
    }
    img.rgb.resize(std::size_t(spec.width) * spec.height * 3);
    for (std::size_t i = 0; i < std::size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * i + c] = all[i * std::size_t(stride) + std::size_t(std::min(c, channels - 1))];
    return img;
}

ImageRGB read_image(const std::string& path) {
    const std::uint64_t file_size = check_input_file(path, "image");
    check_image_header(path);
    try {
        return read_image_checked(path, file_size);
    } catch (const std::bad_alloc&) {
        throw Error(fmt::format("image '{}': not enough memory to read it", path));
    }
}

ImageRGB read_image_bytes(const std::string& name, const std::string& bytes) {
    check_image_header_bytes(name, bytes.substr(0, std::size_t(1) << 16), bytes.size());
    try {
        OIIO::Filesystem::IOMemReader reader(const_cast<char*>(bytes.data()), bytes.size());
        return read_image_checked(name, bytes.size(), &reader);
    } catch (const std::bad_alloc&) {
        throw Error(fmt::format("image '{}': not enough memory to read it", name));
    }
}

// OpenEXR reads a file's whole chunk-offset table when it opens it, sized from the
// header, and each header attribute at its declared size: a few hundred corrupt bytes
// can claim a 1.7 GB attribute or 2^31 lines and take gigabytes and seconds before
// "Unexpected end of file" (found by fuzz_env_map). The header is read here first,
// before OpenImageIO opens the file; only what is certainly wrong is rejected (an
// attribute or offset table larger than the file, a data window of more than
// kMaxImagePixels pixels), anything else is left to OpenEXR's own checks.
void check_image_header(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::string head(1 << 16, '\0');
    file.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(file.gcount()));
    std::error_code ec;
    const std::uintmax_t file_size = fs::file_size(path, ec);
    if (ec) return;
    check_image_header_bytes(path, head, file_size);
}

// The size in bytes of an OpenEXR attribute type of fixed size (OpenEXR's file layout), or 0
// for types of variable size (string, chlist, preview, ...) or unknown ones.
static int exr_fixed_size(const std::string& type) {
    static const std::pair<const char*, int> kSizes[] = {
        {"box2i", 16}, {"box2f", 16},   {"compression", 1}, {"lineOrder", 1}, {"envmap", 1},   {"deepImageState", 1},
        {"int", 4},    {"float", 4},    {"double", 8},      {"v2i", 8},       {"v2f", 8},      {"v2d", 16},
        {"v3i", 12},   {"v3f", 12},     {"v3d", 24},        {"m33f", 36},     {"m33d", 72},    {"m44f", 64},
        {"m44d", 128}, {"rational", 8}, {"timecode", 8},    {"keycode", 28},  {"tiledesc", 9}, {"chromaticities", 32}};
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

void check_image_header_bytes(const std::string& path, const std::string& head, std::uintmax_t file_size) {
    if (head.size() < 8 || head.compare(0, 4, "\x76\x2f\x31\x01") != 0) return;
    auto int32_at = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (int i = 3; i >= 0; --i) v = (v << 8) | std::uint8_t(head[at + std::size_t(i)]);
        return std::int32_t(v);
    };
    const std::uint32_t flags = std::uint32_t(int32_at(4));
    const bool single_part_scanlines = (flags & 0x1a00u) == 0;  // not tiled, deep or multi-part
    std::size_t at = 8;
    bool have_window = false;
    std::int64_t width = 0, height = 0;
    int compression = 0;
    std::int64_t tile_w = 0, tile_h = 0;
    std::int64_t pixel_bytes = 0;  // the channels' bytes a pixel, 0 when any is subsampled
    while (at < head.size() && head[at] != '\0') {
        const std::size_t name_end = head.find('\0', at);
        const std::size_t type_end = name_end == std::string::npos ? name_end : head.find('\0', name_end + 1);
        if (type_end == std::string::npos || type_end + 5 > head.size()) return;
        const std::string name = head.substr(at, name_end - at);
        const std::string type = head.substr(name_end + 1, type_end - name_end - 1);
        const std::int32_t size = int32_at(type_end + 1);
        const std::size_t value = type_end + 5;
        // OpenEXR allocates an attribute's declared size before reading it.
        if (size < 0 || std::uintmax_t(value) + std::uintmax_t(size) > file_size)
            throw Error(
                fmt::format("{}: the EXR header's attribute '{}' claims {} bytes, but the file has {}: it is "
                            "truncated or corrupt",
                            path, name.substr(0, 64), size, file_size));
        // OpenEXR reads a fixed-size type's own size whatever the header declares, and would
        // go on reading at another place than this walk (where a string attribute could
        // then claim gigabytes: found by fuzz_env_map).
        if (const int fixed = exr_fixed_size(type); fixed > 0 && size != fixed)
            throw Error(
                fmt::format("{}: the EXR header's attribute '{}' of type {} declares {} bytes, where its "
                            "type has {}: it is corrupt",
                            path, name.substr(0, 64), type.substr(0, 32), size, fixed));
        if (value + std::size_t(size) > head.size()) return;  // a long header: left to OpenEXR
        // OpenEXR reads a channel list entry by entry (a name, then 16 bytes) up to an empty
        // name, whatever size the header declares, and goes on from there: a list whose
        // entries end elsewhere than its declared size would misalign this walk (a string
        // attribute after it then claimed 1.7 GB: found by fuzz_env_map).
        if (type == "chlist") {
            std::size_t end = value;
            while (end != std::string::npos && end < head.size() && head[end] != '\0') {
                const std::size_t nul = head.find('\0', end);
                end = nul == std::string::npos ? nul : nul + 1 + 16;
            }
            if (end != std::string::npos && end < head.size()) ++end;  // past the empty name
            if (end != value + std::size_t(size))
                throw Error(
                    fmt::format("{}: the EXR header's channel list '{}' declares {} bytes, but its "
                                "channels end elsewhere: it is corrupt",
                                path, name.substr(0, 64), size));
            if (name == "channels") {  // pixel type (UINT 4, HALF 2, FLOAT 4 bytes), x and y sampling
                pixel_bytes = 0;
                bool subsampled = false;
                for (std::size_t c = value; c < end && head[c] != '\0';) {
                    const std::size_t nul = head.find('\0', c);
                    const std::int32_t type_id = int32_at(nul + 1);
                    pixel_bytes += type_id == 1 ? 2 : 4;
                    subsampled = subsampled || int32_at(nul + 9) != 1 || int32_at(nul + 13) != 1;
                    c = nul + 1 + 16;
                }
                if (subsampled) pixel_bytes = 0;
            }
        }
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            width = std::int64_t(int32_at(value + 8)) - int32_at(value) + 1;
            height = std::int64_t(int32_at(value + 12)) - int32_at(value + 4) + 1;
            have_window = true;
        } else if (name == "tiles" && type == "tiledesc" && size == 9) {
            tile_w = std::uint32_t(int32_at(value));
            tile_h = std::uint32_t(int32_at(value + 4));
        } else if (name == "compression" && size == 1) {
            compression = std::uint8_t(head[value]);
        }
        at = value + std::size_t(size);
    }
    if (!have_window || width < 1 || height < 1) return;
    if (width * height > kMaxImagePixels)
        throw Error(
            fmt::format("{}: the EXR header claims a data window of {}x{} pixels: at most 2^28 pixels are "
                        "supported",
                        path, width, height));
    // A single-part tiled file: the offset table holds at least one entry per tile of
    // the full-resolution level (1x1 tiles over 16000x16000 claim a 2 GB table).
    const bool single_part_tiles = (flags & 0x1a00u) == 0x200u;
    if (single_part_tiles && tile_w > 0 && tile_h > 0) {
        const std::uint64_t tiles =
            std::uint64_t((width + tile_w - 1) / tile_w) * std::uint64_t((height + tile_h - 1) / tile_h);
        if (tiles * 8u > file_size)
            throw Error(
                fmt::format("{}: the EXR header claims {} tiles of {}x{} over {}x{} pixels, whose offset table "
                            "alone needs {} bytes, but the file has {}: it is truncated or corrupt",
                            path, tiles, tile_w, tile_h, width, height, tiles * 8u, file_size));
    }
    if (!single_part_scanlines) return;
    // Scanlines per chunk by compression: none, RLE, ZIPS 1; ZIP, PXR24 16; PIZ, B44(A),
    // DWAA 32; DWAB 256 (unknown: the largest).
    static const int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    const int lines = compression >= 0 && compression < 10 ? kLines[compression] : 256;
    const std::uint64_t table = std::uint64_t((height + lines - 1) / lines) * 8u;
    if (table > file_size)
        throw Error(
            fmt::format("{}: the EXR header claims {} scanlines, whose offset table alone needs {} bytes, "
                        "but the file has {}: it is truncated or corrupt",
                        path, height, table, file_size));
    // Each chunk offset (as far as the table lies in the bytes read) must point past the
    // table and leave room for the chunk's y and byte count. A table of zeros (a file whose
    // writer stopped early) made OpenEXR 3.1 fall back to scanning for the chunks, and
    // where that found none OpenImageIO returned the lines unread, as whatever memory held
    // (valgrind on fuzz_env_map's corpus): an error here instead.
    const std::uint64_t table_at = std::uint64_t(at) + 1u;
    for (std::uint64_t k = 0; at < head.size() && k < table / 8u && table_at + 8u * k + 8u <= head.size(); ++k) {
        std::uint64_t offset = 0;
        for (int b = 7; b >= 0; --b) offset = (offset << 8) | std::uint8_t(head[table_at + 8u * k + std::uint64_t(b)]);
        if (offset < table_at + table || offset > file_size || file_size - offset < 8u)
            throw Error(
                fmt::format("{}: the EXR file's chunk {} is at byte {}, outside its chunks (bytes {} to {}): the "
                            "file is incomplete or corrupt",
                            path, k, offset, table_at + table, file_size));
    }
    // Uncompressed scanlines have a known size: the header, the table, and a line a chunk
    // (its y and byte count, then its pixels). OpenEXR 3.1 (through OpenImageIO) reads a
    // chunk that declares fewer bytes than its line holds without an error and leaves the
    // rest of the line as whatever memory held (valgrind on fuzz_env_map's corpus: lines of
    // 759 pixels in chunks of 96 bytes). Such a file is smaller than its lines need, and is
    // refused here; one padded to the full size is left to OpenEXR.
    if (compression == 0 && pixel_bytes > 0 && at < head.size()) {
        const std::uint64_t need =
            table_at + table + std::uint64_t(height) * (8u + std::uint64_t(width) * std::uint64_t(pixel_bytes));
        if (need > file_size)
            throw Error(
                fmt::format("{}: the EXR file's {} uncompressed scanlines of {} pixels need {} bytes, but the file "
                            "has {}: it is truncated",
                            path, height, width, need, file_size));
    }
}

bool can_write_float_image(const std::string& path, std::string* why) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    auto refuse = [&](std::string reason) {
        if (why) *why = std::move(reason);
        return false;
    };
    static const char* const kFloat[] = {".exr", ".hdr", ".tif", ".tiff", ".pfm"};
    static const char* const k8Bit[] = {".png", ".jpg", ".jpeg", ".bmp", ".gif", ".webp", ".tga", ".ppm", ".pnm"};
    if (ext.empty() || ext == ".")
        return refuse("the name has no extension, so the image format is unknown: end it with .exr");
    for (const char* e : k8Bit)
        if (ext == e)
            return refuse(
                fmt::format("a {} file holds 8-bit tone-mapped values, not the linear image: give the "
                            "EXR's name ({}); the tone-mapped PNG is written beside it",
                            ext, replace_extension(path, ".exr")));
    if (std::find_if(std::begin(kFloat), std::end(kFloat), [&](const char* e) { return ext == e; }) == std::end(kFloat))
        return refuse(fmt::format("'{}' is not an image format facet writes: use .exr (or .hdr, .tif, .pfm)", ext));
    std::unique_ptr<ImageOutput> out = ImageOutput::create(path);
    if (!out) return refuse(fmt::format("this OpenImageIO cannot write {} files: {}", ext, OIIO::geterror()));
    return true;
}

}  // namespace facet
