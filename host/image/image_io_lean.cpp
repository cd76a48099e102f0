// image_io.hpp without OpenImageIO (the lean build, CMake option FACET_OIIO=OFF, for GPU
// nodes without facet's full dependency tree: docs/devices.md): linear images as PFM
// (Portable Float Map: "PF", width and height, a negative scale for little-endian, then
// float RGB rows from the bottom), the tone-mapped image as a PNG of stored (uncompressed)
// deflate blocks. Reads PFM only, so references and environment maps must be .pfm.
#ifdef FACET_LEAN_IMAGES

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"
#include "host/util/input_file.hpp"

namespace facet {
namespace {

constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void check_size(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * height * 3)
        throw Error(fmt::format("{}: image of {}x{} with {} values is inconsistent", path, width, height, rgb.size()));
}

// CRC-32 (ISO 3309, as PNG chunks use) and Adler-32 (RFC 1950, the zlib stream's).
std::uint32_t crc32(const std::string& bytes, std::size_t begin) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = begin; i < bytes.size(); ++i) c = table[(c ^ std::uint8_t(bytes[i])) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

void put_u32_be(std::string& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(char((v >> s) & 0xff));
}

void put_chunk(std::string& png, const char* type, const std::string& data) {
    put_u32_be(png, std::uint32_t(data.size()));
    const std::size_t start = png.size();
    png += type;
    png += data;
    put_u32_be(png, crc32(png, start));
}

// A zlib stream of stored deflate blocks (no compression) holding `raw`.
std::string zlib_stored(const std::string& raw) {
    std::string z = {char(0x78), char(0x01)};
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521u;
        b = (b + a) % 65521u;
    }
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
        z.push_back(at + n == raw.size() ? 1 : 0);
        z.push_back(char(n & 0xff));
        z.push_back(char(n >> 8));
        z.push_back(char(~n & 0xff));
        z.push_back(char((~n >> 8) & 0xff));
        z.append(raw, at, n);
        at += n;
    } while (at < raw.size());
    put_u32_be(z, (b << 16) | a);
    return z;
}

// The PFM header's width, height, little-endian flag and its length in bytes.
struct PfmHeader {
    int width = 0, height = 0, channels = 0;
    bool little = true;
    std::size_t bytes = 0;
};

PfmHeader parse_pfm_header(const std::string& path, const std::string& data) {
    PfmHeader h;
    if (data.size() < 3 || data[0] != 'P' || (data[1] != 'F' && data[1] != 'f'))
        throw Error(
            fmt::format("{}: not a PFM image (this facet is built without OpenImageIO and reads .pfm only)", path));
    h.channels = data[1] == 'F' ? 3 : 1;
    std::istringstream in(data.substr(2, 256));
    double scale = 0.0;
    if (!(in >> h.width >> h.height >> scale) || h.width < 1 || h.height < 1 || scale == 0.0 || !std::isfinite(scale))
        throw Error(fmt::format("{}: the PFM header is malformed", path));
    if (std::int64_t(h.width) * h.height > kMaxImagePixels)
        throw Error(fmt::format("{}: the PFM claims {}x{} pixels, more than 2^28", path, h.width, h.height));
    h.little = scale < 0.0;
    in.get();  // the one whitespace byte after the scale
    h.bytes = 2 + std::size_t(in.tellg());
    return h;
}

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb, const ImageMetadata&,
               const std::vector<ImageLayer>& layers) {
    check_size(path, width, height, rgb);
    if (!layers.empty())
        throw Error(fmt::format("{}: this lean build writes PFM, which cannot hold the --aov layers", path));
    std::string why;
    if (!can_write_float_image(path, &why)) throw Error(fmt::format("{}: {}", path, why));
    std::string out = fmt::format("PF\n{} {}\n-1.0\n", width, height);
    for (int y = height - 1; y >= 0; --y)
        out.append(reinterpret_cast<const char*>(rgb.data() + std::size_t(y) * width * 3),
                   std::size_t(width) * 3 * sizeof(float));
    write_bytes_safely(path, "image", out);
}

void write_png(const std::string& path, int width, int height, const std::vector<float>& rgb, float exposure,
               ToneMap tonemap) {
    check_size(path, width, height, rgb);
    const float scale = std::exp2(exposure);
    std::string raw;
    raw.reserve(std::size_t(height) * (1 + std::size_t(width) * 3));
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        for (int i = 0; i < width * 3; ++i) {
            const float v = rgb[std::size_t(y) * width * 3 + i] * scale;
            raw.push_back(char(std::lround(tonemap_display(tonemap, std::isnan(v) ? 0.0f : v) * 255.0f)));
        }
    }
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string ihdr;
    put_u32_be(ihdr, std::uint32_t(width));
    put_u32_be(ihdr, std::uint32_t(height));
    ihdr += std::string{char(8), char(2), char(0), char(0), char(0)};  // 8-bit RGB, no interlace
    put_chunk(png, "IHDR", ihdr);
    put_chunk(png, "IDAT", zlib_stored(raw));
    put_chunk(png, "IEND", "");
    write_bytes_safely(path, "image", png);
}

void check_image_header(const std::string& path) {
    const std::string head = read_input_file(path, "image").substr(0, 256);
    parse_pfm_header(path, head);
}

void check_image_header_bytes(const std::string& path, const std::string& head, std::uintmax_t) {
    parse_pfm_header(path, head.substr(0, 256));
}

ImageRGB read_image(const std::string& path) { return read_image_bytes(path, read_input_file(path, "image")); }

ImageRGB read_image_bytes(const std::string& path, const std::string& data) {
    const PfmHeader h = parse_pfm_header(path, data);
    const std::size_t values = std::size_t(h.width) * std::size_t(h.height) * std::size_t(h.channels);
    if (data.size() - h.bytes < values * sizeof(float))
        throw Error(fmt::format("{}: the PFM of {}x{} pixels is truncated", path, h.width, h.height));
    std::vector<float> v(values);
    std::memcpy(v.data(), data.data() + h.bytes, values * sizeof(float));
    if (!h.little)
        for (float& f : v) {
            std::uint32_t u;
            std::memcpy(&u, &f, 4);
            u = __builtin_bswap32(u);
            std::memcpy(&f, &u, 4);
        }
    ImageRGB img;
    img.width = h.width;
    img.height = h.height;
    img.rgb.resize(std::size_t(h.width) * std::size_t(h.height) * 3);
    for (int y = 0; y < h.height; ++y)  // PFM rows go from the bottom
        for (int x = 0; x < h.width; ++x)
            for (int c = 0; c < 3; ++c)
                img.rgb[(std::size_t(y) * h.width + x) * 3 + c] =
                    v[(std::size_t(h.height - 1 - y) * h.width + x) * h.channels + (h.channels == 3 ? c : 0)];
    return img;
}

bool can_write_float_image(const std::string& path, std::string* why) {
    if (lower_extension(path) == ".pfm") return true;
    if (why)
        *why = fmt::format(
            "this facet is built without OpenImageIO (FACET_OIIO=OFF) and writes linear images as "
            ".pfm only: give {}",
            replace_extension(path, ".pfm"));
    return false;
}

}  // namespace facet

#endif  // FACET_LEAN_IMAGES
