#include "film/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Writes through `write` into a temporary file beside `path`, then renames it.
template <typename F>
void write_atomically(const std::string& path, F&& write) {
    fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw Error(fmt::format("{}: cannot create folder {}: {}", path, target.parent_path().string(), ec.message()));
    }
    // Keep the extension last: OpenImageIO picks the format from it.
    fs::path tmp = target.parent_path() / (".tmp-" + target.filename().string());
    write(tmp.string());
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw Error(fmt::format("{}: cannot move the written image into place: {}", path, ec.message()));
    }
}

void write_pixels(const std::string& path, const ImageSpec& spec, TypeDesc type, const void* data,
                  const std::string& shown_path) {
    std::unique_ptr<ImageOutput> out = ImageOutput::create(path);
    if (!out) throw Error(fmt::format("{}: cannot write this image format: {}", shown_path, OIIO::geterror()));
    if (!out->open(path, spec) || !out->write_image(type, data) || !out->close())
        throw Error(fmt::format("{}: writing failed: {}", shown_path, out->geterror()));
}

float srgb_encode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

void check_size(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * height * 3)
        throw Error(fmt::format("{}: image of {}x{} with {} values is inconsistent", path, width, height, rgb.size()));
}

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb,
               const ImageMetadata& meta) {
    check_size(path, width, height, rgb);
    ImageSpec spec(width, height, 3, TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    spec.attribute("Software", "facet");
    for (const auto& [k, v] : meta.strings) spec.attribute(k, v);
    for (const auto& [k, v] : meta.floats) spec.attribute(k, v);
    for (const auto& [k, v] : meta.ints) spec.attribute(k, v);
    write_atomically(path, [&](const std::string& tmp) { write_pixels(tmp, spec, TypeDesc::FLOAT, rgb.data(), path); });
}

void write_png(const std::string& path, int width, int height, const std::vector<float>& rgb, float exposure) {
    check_size(path, width, height, rgb);
    float scale = std::exp2(exposure);
    std::vector<std::uint8_t> bytes(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        float v = rgb[i] * scale;
        v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
        bytes[i] = std::uint8_t(std::lround(srgb_encode(v) * 255.0f));
    }
    ImageSpec spec(width, height, 3, TypeDesc::UINT8);
    spec.attribute("Software", "facet");
    write_atomically(path, [&](const std::string& tmp) { write_pixels(tmp, spec, TypeDesc::UINT8, bytes.data(), path); });
}

ImageRGB read_image(const std::string& path) {
    if (!fs::exists(path)) throw Error(fmt::format("{}: no such file", path));
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw Error(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
    const ImageSpec& spec = in->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
        throw Error(fmt::format("{}: empty image ({}x{}, {} channels)", path, spec.width, spec.height, spec.nchannels));
    // Checked before allocating: a header can claim any size (16384 x 16384 is 2^28).
    if (std::int64_t(spec.width) * spec.height > kMaxImagePixels)
        throw Error(fmt::format("{}: the image claims {}x{} pixels: at most 2^28 pixels are supported", path,
                                spec.width, spec.height));
    const int channels = std::min(spec.nchannels, 3);   // R, G, B (or grey); alpha and the rest unused
    std::vector<float> all(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, TypeDesc::FLOAT, all.data()))
        throw Error(fmt::format("{}: cannot read pixels: {}", path, in->geterror()));
    ImageRGB img;
    img.width = spec.width;
    img.height = spec.height;
    img.spp = spec.get_int_attribute("facet:spp", -1);
    img.rgb.resize(std::size_t(spec.width) * spec.height * 3);
    for (std::size_t i = 0; i < std::size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * i + c] = all[i * std::size_t(channels) + std::size_t(std::min(c, channels - 1))];
    return img;
}

ImageRGB read_reference(const std::string& path, int width, int height) {
    ImageRGB ref = read_image(path);
    if (ref.width != width || ref.height != height)
        throw Error(fmt::format("reference {}: the reference is {}x{} but the render is {}x{}", path, ref.width,
                                ref.height, width, height));
    for (std::size_t i = 0; i < ref.rgb.size(); ++i)
        if (!std::isfinite(ref.rgb[i]))
            throw Error(fmt::format("reference {}: channel {} of pixel ({}, {}) is not finite", path, i % 3,
                                    (i / 3) % std::size_t(width), (i / 3) / std::size_t(width)));
    return ref;
}

std::string replace_extension(const std::string& path, const std::string& ext) {
    return fs::path(path).replace_extension(ext).string();
}

}  // namespace facet
